#pragma once
// The measures of bat performance the rules test (physics.md §7, README "Certification"), as
// closed forms of a collision's speeds. Physics only: the rig that makes the collision is
// bat_test_rig.hpp, the standards that bound them standards.hpp.
#include <limits>

namespace sweetspot {

// Collision efficiency e_A = (v_f - v_bat) / (v_ball + v_bat): the ball's rebound speed over its
// inbound speed in the frame where the struck point is at rest (Nathan, Am. J. Phys. 71, 134
// (2003)). With the bat at rest it is v_f / v_ball; with a swinging bat it is the same number,
// since a rigid motion of the bat is a free motion of its modes and adds linearly.
double collision_efficiency(double vf, double ball_speed, double bat_speed);

// The rig's recoil factor r = m d^2 / I: ball mass m, impact distance d from the pivot, MOI I
// about the pivot. The held bat's rigid response at the impact point is that of a mass I / d^2.
double pivot_recoil(double ball_mass, double distance, double moi_pivot);

// BBCOR = e_A (1 + r) + r: the ball-bat COR, relative speed after over before, the bat's speed
// after found from angular momentum about the pivot, V = r (v_in + v_out) (physics.md §7).
double bbcor_from(double e_a, double recoil);

struct RigMeasures {
  static constexpr double none = std::numeric_limits<double>::quiet_NaN();
  double e_a = none;    // collision efficiency
  double bbcor = none;  // ball-bat COR, e_a (1 + r) + r
  double besr = none;   // ball exit speed ratio, e_a + 1/2
  double bpf = none;    // bat performance factor, bbcor / e0
};

// All four from e_A, the rig's recoil factor and the ball's own COR e0.
RigMeasures rig_measures(double e_a, double recoil, double e0);

}  // namespace sweetspot
