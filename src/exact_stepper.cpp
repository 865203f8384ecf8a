#include "exact_stepper.hpp"

#include <algorithm>
#include <array>
#include <unordered_map>
#include <cmath>

namespace sweetspot::detail {

namespace {

constexpr double event_grid = 4096;  // event steps end on this many divisions of the step

// P_k = int_0^h sin(w (h - t)) / w t^k dt and Q_k = int_0^h cos(w (h - t)) t^k dt, k = 0..3:
// the response of a mode to the forcing t^k. For w h >= 1, integration by parts from P_0 =
// (1 - cos)/w^2, Q_0 = sin/w: Q_k = k P_{k-1}, P_k = (h^k - k Q_{k-1}) / w^2. Below that the
// recursion cancels, and the power series (exact at w = 0) takes over:
//   P_k = h^(k+2) k! sum_j (-x^2)^j / (k+2j+2)!,  Q_k = h^(k+1) k! sum_j (-x^2)^j / (k+2j+1)!.
void monomial_responses(double w, double h, double cos_x, double sin_x, double p[4], double q[4]) {
  const double x = w * h;
  const double h_power[5] = {1, h, h * h, h * h * h, h * h * h * h};
  if (x >= 1) {
    const double w2 = w * w;
    p[0] = (1 - cos_x) / w2;
    q[0] = sin_x / w;
    for (int k = 1; k < 4; ++k) {
      q[k] = k * p[k - 1];
      p[k] = (h_power[k] - k * q[k - 1]) / w2;
    }
    return;
  }
  const double x2 = x * x;
  double factorial = 1;  // k!
  for (int k = 0; k < 4; ++k) {
    if (k > 0) factorial *= k;
    double denom_q = 1;
    for (int j = 2; j <= k + 1; ++j) denom_q *= j;  // (k + 1)!
    double denom_p = denom_q * (k + 2);             // (k + 2)!
    double sp = 0, sq = 0, term = 1;
    for (int j = 0; j < 12 && std::abs(term) > 1e-18 * denom_q; ++j) {
      sq += term / denom_q;
      sp += term / denom_p;
      term *= -x2;
      denom_q *= (k + 2 * j + 2) * (k + 2 * j + 3);
      denom_p *= (k + 2 * j + 3) * (k + 2 * j + 4);
    }
    q[k] = h_power[k + 1] * factorial * sq;
    p[k] = h_power[k + 1] * h * factorial * sp;
  }
}

// Cubic Hermite basis on [0, h] as polynomials in t: rows A (F0), B (h F0' folded: weight of F0'),
// C (F1), D (F1'); columns t^0..t^3.
void hermite_weights(double h, double b[4][4]) {
  const double h2 = h * h, h3 = h2 * h;
  const double rows[4][4] = {{1, 0, -3 / h2, 2 / h3}, {0, 1, -2 / h, 1 / h2}, {0, 0, 3 / h2, -2 / h3}, {0, 0, -1 / h, 1 / h2}};
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k) b[r][k] = rows[r][k];
}

}  // namespace

namespace {

// One mode's closed-form response over a step: c, sn, w2sn, then dA..dD and qA..qD.
using ModeCoefficients = std::array<double, 11>;

ModeCoefficients mode_coefficients(double w, double h) {
  double b[4][4];
  hermite_weights(h, b);
  const auto combine = [&b](const double m[4], int row) {
    return b[row][0] * m[0] + b[row][1] * m[1] + b[row][2] * m[2] + b[row][3] * m[3];
  };
  const double cos_x = std::cos(w * h), sin_x = std::sin(w * h);
  double p[4], q[4];
  monomial_responses(w, h, cos_x, sin_x, p, q);
  return {cos_x,         w == 0 ? h : sin_x / w, w * sin_x,     combine(p, 0), combine(p, 1), combine(p, 2),
          combine(p, 3), combine(q, 0),          combine(q, 1), combine(q, 2), combine(q, 3)};
}

// Steps of the lengths a run reuses (nominal, graded) meet the same frequencies again and again
// even when the kept modes differ from impact to impact (modes = auto), so each thread remembers
// every mode's coefficients by (omega, h).
const ModeCoefficients& memoized_coefficients(double w, double h) {
  struct Key {
    double w, h;
    bool operator==(const Key&) const = default;
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      return std::hash<double>()(k.w) * 31 + std::hash<double>()(k.h);
    }
  };
  thread_local std::unordered_map<Key, ModeCoefficients, Hash> memo;
  if (memo.size() > 100000) memo.clear();  // bounded: a long run over many bases
  const auto [it, inserted] = memo.try_emplace(Key{w, h});
  if (inserted) it->second = mode_coefficients(w, h);
  return it->second;
}

}  // namespace

