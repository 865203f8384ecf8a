#pragma once
// Which vibrational modes an impact needs (modes = "auto"). A mode takes from the ball about
// R_n = m psi_n(z)^2 g(omega_n tau) of the recoil (physics.md §5): modes much faster than the
// pulse (g -> 0) or with a node at the impact point (psi_n = 0) add nothing. The pulse is
// estimated from the rigid bat's collision, which is shorter than the flexible one, so the
// estimate of what the dropped modes take is an upper bound; they are kept as a static
// (residual) compliance sum psi_n^2 / omega_n^2, which removes most of even that.
#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <vector>

#include "sweetspot/contact/ball.hpp"

namespace sweetspot {

struct ModeSelection {
  std::vector<int> kept;           // indices of the kept vibrational modes (2, 3, ...), ascending
  double residual_compliance = 0;  // sum psi_n^2 / omega_n^2 over the dropped ones
  double error_estimate = 0;       // bound on the exit-speed error of dropping them, over selection_error_scale
  double pulse_duration = 0;       // s, the rigid-bat estimate used
};

// Duration of the force pulse of the ball on a rigid bat of recoil factor R0 = m / M_eff at
// approach speed v: compression and expansion of the power-law spring in closed form.
double pulse_duration(const Ball& ball, double approach_speed, double recoil);

// What a partial basis (ModalBasis::complete() false) leaves unsolved at the impact point: the
// unsolved modes' total static compliance sum psi^2 / omega^2 (exact from the flexibility,
// ModalBasis::unsolved_compliance_at) and a frequency none of them lies below (solved_below).
struct UnsolvedModes {
  double compliance = 0;
  double omega = std::numeric_limits<double>::infinity();
};

// omega and psi over the solved modes (0 and 1 rigid; all of them unless `unsolved` says what
// is missing); keeps the fewest modes whose dropped part stays within `tolerance` of the exit
// speed. The unsolved modes are dropped first, at a cost bounded from their compliance alone:
// both terms of a mode's cost are its psi^2 / omega^2 times a factor that falls with omega
// (omega^2 g(omega) and the lag), so their sum is at most that factor at `unsolved.omega` times
// their compliance (infinite, i.e. every solved mode kept and the error unknown, when the pulse
// could still ring them: unsolved.omega below 2 pi / T).
// m/s: what the tolerance and the estimate are relative to, the rigid bat's max(|v_f|, 5 % of the
// approach speed), the only scale known before the impact; the impact restates the estimate
// against its own (impact.cpp).
double selection_error_scale(const Ball& ball, double ball_speed, double bat_speed, double recoil);

ModeSelection select_modes(const Eigen::VectorXd& omega, const Eigen::VectorXd& psi, const Ball& ball,
                           double ball_speed, double bat_speed, double recoil, double tolerance,
                           const UnsolvedModes& unsolved = {});

// Modes faster than this multiple of the pulse's reach 4 pi / T are what a study solves for
// `auto` (scene.hpp, auto_mode_request). The unsolved tail's bound falls about as the cube of the
// multiple (the tail's compliance as 1 / omega and its cost per unit compliance as 1 / omega^2; measured
// 3.1), so the multiple grows as the tolerance's cube root: 24 at 1e-5. Measured (README,
// "Numerics"; R161, torpedo and aluminium at N = 84/85 and 168/170, 30.5-80.5 cm, 1-50 m/s, e0 0.5-1,
// a 1.5-2.2, tolerances 1e-3 to 1e-7): modes_error stays within the tolerance everywhere, and
// two thirds of this multiple is not enough. (A fixed 48 asked twice as far as needed at 1e-5 and
// not far enough at 1e-7, where the tail alone took up to 2.4 x the tolerance.)
inline double auto_solve_factor(double tolerance) { return 24 * std::cbrt(1e-5 / tolerance); }

}  // namespace sweetspot
