#include "sweetspot/bat/parameter_bounds.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "toml_values.hpp"

namespace sweetspot {

namespace {

// Lengths along the bat: a millimetre (below, a bat is not a beam the slices can describe) to
// 2 m (beyond any bat, and the slices' count stays under max_slices at about 1 cm each).
constexpr std::string_view along_why =
    "a bat's lengths lie from 1 mm to 2 m: the slices that model it need a length to cut";
// Diameters: the slices' stiffness goes as d^4 and their mass as d^2, which must not underflow
// against each other in the mode solve.
constexpr std::string_view diameter_why =
    "a bat's diameters lie from 1 mm to 1 m: far outside, its slices' stiffness (d^4) and mass (d^2) lose the "
    "mode solve's digits";
constexpr std::string_view wall_why =
    "a hollow bat's wall is at least 0.1 mm thick (real walls are 1.5 to 4 mm): a thinner one leaves the "
    "slices' stiffness to round-off";
constexpr std::string_view density_why = "from the lightest foams (10 kg/m^3) to beyond osmium (22 600 kg/m^3)";
constexpr std::string_view modulus_why =
    "from soft rubber (about 1e6 Pa) to diamond (about 1e12 Pa): outside, the mode solve's stiffness loses its digits";
constexpr std::string_view shear_coefficient_why =
    "Timoshenko's kappa is about 0.5 for a thin tube and 0.85 to 0.9 for a solid rod, never above 1; for no "
    "shear flexibility at all use theory \"euler-bernoulli\"";

constexpr std::array<ParameterBound, 16> bounds = {{
    {"length", 1e-3, 2, "m", along_why},
    {"knob_length", 1e-3, 2, "m", along_why},
    {"taper_start", 1e-3, 2, "m", along_why},
    {"taper_end", 1e-3, 2, "m", along_why},
    {"end_depth", 1e-3, 2, "m", along_why},
    {"knob_diameter", 1e-3, 1, "m", diameter_why},
    {"handle_diameter", 1e-3, 1, "m", diameter_why},
    {"barrel_diameter", 1e-3, 1, "m", diameter_why},
    {profile_outer_diameter, 1e-3, 1, "m", diameter_why},
    {"wall_thickness", 1e-4, 0.5, "m", wall_why},
    {profile_wall, 1e-4, 0.5, "m", wall_why},
    {"density", 10, 25000, "kg/m^3", density_why},
    {"youngs_modulus", 1e6, 1e12, "Pa", modulus_why},
    {"shear_modulus", 1e6, 1e12, "Pa", modulus_why},
    {"hoop_modulus", 1e6, 1e12, "Pa", modulus_why},
    {"shear_coefficient", 0.1, 1, "", shear_coefficient_why},
}};

std::string with_unit(double value, std::string_view unit) {
  std::string text = detail::format_number(value);
  if (!unit.empty()) text.append(" ").append(unit);
  return text;
}

}  // namespace

const ParameterBound* parameter_bound(std::string_view name) {
  const auto it = std::ranges::find(bounds, name, &ParameterBound::name);
  return it == bounds.end() ? nullptr : &*it;
}

std::string expected_range(const ParameterBound& bound) {
  return detail::format_number(bound.low) + " to " + with_unit(bound.high, bound.unit) + " (" +
         std::string(bound.why) + ")";
}

// A rounding's worth beyond either end is within: a wall of 0.06 - 0.0598 m is 0.1 mm, and a
// value written in inches at the bound converts with round-off.
bool within(const ParameterBound& bound, double value) {
  constexpr double rounding = 1e-9;
  return value >= bound.low * (1 - rounding) && value <= bound.high * (1 + rounding);
}

std::optional<std::string> bound_break(std::string_view name, double value) {
  const ParameterBound* bound = parameter_bound(name);
  if (!bound || within(*bound, value)) return std::nullopt;
  return std::string(name) + " " + with_unit(value, bound->unit) + ": expected " + expected_range(*bound);
}

}  // namespace sweetspot