ModeResponse::ModeResponse(const Eigen::ArrayXd& w, double step, double ball_mass, bool memoize)
    : h(step), omega(w) {
  const int n = static_cast<int>(omega.size());
  Eigen::ArrayXd* columns[11] = {&c, &sn, &w2sn, &dA, &dB, &dC, &dD, &qA, &qB, &qC, &qD};
  for (Eigen::ArrayXd* a : columns) a->resize(n);
  for (int i = 0; i < n; ++i) {
    const ModeCoefficients computed = memoize ? ModeCoefficients{} : mode_coefficients(omega(i), h);
    const ModeCoefficients& m = memoize ? memoized_coefficients(omega(i), h) : computed;
    for (int j = 0; j < 11; ++j) (*columns[j])(i) = m[j];
  }
  double b[4][4], p[4], q[4];
  hermite_weights(h, b);
  monomial_responses(0, h, 1, 0, p, q);
  for (int r = 0; r < 4; ++r) {
    ball_d[r] = (b[r][0] * p[0] + b[r][1] * p[1] + b[r][2] * p[2] + b[r][3] * p[3]) / ball_mass;
    ball_q[r] = (b[r][0] * q[0] + b[r][1] * q[1] + b[r][2] * q[2] + b[r][3] * q[3]) / ball_mass;
  }
}

StepCoefficients::StepCoefficients(std::shared_ptr<const ModeResponse> r, const Eigen::ArrayXd& psi,
                                   double compliance)
    : response(std::move(r)), driven(psi.size(), 8), psi2_sum(psi.square().sum()) {
  const ModeResponse& m = *response;
  const Eigen::ArrayXd* columns[8] = {&m.dA, &m.dB, &m.qA, &m.qB, &m.dC, &m.dD, &m.qC, &m.qD};
  for (int j = 0; j < 8; ++j) driven.col(j) = psi * *columns[j];
  mode_dC = (psi * driven.col(dC)).sum(), mode_dD = (psi * driven.col(dD)).sum();
  mode_qC = (psi * driven.col(qC)).sum(), mode_qD = (psi * driven.col(qD)).sum();
  gC = mode_dC + m.ball_d[2] + compliance;
  gD = mode_dD + m.ball_d[3];
  hC = mode_qC + m.ball_q[2];
  hD = mode_qD + m.ball_q[3] + compliance;
}

namespace {

// The responses at the nominal step and at the graded first steps are the same for every impact
// that keeps the same modes (only the mode shapes at the contact differ), so each thread keeps
// them, keyed by step, ball mass and frequencies. With modes = auto the kept set varies from
// impact to impact, and event steps vary too; the cache starts over when it grows large.
std::shared_ptr<const ModeResponse> cached_response(const Eigen::ArrayXd& omega, std::size_t omega_key, double h,
                                                    double ball_mass) {
  const std::size_t key = omega_key ^ std::hash<double>()(h) ^ (std::hash<double>()(ball_mass) << 1);
  thread_local std::unordered_multimap<std::size_t, std::pair<double, std::shared_ptr<const ModeResponse>>> cache;
  const auto [first, last] = cache.equal_range(key);
  for (auto it = first; it != last; ++it) {
    const auto& [mass, response] = it->second;
    if (response->h == h && mass == ball_mass && response->omega.size() == omega.size() &&
        (response->omega == omega).all())
      return response;
  }
  thread_local std::size_t stored = 0;  // doubles held: at most about 32 MB per thread
  if (stored > 4'000'000) cache.clear(), stored = 0;
  stored += 11 * omega.size();
  auto response = std::make_shared<const ModeResponse>(omega, h, ball_mass, true);
  cache.emplace(key, std::make_pair(ball_mass, response));
  return response;
}

}  // namespace

std::size_t ExactStepper::frequencies_key(const Eigen::ArrayXd& omega) {
  std::size_t key = omega.size();
  for (double w : omega) key = key * 1099511628211ull ^ std::hash<double>()(w);
  return key;
}

std::shared_ptr<const ModeResponse> ExactStepper::response(double h) const {
  return cached_response(state_.body().omega.array(), omega_key_, h, state_.ball_mass());
}

