#pragma once
// N2000's scenes (physics.md §6) as the tests and benchmarks build them, with N2000's settings
// (RK4 at 5 us; 18 vibrational modes unless a test asks for others), which the tests built on
// them were written for: a test that means another integrator sets it.
#include "sweetspot/impact/n2000_settings.hpp"
#include "sweetspot/impact/scene.hpp"

// Figs. 10-15: ball 40 m/s, e0 0.5, the bat rotating at 51 rad/s about a point 9 cm from the knob.
inline sweetspot::ImpactScene n2000_high_impact(double z, int modes = sweetspot::n2000_modes) {
  sweetspot::ImpactScene s = sweetspot::with_n2000_settings(sweetspot::ImpactScene{});
  s.z = z;
  s.ball_speed = 40;
  s.ball.e0 = 0.5;
  s.swing = {51, true, 0, 0.09};
  s.vibrational_modes = modes;
  return s;
}

// Figs. 7-9: ball 1 m/s on the bat at rest, e0 0.66.
inline sweetspot::ImpactScene n2000_low_impact(double z, int modes = sweetspot::n2000_modes) {
  sweetspot::ImpactScene s = sweetspot::with_n2000_settings(sweetspot::ImpactScene{});
  s.z = z;
  s.ball_speed = 1;
  s.ball.e0 = 0.66;
  s.swing = {0, false, 0, 0};
  s.vibrational_modes = modes;
  return s;
}
