#include "contact/rigid_collision.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace sweetspot::detail {

double whole_branch_time(double q) {
  return std::tgamma(1 / q) * std::sqrt(std::numbers::pi) / std::tgamma(1 / q + 0.5) / q;
}

// Two series, each used where it converges at least as 2^-k: for level <= 1/2 the binomial series
// of (1 - x^q)^(-1/2) term by term; above it the remainder to x = 1, which w = sqrt(1 - x^q)
// turns into (2/q) int_0^W (1 - w^2)^(1/q - 1) dw, W^2 = 1 - level <= 1/2.
double branch_time(double level, double q) {
  constexpr int max_terms = 200;
  constexpr double relative = 1e-17;
  if (level <= 0.5) {
    const double x = std::pow(level, 1 / q);
    double sum = 0, coefficient = 1, power = x;  // coefficient binom(2k, k) / 4^k, power x level^k
    for (int k = 0; k < max_terms; ++k) {
      const double term = coefficient * power / (q * k + 1);
      sum += term;
      if (term <= relative * sum) break;
      coefficient *= (2 * k + 1) / (2.0 * k + 2);
      power *= level;
    }
    return sum;
  }
  const double w2 = 1 - level, c = 1 / q - 1;
  double sum = 0, coefficient = 1, power = std::sqrt(w2);  // coefficient (-1)^k binom(c, k), power W^(2k+1)
  for (int k = 0; k < max_terms; ++k) {
    const double term = coefficient * power / (2 * k + 1);
    sum += term;
    if (term <= relative * sum) break;
    coefficient *= (k - c) / (k + 1);
    power *= w2;
  }
  return whole_branch_time(q) - 2 / q * sum;
}

std::optional<Collision> rigid_collision(const ModalContact& body, const Ball& ball, double ball_speed,
                                         const CollisionOptions& options) {
  if (options.record_force || body.residual_compliance != 0 || body.damped() || (body.omega.array() != 0).any())
    return std::nullopt;
  const double bat = body.psi.dot(body.velocity0), closing = ball_speed + bat;
  if (!(closing > 1e-12 * (std::abs(bat) + std::abs(ball_speed)))) return std::nullopt;  // the stepper's no_contact
  const double mobility = 1 / ball.mass + body.psi.squaredNorm(), a = ball.a;
  // Closing: 1/2 u'^2 + mu k1 u^(a+1) / (a+1) = 1/2 w0^2. Parting from u_m on F_m (u/u_m)^b, whose
  // energy F_m u_m / (b+1) is e^2 of the stored one: u' = e w0 at separation.
  ContactForce law(ball);
  const double u_max = std::pow((a + 1) * closing * closing / (2 * mobility * ball.k1), 1 / (a + 1));
  if (!(u_max > 0)) return std::nullopt;
  law.start_expansion(u_max);  // b from the stored energy's COR, as the stepper's law takes it
  const double b = law.exponent(), parting = std::sqrt((1 + a) / (1 + b)) * closing;
  const double compression_time = u_max / closing * whole_branch_time(a + 1);
  const double expansion_time = u_max / parting * whole_branch_time(b + 1);
  const double contact_time = compression_time + expansion_time;
  if (!std::isfinite(contact_time) || !(contact_time <= options.max_contact_time)) return std::nullopt;

  Collision c;
  c.impulse = (closing + parting) / mobility;
  c.ball_velocity = -ball_speed + c.impulse / ball.mass;
  c.a_dot = body.velocity0 - c.impulse * body.psi;
  // u(T) = 0 at separation makes the force's moment int_0^T (T - s) F ds = w0 T / mu.
  c.a = contact_time * (body.velocity0 - closing / mobility * body.psi);
  c.contact_time = contact_time;
  c.u_max = u_max;
  c.peak_force = law.f_max();
  c.dissipated = law.loop_energy();
  c.contacts = 1;
  c.force_peaks = 1;  // the rigid bat's pulse rises to one maximum and falls
  c.collision_time = std::numeric_limits<double>::quiet_NaN();
  if (options.find_collision_time) {
    // The impulse delivered is (w0 - u') / mu: the fraction's is reached where u' is this.
    const double rate = closing - collision_time_fraction * (closing + parting);
    if (rate >= 0) {
      c.collision_time = u_max / closing * branch_time(1 - (rate / closing) * (rate / closing), a + 1);
    } else {
      const double level = 1 - (rate / parting) * (rate / parting);
      c.collision_time = compression_time + expansion_time - u_max / parting * branch_time(level, b + 1);
    }
  }
  return c;
}

}  // namespace sweetspot::detail