ExactStepper::ExactStepper(const ContactState& state, const CollisionOptions& options)
    : state_(state), psi_(state.body().psi.array()), psi_w2_(psi_ * state.omega2()),
      omega_key_(frequencies_key(state.body().omega.array())), nominal_(response(options.dt), psi_, state.compliance()) {}

void ExactStepper::step(const Eigen::VectorXd& y, double h, const ContactForce& law, Eigen::VectorXd& out) {
  if (h == nominal_.h()) return advance(nominal_, y, law, out);
  // Halvings of the nominal step (the graded start, the stiff expansion) recur: keep them.
  const bool graded = h < nominal_.h() && std::exp2(std::round(std::log2(nominal_.h() / h))) * h == nominal_.h();
  if (graded) {
    for (const StepCoefficients& k : graded_)
      if (k.h() == h) return advance(k, y, law, out);
    graded_.emplace_back(response(h), psi_, state_.compliance());
    return advance(graded_.back(), y, law, out);
  }
  if (h != other_.h())
    other_ = StepCoefficients(std::make_shared<ModeResponse>(state_.body().omega.array(), h, state_.ball_mass()),
                              psi_, state_.compliance());
  advance(other_, y, law, out);
}

double ExactStepper::locate(const Eigen::VectorXd& y, double h, const ContactForce& law, ContactEvent event,
                            Eigen::VectorXd& out) {
  const double f0 = event_value(state_, event, y), d0 = event_rate(state_, event, y, law) * h;
  const double f1 = event_value(state_, event, out), d1 = event_rate(state_, event, out, law) * h;
  const auto cubic = [&](double s) {
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * f0 + (s3 - 2 * s2 + s) * d0 + (-2 * s3 + 3 * s2) * f1 + (s3 - s2) * d1;
  };
  double lo = 0, hi = 1;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double mid = (lo + hi) / 2;
    (cubic(mid) > 0 ? lo : hi) = mid;
  }
  if (hi == 1) return h;  // `out` already is the state at the end of the step
  // The event step ends on a 1/4096 grid of the step just past the root, so its response recurs
  // from impact to impact and is kept. Where it lands (within h/4096, ~2 ns at 10 us) changes
  // nothing that matters: the force is stationary there (F' = 0 at maximum compression, F = 0
  // at separation) and the loop's energy is exact anyway. Separation keeps the root's own time,
  // for the contact time; free flight from there is exact.
  const double fraction = std::ceil(hi * event_grid) / event_grid;
  if (fraction >= 1) return h;
  const StepCoefficients k(response(fraction * h), psi_, state_.compliance());
  Eigen::VectorXd trial(y.size());
  advance(k, y, law, trial);
  out = trial;
  return event == ContactEvent::separation ? hi * h : fraction * h;
}

// Solves for the end compression u1 with F1 = F(u1) and F1' = F'(u1) u1': Newton on
// g(u) = u - u_known + gC F(u) + gD F1'(u), kept inside [0, u_known] where g changes sign.
// `guess` is a prediction of u1 (the Taylor step from the start of the step).
double end_compression(const StepCoefficients& k, const ContactForce& law, double u_known, double du_known,
                       double guess) {
  if (u_known <= 0) return u_known;  // no force can arise: the ball is clear all step
  const double e = law.exponent();
  const auto g = [&](double u, double& slope) {
    const double f = law(u), inverse_u = 1 / u, stiffness = e * f * inverse_u;
    const double stiffness_rate = (e - 1) * stiffness * inverse_u;
    const double inverse_denominator = 1 / (1 + k.hD * stiffness), numerator = du_known - k.hC * f;
    const double rate = stiffness * numerator * inverse_denominator;
    const double rate_slope =
        (stiffness_rate * numerator - stiffness * k.hC * stiffness - rate * k.hD * stiffness_rate) * inverse_denominator;
    slope = 1 + k.gC * stiffness + k.gD * rate_slope;
    return u - u_known + k.gC * f + k.gD * rate;
  };
  double lo = 0, hi = u_known, slope = 0;
  double u = guess > 0 && guess < u_known ? guess : u_known / 2;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double value = g(u, slope);
    (value > 0 ? hi : lo) = u;
    double next = u - value / slope;
    // Newton converges quadratically: after a step of 1e-9 the error is of order 1e-18 (times
    // the law's curvature, below 1e-13 even for the stiffest expansion of a dead ball). The
    // force there is F(u) (1 + x)^e, x = (next - u) / u, to second order: exact to round-off.
    if (std::abs(next - u) <= 1e-9 * u) {
      const double x = (next - u) / u;
      law.remember(next, law(u) * (1 + e * x * (1 + (e - 1) / 2 * x)));
      return next;
    }
    if (hi - lo <= 1e-15 * hi) return next;
    if (!(next > lo && next < hi) || !(slope > 0)) next = (lo + hi) / 2;
    u = next;
  }
  return u;
}

