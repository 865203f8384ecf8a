#include "sweetspot/impact/batted_ball.hpp"

#include <cmath>

#include "sweetspot/impact/impact.hpp"

namespace sweetspot {

double collision_efficiency(const ModalBasis& basis, const ImpactScene& scene, double speed) {
  ImpactScene rest;  // the same ball, point, constraint, modes and integration; nothing else asked
  rest.z = scene.z;
  rest.ball = scene.ball;
  rest.ball_speed = speed;
  rest.swing = scene.swing;
  rest.swing.omega = rest.swing.cm_speed = 0;
  rest.pivoted = scene.pivoted;
  rest.vibrational_modes = scene.vibrational_modes;
  rest.mode_tolerance = scene.mode_tolerance;
  rest.step_accuracy = scene.step_accuracy;
  rest.integrator = scene.integrator;
  rest.integrator.record_force = rest.integrator.find_collision_time = false;
  const ImpactResult r = simulate_impact(basis, rest);
  return r.status == CollisionStatus::ok ? r.vf / speed : std::nan("");
}

double linear_batted_ball_speed(double e_a, double pitch_speed, double bat_speed) {
  return e_a * pitch_speed + (1 + e_a) * bat_speed;
}

}  // namespace sweetspot
