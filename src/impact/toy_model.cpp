#include "sweetspot/impact/toy_model.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "sweetspot/impact/formulas.hpp"

namespace sweetspot {

ImpactResult toy_model(double omega_tau) {
  constexpr double ball_mass = 1, spring = 1, struck = 2, other = 4;
  constexpr double steps_per_tau = 4000;
  const double tau = std::numbers::pi * std::sqrt(ball_mass / spring);
  const double total = struck + other;
  // Mass-orthonormal modes of the two-mass bat seen at the struck mass: the common translation,
  // and the vibration in which the masses move oppositely with the CM at rest.
  ModalContact bat;
  bat.omega = Eigen::Vector2d(0, omega_tau / tau);
  bat.psi = Eigen::Vector2d(1 / std::sqrt(total), other / std::sqrt(struck * other * total));
  bat.velocity0 = Eigen::Vector2d::Zero();

  const Ball ball{ball_mass, 1.0, spring, 1.0, 1.0};  // linear (a = 1) and lossless (e0 = 1)
  CollisionOptions options;
  options.method = Method::rk4;  // its step is fixed in tau (below)
  options.dt = tau / steps_per_tau;
  options.window = 4 * tau;
  options.max_contact_time = 100 * tau;
  options.record_force = true;  // Van Zandt's prescription needs the force profile
  const double speed = 1;
  const Collision c = collide(bat, ball, speed, options);

  ImpactResult r = collision_result(c);
  r.force.clear();  // recorded for Van Zandt only: a study point should not carry it around
  // The step is fixed in tau, so omega tau above 2.8 * 4000 is refused, with no state to read.
  if (c.status == CollisionStatus::refused_step) {
    r.message = "omega tau above " + std::to_string(static_cast<int>(rk4_stability_limit * steps_per_tau)) +
                " is beyond the toy model's fixed step, tau / " + std::to_string(static_cast<int>(steps_per_tau));
    return r;
  }
  r.energy.initial = 0.5 * ball_mass * speed * speed;
  r.energy.ball = 0.5 * ball_mass * r.vf * r.vf;
  r.energy.bat_translation = c.mode_energy(bat, 0);
  r.energy.vibration = c.mode_energy(bat, 1);
  close_balance(r);
  if (c.status != CollisionStatus::ok) return r;  // no whole force profile to drive the modes with
  const double recoil = ball_mass / total;         // the rigid bat: all of it moves as one
  r.vf_van_zandt = van_zandt_exit_speed(bat, ball, recoil, speed, 0.0, c.force);
  require_finite(r, {true, false, true});
  return r;
}

}  // namespace sweetspot
