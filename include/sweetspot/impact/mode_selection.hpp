#pragma once
// Which vibrational modes an impact needs (modes = "auto"). A mode takes from the ball about
// R_n = m psi_n(z)^2 g(omega_n tau) of the recoil (physics.md §5): modes much faster than the
// pulse (g -> 0) or with a node at the impact point (psi_n = 0) add nothing. The pulse is
// estimated from the rigid bat's collision, which is shorter than the flexible one, so the
// estimate of what the dropped modes take is an upper bound; they are kept as a static
// (residual) compliance sum psi_n^2 / omega_n^2, which removes most of even that.
#include <Eigen/Dense>
#include <vector>

#include "sweetspot/contact/ball.hpp"

namespace sweetspot {

struct ModeSelection {
  std::vector<int> kept;           // indices of the kept vibrational modes (2, 3, ...), ascending
  double residual_compliance = 0;  // sum psi_n^2 / omega_n^2 over the dropped ones
  double error_estimate = 0;       // bound on the relative exit-speed error of dropping them
  double pulse_duration = 0;       // s, the rigid-bat estimate used
};

// Duration of the force pulse of the ball on a rigid bat of recoil factor R0 = m / M_eff at
// approach speed v: compression and expansion of the power-law spring in closed form.
double pulse_duration(const Ball& ball, double approach_speed, double recoil);

// omega and psi over all modes (0 and 1 rigid); keeps the fewest modes whose dropped part stays
// within `tolerance` of the exit speed.
ModeSelection select_modes(const Eigen::VectorXd& omega, const Eigen::VectorXd& psi, const Ball& ball,
                           double ball_speed, double bat_speed, double recoil, double tolerance);

}  // namespace sweetspot
