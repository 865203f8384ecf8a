#include "sweetspot/impact/formulas.hpp"

#include <array>
#include <cmath>
#include <complex>

#include "contact/damped_mode.hpp"

namespace sweetspot {

namespace {

// 8-point Gauss-Legendre on [0, 1]: exact for degree 15, so a cubic times e^(i omega t) is
// integrated to round-off while omega times the sample step stays below about 1.
constexpr std::array<double, 8> gl_x = {0.0198550717512319, 0.1016667612931866, 0.2372337950418355,
                                        0.4082826787521751, 0.5917173212478249, 0.7627662049581645,
                                        0.8983332387068134, 0.9801449282487681};
constexpr std::array<double, 8> gl_w = {0.0506142681451881, 0.1111905172266872, 0.1568533229389436,
                                        0.1813418916891810, 0.1813418916891810, 0.1568533229389436,
                                        0.1111905172266872, 0.0506142681451881};

double hermite(const ForceSample& p, const ForceSample& q, double s) {
  const double h = q.t - p.t, s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p.force + (s3 - 2 * s2 + s) * h * p.rate + (-2 * s3 + 3 * s2) * q.force +
         (s3 - s2) * h * q.rate;
}

// integral of F(t) kernel(t) dt over the samples.
template <class Kernel>
auto integrate(const std::vector<ForceSample>& force, Kernel kernel) {
  decltype(kernel(0.0)) sum{};
  for (std::size_t i = 1; i < force.size(); ++i) {
    const ForceSample &p = force[i - 1], &q = force[i];
    const double h = q.t - p.t;
    if (h <= 0) continue;
    for (std::size_t j = 0; j < gl_x.size(); ++j) sum += gl_w[j] * h * hermite(p, q, gl_x[j]) * kernel(p.t + gl_x[j] * h);
  }
  return sum;
}

double impulse(const std::vector<ForceSample>& force) {
  return integrate(force, [](double) { return 1.0; });
}

}  // namespace

double rigid_exit_speed(double e0, double recoil, double ball_speed, double bat_speed) {
  return ((e0 - recoil) * ball_speed + (e0 + 1) * bat_speed) / (1 + recoil);
}

double effective_cor(double vf, double recoil, double ball_speed, double bat_speed) {
  return (vf * (1 + recoil) + recoil * ball_speed - bat_speed) / (ball_speed + bat_speed);
}

double lossless_exit_speed(double response_sum, double ball_speed, double bat_speed) {
  return ((1 - response_sum) * ball_speed + 2 * bat_speed) / (1 + response_sum);
}

std::vector<double> force_responses(const std::vector<ForceSample>& force, const std::vector<double>& omegas) {
  const std::complex<double> i(0, 1);
  const double j = impulse(force);
  std::vector<double> g;
  for (double omega : omegas)
    g.push_back(std::norm(integrate(force, [&](double t) { return std::exp(i * omega * t); }) / j));
  return g;
}

double force_response(const std::vector<ForceSample>& force, double omega) { return force_responses(force, {omega})[0]; }

std::vector<double> mode_responses(const ModalContact& body, double ball_mass, const std::vector<ForceSample>& force) {
  const std::vector<double> g = force_responses(force, {body.omega.data(), body.omega.data() + body.count()});
  std::vector<double> r;
  for (int n = 0; n < body.count(); ++n) r.push_back(ball_mass * body.psi(n) * body.psi(n) * g[n]);
  return r;
}

double van_zandt_exit_speed(const ModalContact& body, const Ball& ball, double recoil, double ball_speed,
                            double bat_speed, const std::vector<ForceSample>& force) {
  // A mode at rest driven by -Fhat psi_n moves at -psi_n int Fhat(t) cos(omega (tau - t)) dt at tau;
  // a damped one (the barrel wall) at -psi_n int Fhat(t) G'(tau - t) dt, G its impulse response.
  const double tau = force.back().t, j = impulse(force);
  double a_vib = 0;
  for (int n = 0; n < body.count(); ++n) {
    const double w = body.omega(n), zeta = body.damping(n);
    if (w == 0) continue;
    if (zeta != 0) {
      const auto kernel = [&](double t) { return detail::damped_impulse_response(w, zeta, tau - t).g_rate; };
      a_vib += body.psi(n) * body.psi(n) * integrate(force, kernel) / j;
      continue;
    }
    a_vib += body.psi(n) * body.psi(n) * integrate(force, [&](double t) { return std::cos(w * (tau - t)); }) / j;
  }
  return rigid_exit_speed(ball.e0, recoil + ball.mass * a_vib, ball_speed, bat_speed);
}

}  // namespace sweetspot
