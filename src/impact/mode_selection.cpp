#include "sweetspot/impact/mode_selection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

#include "contact/rigid_collision.hpp"
#include "sweetspot/impact/formulas.hpp"

namespace sweetspot {

namespace {

// Upper envelope of g for a half-sine pulse of duration T (|F^| = |cos(w T/2)| / |1 - (w T/pi)^2|):
// 1 up to w T = 2 pi, then 1 / ((w T / pi)^2 - 1)^2, here from x2 = (w T / pi)^2. Real pulses are
// smoother, so g is smaller.
double response_bound(double x2) { return x2 <= 4 ? 1.0 : 1 / ((x2 - 1) * (x2 - 1)); }

// What dropping a mode costs, and the static compliance psi^2 / omega^2 it leaves.
struct Take {
  double cost = 0, compliance = 0;
};

}  // namespace

double pulse_duration(const Ball& ball, double approach_speed, double recoil) {
  const double v = std::max(approach_speed, 1e-9);
  const double reduced_mass = ball.mass / (1 + recoil);
  const double q = ball.a + 1, b = ball.expansion_exponent();
  const double u_max = std::pow(q * reduced_mass * v * v / (2 * ball.k1), 1 / q);
  return u_max / v * (detail::whole_branch_time(q) + detail::whole_branch_time(b + 1) / ball.e0);
}

double selection_error_scale(const Ball& ball, double ball_speed, double bat_speed, double recoil) {
  const double vf = rigid_exit_speed(ball.e0, recoil, ball_speed, bat_speed);
  return std::max(std::abs(vf), 0.05 * std::abs(ball_speed + bat_speed));
}

ModeSelection select_modes(const Eigen::VectorXd& omega, const Eigen::VectorXd& psi, const Ball& ball,
                           double ball_speed, double bat_speed, double recoil, double tolerance,
                           const UnsolvedModes& unsolved) {
  ModeSelection s;
  const double approach = ball_speed + bat_speed;
  s.pulse_duration = pulse_duration(ball, approach, recoil);
  const double scale = selection_error_scale(ball, ball_speed, bat_speed, recoil);
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
  const double pulse_omega2 = pulse_omega * pulse_omega;
  const double duration2 = s.pulse_duration * s.pulse_duration / (std::numbers::pi * std::numbers::pi);
  // Drop the modes that cost least while their sum stays within the tolerance. Those costing
  // under tolerance / n are among the least and sum to under the tolerance: they go at once,
  // and only the few others are ordered. A dropped mode's cost adds to the estimate, its
  // compliance stays. (The sums are plain locals, and the first loop calls nothing: otherwise
  // they would go through memory at every mode.)
  double dropped_cost = 0, dropped_compliance = 0;
  if (unsolved.compliance > 0) {  // a complete basis adds nothing: the sums start at 0 as before
    const double w2 = unsolved.omega * unsolved.omega, x2 = w2 * duration2;
    const double per_compliance = recoil_sensitivity * ball.mass * w2 * response_bound(x2) +
                                  compliance_sensitivity * std::min(1.0, pulse_omega2 / w2);
    dropped_cost = x2 > 4 ? unsolved.compliance * per_compliance : std::numeric_limits<double>::infinity();
    dropped_compliance = unsolved.compliance;
  }
  // Scratch of this thread's: a study selects at every impact (no allocation once it has the size).
  thread_local std::vector<Take> take;
  thread_local std::vector<int> candidates;
  take.assign(n, Take{});
  candidates.clear();
  for (int i = 2; i < n; ++i) {
    const double w2 = omega(i) * omega(i), inverse_w2 = 1 / w2, psi2 = psi(i) * psi(i);
    const double lag = std::min(1.0, pulse_omega2 * inverse_w2);
    take[i].compliance = psi2 * inverse_w2;
    take[i].cost = recoil_sensitivity * ball.mass * psi2 * response_bound(w2 * duration2) +
                   compliance_sensitivity * take[i].compliance * lag;
    if (take[i].cost * n <= tolerance) {
      dropped_cost += take[i].cost;
      dropped_compliance += take[i].compliance;
    }
  }
  for (int i = 2; i < n; ++i)
    if (take[i].cost * n > tolerance) candidates.push_back(i);
  std::ranges::sort(candidates, [](int i, int j) { return take[i].cost < take[j].cost; });
  s.kept.reserve(candidates.size());
  for (const int i : candidates) {
    if (dropped_cost + take[i].cost <= tolerance) {
      dropped_cost += take[i].cost;
      dropped_compliance += take[i].compliance;
    } else {
      s.kept.push_back(i);
    }
  }
  s.error_estimate = dropped_cost;
  s.residual_compliance = dropped_compliance;
  std::ranges::sort(s.kept);
  return s;
}

}  // namespace sweetspot
