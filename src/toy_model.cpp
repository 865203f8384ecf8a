#include "sweetspot/toy_model.hpp"

#include <cmath>
#include <numbers>

#include "sweetspot/formulas.hpp"

namespace sweetspot {

ToyResult toy_model(double omega_tau) {
  constexpr double ball_mass = 1, spring = 1, struck = 2, other = 4;
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
  options.dt = tau / 4000;
  options.window = 4 * tau;
  options.max_contact_time = 100 * tau;
  options.record_force = true;
  const double speed = 1;
  const Collision c = collide(bat, ball, speed, options);

  ToyResult r;
  r.status = c.status;
  r.omega_tau = omega_tau;
  const double initial = 0.5 * ball_mass * speed * speed;
  r.exit_ratio = c.ball_velocity / speed;
  r.ball_energy = 0.5 * ball_mass * c.ball_velocity * c.ball_velocity / initial;
  r.bat_cm_energy = c.mode_energy(bat, 0) / initial;
  r.vibration_energy = c.mode_energy(bat, 1) / initial;
  const double recoil = ball_mass / total;  // the rigid bat: all of it moves as one
  r.van_zandt_ratio = van_zandt_exit_speed(bat, ball, recoil, speed, 0.0, c.force) / speed;
  return r;
}

}  // namespace sweetspot
