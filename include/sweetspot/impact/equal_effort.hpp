#pragma once
// Equal-effort swings (physics.md §7): a player swings a bat of larger moment of inertia more
// slowly. Field and lab measurements fit the swing speed as a power law of the bat's MOI about
// the knob, v ∝ I_knob^-n: n ≈ 0.3 for college hitters (A. M. Nathan's fit of the Crisco and
// Greenwald field data, in which the swing turns about a point near the knob and its rotational
// speed falls as the knob MOI grows; J. J. Crisco et al., Med. Sci. Sports Exerc. 34, 1675
// (2002); J. J. Crisco, R. M. Greenwald, A. M. Nathan, L. V. Smith et al., Sports Eng. 13, 153
// (2011)); R. Cross and R. Bower, J. Sports Sci. 24, 23 (2006) found n = 0.27 for swung rods and
// cite 0.25 for softball bats. So comparing bats at one swing speed favours the heavier one:
// equal effort compares them as one player would swing them.
#include "sweetspot/impact/scene.hpp"

namespace sweetspot {

inline constexpr double default_swing_exponent = 0.3;
// The exponent's range, in studies and optimisations alike: 0 swings every bat as the reference
// (equal speed); measured values are 0.25 to 0.3, and beyond 2 a bat of twice the MOI would be
// swung at under a quarter of the speed, no player's swing.
inline constexpr double max_swing_exponent = 2;
inline bool valid_swing_exponent(double n) { return n >= 0 && n <= max_swing_exponent; }

// The swing of a bat whose MOI about the knob is `moi`, by the player whose swing with a bat of
// MOI `reference_moi` is `reference`: the whole rigid velocity field (omega, and cm_speed when
// the swing is given by it) scaled by (reference_moi / moi)^exponent; the rotation centre stays.
// The reference bat itself gets the reference swing exactly.
Swing equal_effort_swing(const Swing& reference, double reference_moi, double moi, double exponent);

}  // namespace sweetspot
