#pragma once
// Internal: closed forms of a viscously damped mode a'' + 2 zeta w a' + w^2 a = g(t), w > 0,
// 0 < zeta < 1 (a hollow barrel's wall, README "Hollow barrels"). With sigma = zeta w and the
// damped frequency w_d = w sqrt(1 - zeta^2), the impulse response is
//   G(s) = exp(-sigma s) sin(w_d s) / w_d,   G'(s) = exp(-sigma s) (cos(w_d s) - sigma / w_d sin(w_d s)),
// (G(0) = 0, G'(0) = 1), and every closed form below follows from it: the free evolution of the
// state (a, a') and, in the exact stepper, the response to the force's polynomial pieces.
#include <cmath>

namespace sweetspot::detail {

// The state after tau of free evolution: a = aa a0 + av v0, a' = va a0 + vv v0 (zeta = 0 gives
// cos, sin / w, -w sin, cos).
struct FreeEvolution {
  double aa, av, va, vv;
};

struct ImpulseResponse {
  double g, g_rate;  // G(tau), G'(tau)
};

inline ImpulseResponse damped_impulse_response(double w, double zeta, double tau) {
  const double sigma = zeta * w, wd = w * std::sqrt(1 - zeta * zeta), decay = std::exp(-sigma * tau);
  const double sine = std::sin(wd * tau), cosine = std::cos(wd * tau);
  return {decay * sine / wd, decay * (cosine - sigma / wd * sine)};
}

// Homogeneous solution fitted to (a0, v0): a = a0 (G' + 2 sigma G) + v0 G, a' = -w^2 G a0 + G' v0.
inline FreeEvolution damped_free_evolution(double w, double zeta, double tau) {
  const ImpulseResponse r = damped_impulse_response(w, zeta, tau);
  return {r.g_rate + 2 * zeta * w * r.g, r.g, -w * w * r.g, r.g_rate};
}

// The energy 1/2 (a'^2 + w^2 a^2) a free damped mode loses between two of its states: exactly
// what its damping dissipates, int 2 zeta w a'^2 dt, since nothing else acts on it.
inline double free_decay_loss(double w, double a0, double v0, double a1, double v1) {
  return 0.5 * ((v0 * v0 - v1 * v1) + w * w * (a0 * a0 - a1 * a1));
}

}  // namespace sweetspot::detail