// One pass over the modes for what is known before the end force (free rotation plus the
// response to F0 and F0'), summing the contact's u and u' on the way; a second adds the response
// to F1 and F1'. Plain loops: Eigen would make a pass per expression and one per sum.
void ExactStepper::advance(const StepCoefficients& k, const Eigen::VectorXd& y, const ContactForce& law,
                           Eigen::VectorXd& out) {
  const ModeResponse& m = *k.response;
  const int n = state_.modes();
  out.resize(y.size());
  const double *a = y.data() + 2, *v = a + n;
  double *out_a = out.data() + 2, *out_v = out_a + n;
  const double *c = m.c.data(), *sn = m.sn.data(), *w2sn = m.w2sn.data(), *psi = psi_.data(), *psi_w2 = psi_w2_.data();
  const auto column = [&k](StepCoefficients::Column j) { return k.driven.col(j).data(); };

  // The start: the ball's compression, its rate and acceleration, the force and its rate.
  const double u0 = state_.ball_compression(state_.compression(y), law), du0_geometric = state_.compression_rate(y);
  const double f0 = law(u0), k0 = u0 > 0 ? law.exponent() * f0 / u0 : 0.0;
  const double du0 = du0_geometric / (1 + state_.compliance() * k0), r0 = k0 * du0;

  const double *dA = column(k.dA), *dB = column(k.dB), *qA = column(k.qA), *qB = column(k.qB);
  double psi_a = 0, psi_v = 0, psi_w2a = 0;
#pragma omp simd reduction(+ : psi_a, psi_v, psi_w2a)
  for (int i = 0; i < n; ++i) {
    const double a_known = c[i] * a[i] + sn[i] * v[i] - f0 * dA[i] - r0 * dB[i];
    const double v_known = c[i] * v[i] - w2sn[i] * a[i] - f0 * qA[i] - r0 * qB[i];
    out_a[i] = a_known, out_v[i] = v_known;
    psi_a += psi[i] * a_known, psi_v += psi[i] * v_known, psi_w2a += psi_w2[i] * a[i];
  }
  const double s_known = y(0) + y(1) * m.h + f0 * m.ball_d[0] + r0 * m.ball_d[1];
  const double vb_known = y(1) + f0 * m.ball_q[0] + r0 * m.ball_q[1];
  const double u_known = psi_a - s_known, du_known = psi_v - vb_known;

  const double ddu0 = -psi_w2a - f0 * (k.psi2_sum + 1 / state_.ball_mass());
  const double guess = u0 + m.h * du0 + 0.5 * m.h * m.h * ddu0;
  const double u1 = end_compression(k, law, u_known, du_known, guess);
  const double f1 = law(u1);
  const double stiffness = u1 > 0 ? law.exponent() * f1 / u1 : 0.0;
  const double r1 = stiffness * (du_known - k.hC * f1) / (1 + k.hD * stiffness);

  out(0) = s_known + f1 * m.ball_d[2] + r1 * m.ball_d[3];
  out(1) = vb_known + f1 * m.ball_q[2] + r1 * m.ball_q[3];
  const double *dC = column(k.dC), *dD = column(k.dD), *qC = column(k.qC), *qD = column(k.qD);
#pragma omp simd
  for (int i = 0; i < n; ++i) {
    out_a[i] -= f1 * dC[i] + r1 * dD[i];
    out_v[i] -= f1 * qC[i] + r1 * qD[i];
  }
  // The end's u and u' follow from the sums already made, without another pass over the modes.
  // The geometric u is the ball's own plus the residual compliance's yield (equal to the sums to
  // round-off, and exactly consistent with u1, whose force is known).
  state_.remember(out, u1 + state_.compliance() * f1, psi_v - f1 * k.mode_qC - r1 * k.mode_qD - out(1), law, u1);
}

}  // namespace sweetspot::detail
