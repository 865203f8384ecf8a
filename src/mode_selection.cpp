#include "sweetspot/mode_selection.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "sweetspot/formulas.hpp"

namespace sweetspot {

namespace {

// int_0^1 dx / sqrt(1 - x^q) = B(1/q, 1/2) / q: the time to stop a mass on a spring F ~ u^(q-1),
// in units of u_max / v.
double quarter_period(double q) {
  return std::tgamma(1 / q) * std::sqrt(std::numbers::pi) / std::tgamma(1 / q + 0.5) / q;
}

// Upper envelope of g for a half-sine pulse of duration T (|F^| = |cos(w T/2)| / |1 - (w T/pi)^2|):
// 1 up to w T = 2 pi, then 1 / ((w T / pi)^2 - 1)^2. Real pulses are smoother, so g is smaller.
double response_bound(double omega, double duration) {
  const double x = omega * duration / std::numbers::pi;
  return x <= 2 ? 1.0 : 1 / ((x * x - 1) * (x * x - 1));
}

}  // namespace

double pulse_duration(const Ball& ball, double approach_speed, double recoil) {
  const double v = std::max(approach_speed, 1e-9);
  const double reduced_mass = ball.mass / (1 + recoil);
  const double q = ball.a + 1, b = ball.expansion_exponent();
  const double u_max = std::pow(q * reduced_mass * v * v / (2 * ball.k1), 1 / q);
  return u_max / v * (quarter_period(q) + quarter_period(b + 1) / ball.e0);
}

ModeSelection select_modes(const Eigen::VectorXd& omega, const Eigen::VectorXd& psi, const Ball& ball,
                           double ball_speed, double bat_speed, double recoil, double tolerance) {
  ModeSelection s;
  const double approach = ball_speed + bat_speed;
  s.pulse_duration = pulse_duration(ball, approach, recoil);
  const double vf = rigid_exit_speed(ball.e0, recoil, ball_speed, bat_speed);
  const double scale = std::max(std::abs(vf), 0.05 * std::abs(approach));
  // A dropped mode errs twice. Dynamically, it would take R_n of the recoil: d v_f / d(sum R)
  // of the rigid formula. Statically, its compliance is kept, but a mode only follows the force
  // quasi-statically to within (omega_pulse / omega_n)^2 of it; the compliance c in series with
  // the lossy ball stores c F_m^2 / 2 losslessly, a share delta = c F_m (a+1) / (2 u_m) of what
  // the ball stores, which raises e_eff by (1 - e0^2) / (2 e0) per unit delta.
  const double recoil_sensitivity = (1 + ball.e0) * std::abs(approach) / ((1 + recoil) * (1 + recoil)) / scale;
  const double reduced_mass = ball.mass / (1 + recoil), q = ball.a + 1;
  const double u_max = std::pow(q * reduced_mass * approach * approach / (2 * ball.k1), 1 / q);
  const double compliance_sensitivity = std::abs(approach) / ((1 + recoil) * scale) * (1 - ball.e0 * ball.e0) /
                                        (2 * ball.e0) * ball.k1 * std::pow(u_max, ball.a - 1) * q / 2;
  // The pulse is no pure half-sine: on a flexible bat it ripples at the kept modes' frequencies.
  // Its content reaches about twice the half-sine's 2 pi / T (checked against all-mode runs of
  // the high-impact scene, tests/test_mode_selection.cpp).
  const double pulse_omega = 4 * std::numbers::pi / s.pulse_duration;

  const int n = static_cast<int>(omega.size());
  std::vector<std::pair<double, int>> takes;  // what dropping each mode costs, and the mode
  takes.reserve(n);
  for (int i = 2; i < n; ++i) {
    const double ratio = pulse_omega / omega(i), psi2 = psi(i) * psi(i), lag = std::min(1.0, ratio * ratio);
    takes.emplace_back(recoil_sensitivity * ball.mass * psi2 * response_bound(omega(i), s.pulse_duration) +
                           compliance_sensitivity * psi2 / (omega(i) * omega(i)) * lag,
                       i);
  }
  // Drop the modes that take least while their sum stays within the tolerance: equivalently,
  // keep the ones that take most until what is left fits. Few are kept, so a heap finds them.
  double left = 0;
  for (const auto& t : takes) left += t.first;
  std::ranges::make_heap(takes);
  while (!takes.empty() && left > tolerance) {
    std::ranges::pop_heap(takes);
    left -= takes.back().first;
    s.kept.push_back(takes.back().second);
    takes.pop_back();
  }
  for (const auto& [take, i] : takes) {
    s.error_estimate += take;
    s.residual_compliance += psi(i) * psi(i) / (omega(i) * omega(i));
  }
  std::ranges::sort(s.kept);
  return s;
}

}  // namespace sweetspot
