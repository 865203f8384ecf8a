#pragma once
// The inch-pound units the bat rules are written in, and the rules' "drop".
namespace sweetspot {

inline constexpr double metres_per_inch = 0.0254;
inline constexpr double kilograms_per_ounce = 0.028349523125;
inline constexpr double metres_per_second_per_mph = 0.44704;
inline constexpr double newtons_per_pound_force = 4.4482216152605;  // lbf: 0.45359237 kg x 9.80665 m/s^2

// The pivot of the swing-weight (MOI) measurement and of the bat-test rig, 6 in from the knob
// (ASTM F2398; NCAA).
inline constexpr double swing_weight_pivot = 0.1524;  // m, 6 in, written as users write it

// Drop: length in inches minus weight in ounces (a 33-in, 30-oz bat has drop 3; the rules'
// "-3" is the weight less the length, so "at least -3" is a drop of at most 3 here).
inline double bat_drop(double length_m, double mass_kg) {
  return length_m / metres_per_inch - mass_kg / kilograms_per_ounce;
}

}  // namespace sweetspot
