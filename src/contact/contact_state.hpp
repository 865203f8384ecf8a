#pragma once
// Internal: the state of ball and modes during a collision, shared by the steppers.
// y = [s, v, a_0..a_{n-1}, a_0'..a_{n-1}'], s the ball's displacement from first touch (+y); with
// damped modes one more entry, the energy their damping has dissipated (J), int 2 zeta w a'^2 dt,
// integrated with the rest. Without damping y is exactly what it always was.
#include <Eigen/Dense>
#include <array>
#include <optional>
#include <cmath>
#include <vector>

#include "sweetspot/contact/ball.hpp"
#include "sweetspot/contact/collision.hpp"

namespace sweetspot::detail {

class ContactState {
 public:
  ContactState(const ModalContact& body, const Ball& ball, bool damping_loss = true)
      : body_(body), n_(body.count()), mass_(ball.mass), damping_loss_(damping_loss), omega2_(body.omega.array().square()),
        compliance_(body.residual_compliance), mobility_(1 / ball.mass + body.psi.squaredNorm()) {
    for (int i = 0; i < n_; ++i)
      if (body.damping(i) != 0) damped_.push_back({i, 2 * body.damping(i) * body.omega(i)});
  }

  int modes() const { return n_; }
  int size() const { return 2 + 2 * n_ + (dissipated_index() < 0 ? 0 : 1); }
  // The index of the dissipated energy in y, or -1 without damped modes or when it is not asked.
  int dissipated_index() const { return damped_.empty() || !damping_loss_ ? -1 : 2 + 2 * n_; }
  // A damped mode and its rate 2 zeta omega (the damping force per unit velocity).
  struct DampedMode {
    int mode;
    double rate;
  };
  const std::vector<DampedMode>& damped() const { return damped_; }
  double ball_mass() const { return mass_; }
  const ModalContact& body() const { return body_; }
  const Eigen::ArrayXd& omega2() const { return omega2_; }

  double compliance() const { return compliance_; }

  // The geometric compression u = y_k - s: the ball touches while u > 0. Events (maximum
  // compression, separation) are its zero crossings and those of u'.
  double compression(const Eigen::VectorXd& y) const {
    return known(y) ? known_u_ : body_.psi.dot(y.segment(2, n_)) - y(0);
  }
  double compression_rate(const Eigen::VectorXd& y) const {
    return known(y) ? known_du_ : body_.psi.dot(y.segment(2 + n_, n_)) - y(1);
  }
  // A stepper that knows u and u' of a state it made in closed form leaves them here: events,
  // samples and the next step ask for them again, and then cost no dot product over the modes.
  // It knows the ball's own compression too (it solved for it): that saves solving again.
  void remember(const Eigen::VectorXd& y, double u, double du, const ContactForce& law, double ball_u) const {
    known_key_ = key(y), known_u_ = u, known_du_ = du;
    remember_ball_compression(u, law, ball_u);
  }
  // The ball's own compression: the dropped modes' static yield c F takes up part of the
  // geometric one, u_ball + c F(u_ball) = u (the same when no mode was dropped, c = 0).
  double ball_compression(double u, const ContactForce& law) const {
    if (compliance_ == 0 || u <= 0) return u;
    // Asked again for the same state (samples, step limits, the next step's start): reuse.
    if (u == last_u_ && &law == last_law_ && law.expanding() == last_expanding_ && law.u_max() == last_u_max_)
      return last_ball_u_;
    remember_ball_compression(u, law, solve_ball_compression(u, law));
    return last_ball_u_;
  }
  // g(x) = x + c F(x) - u is convex and rising: Newton from above the root falls to it without
  // overshooting. From x = u it falls by about x / e a step where c F(u) far exceeds u on a steep
  // branch (F ~ u^e, e up to ~800 for a nearly dead ball): 100 steps left it 27 % off. The
  // compression whose force alone takes up u, F(x) = u / c, is an upper bound as close to the
  // root as e is large; it is taken where it lies below u.
  double solve_ball_compression(double u, const ContactForce& law) const {
    double lo = 0, hi = u, x = u;
    if (compliance_ * law(u) > u) hi = x = law.compression_at(u / compliance_);
    for (int iteration = 0; iteration < 100; ++iteration) {
      const double f = law(x), g = x + compliance_ * f - u, slope = 1 + compliance_ * law.exponent() * f / x;
      (g > 0 ? hi : lo) = x;
      double next = x - g / slope;
      if (std::abs(next - x) <= 1e-15 * x) return next;
      x = next > lo && next < hi ? next : (lo + hi) / 2;
    }
    return x;
  }
  void remember_ball_compression(double u, const ContactForce& law, double ball_u) const {
    last_u_ = u, last_law_ = &law, last_expanding_ = law.expanding(), last_u_max_ = law.u_max();
    last_ball_u_ = ball_u;
  }
  double force(const Eigen::VectorXd& y, const ContactForce& law) const {
    return law(ball_compression(compression(y), law));
  }
  // u'' = sum psi_n a_n'' - s'' = -sum psi_n omega_n^2 a_n - F (sum psi_n^2 + 1/m).
  // Damped modes add -sum psi_n 2 zeta_n omega_n a_n'.
  double compression_acceleration(const Eigen::VectorXd& y, const ContactForce& law) const {
    double damping = 0;
    for (const DampedMode& d : damped_) damping += body_.psi(d.mode) * d.rate * y(2 + n_ + d.mode);
    return -(body_.psi.array() * omega2_ * y.segment(2, n_).array()).sum() -
           force(y, law) * (body_.psi.squaredNorm() + 1 / mass_) - damping;
  }
  // The frequency at which the contact itself rings: the ball's stiffness F'(u) (in series with
  // the residual compliance) against the mobility 1/m + sum psi_n^2 of ball and kept modes. On
  // the expansion branch F'(u) = b F / u with b = (1 + a)/e0^2 - 1, huge for a nearly dead ball.
  // Asked at a step's end and again at the next one's start: the last answer is kept.
  double contact_frequency(const Eigen::VectorXd& y, const ContactForce& law) const {
    const double u = ball_compression(compression(y), law);
    if (u <= 0) return 0;
    if (u == frequency_u_ && &law == frequency_law_ && law.expanding() == frequency_expanding_ &&
        law.u_max() == frequency_u_max_)
      return frequency_;
    const double stiffness = law.stiffness(u);
    frequency_u_ = u, frequency_law_ = &law, frequency_expanding_ = law.expanding(), frequency_u_max_ = law.u_max();
    frequency_ = std::sqrt(stiffness / (1 + compliance_ * stiffness) * mobility_);
    return frequency_;
  }
  // Force and its time derivative dF/dt = F'(u_ball) u_ball', u_ball' = u' / (1 + c F').
  ForceSample sample(double t, const Eigen::VectorXd& y, const ContactForce& law) const {
    const double u = ball_compression(compression(y), law), force = law(u);
    const double stiffness = law.stiffness(u);  // F'(u): the force's pow is remembered
    return {t, force, stiffness * compression_rate(y) / (1 + compliance_ * stiffness)};
  }

  // dy/dt: the ball pushed by +F, every mode by -F psi_n.
  void derivative(const Eigen::VectorXd& y, const ContactForce& law, Eigen::VectorXd& dy) const {
    const double force = this->force(y, law);
    dy(0) = y(1);
    dy(1) = force / mass_;
    dy.segment(2, n_) = y.segment(2 + n_, n_);
    dy.segment(2 + n_, n_) = -(omega2_ * y.segment(2, n_).array()).matrix() - force * body_.psi;
    if (damped_.empty()) return;
    double power = 0;  // the damping's dissipation rate, sum 2 zeta w a'^2
    for (const DampedMode& d : damped_) {
      const double v = y(2 + n_ + d.mode);
      dy(2 + n_ + d.mode) -= d.rate * v;
      power += d.rate * v * v;
    }
    if (damping_loss_) dy(2 + 2 * n_) = power;
  }

 private:
  const ModalContact& body_;
  int n_;
  double mass_;
  bool damping_loss_;
  Eigen::ArrayXd omega2_;
  double compliance_;
  double mobility_;
  std::vector<DampedMode> damped_;
  mutable double last_u_ = -1, last_ball_u_ = 0, last_u_max_ = 0;
  // The state remembered (ball position and speed, first and last modal coordinates) and its u, u'.
  using Key = std::array<double, 4>;
  Key key(const Eigen::VectorXd& y) const {
    return {y(0), y(1), n_ ? y(2) : 0.0, n_ ? y(1 + 2 * n_) : 0.0};
  }
  bool known(const Eigen::VectorXd& y) const { return known_key_ == key(y); }
  mutable Key known_key_ = {std::nan(""), 0, 0, 0};
  mutable double known_u_ = 0, known_du_ = 0;
  mutable const ContactForce* last_law_ = nullptr;
  mutable bool last_expanding_ = false;
  mutable double frequency_u_ = -1, frequency_u_max_ = 0, frequency_ = 0;
  mutable const ContactForce* frequency_law_ = nullptr;
  mutable bool frequency_expanding_ = false;
};

// What a stepper says of an attempted step: adaptive ones may reject it and propose a new size.
struct StepOutcome {
  bool accepted = true;
  double next_h = 0;
};

// The fixed-step methods resolve the contact's own ringing: omega_c h stays below the options'
// contact_phase_limit at both ends of a step (at the start by choosing h, at the end by redoing
// the step at half length: a nearly dead ball re-compressed on its steep expansion branch
// stiffens a thousandfold in a step).
constexpr double smallest_step = 1e-12;  // s

inline bool too_stiff_at_end(const ContactState& state, const Eigen::VectorXd& out, double h,
                             const ContactForce& law, const CollisionOptions& options) {
  return h > smallest_step && state.contact_frequency(out, law) * h > options.contact_phase_limit;
}

// The events of a contact: maximum compression (u' falls through 0: the force law switches to
// expansion), separation (u falls through 0) and reloading (an expanding ball pressed past its
// maximum compression: the law switches back). Each is the zero of a value falling through 0.
enum class ContactEvent { max_compression, separation, reloading };

// The geometric compression at which the ball's own reaches the expansion branch's u_m (the
// residual compliance yields c F_m on top).
inline double reloading_compression(const ContactState& state, const ContactForce& law) {
  return law.u_max() + state.compliance() * law.f_max();
}

inline double event_value(const ContactState& state, ContactEvent event, const Eigen::VectorXd& y,
                          const ContactForce& law) {
  switch (event) {
    case ContactEvent::max_compression: return state.compression_rate(y);
    case ContactEvent::separation: return state.compression(y);
    case ContactEvent::reloading: break;
  }
  return reloading_compression(state, law) - state.compression(y);
}

inline double event_rate(const ContactState& state, ContactEvent event, const Eigen::VectorXd& y,
                         const ContactForce& law) {
  switch (event) {
    case ContactEvent::max_compression: return state.compression_acceleration(y, law);
    case ContactEvent::separation: return state.compression_rate(y);
    case ContactEvent::reloading: break;
  }
  return -state.compression_rate(y);
}

// The cubic Hermite through (f0, d0) at s = 0 and (f1, d1) at s = 1 (d: the slopes in s), at s.
inline double hermite(double s, double f0, double d0, double f1, double d1) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * f0 + (s3 - 2 * s2 + s) * d0 + (-2 * s3 + 3 * s2) * f1 + (s3 - s2) * d1;
}

// Illinois regula falsi for where f falls through zero in (lo, hi], given f(lo) = f_lo > 0 >=
// f(hi) = f_hi: it keeps that bracket, and halving the weight of an end that stays put closes both
// sides, in about a dozen evaluations where bisection takes 50 (bisection while the ends do not
// bracket). Stops when done(lo, hi) or f is 0; returns the bracket.
struct Bracket {
  double lo, hi;
};
template <class F, class Done>
Bracket falling_root(F f, double lo, double hi, double f_lo, double f_hi, Done done, int iterations) {
  int side = 0;
  for (int iteration = 0; iteration < iterations && !done(lo, hi); ++iteration) {
    double x = f_lo > 0 && f_hi <= 0 ? hi - f_hi * (hi - lo) / (f_hi - f_lo) : (lo + hi) / 2;
    if (!(x > lo && x < hi)) x = (lo + hi) / 2;
    const double value = f(x);
    if (value > 0) {
      lo = x, f_lo = value;
      if (side == 1) f_hi /= 2;
      side = 1;
    } else {
      hi = x, f_hi = value;
      if (side == -1) f_lo /= 2;
      side = -1;
      if (value == 0) break;
    }
  }
  return {lo, hi};
}

// Where inside (0, 1) the cubic Hermite through (u0, d0) at s = 0 and (u1, d1) at s = 1 (d: the
// slopes in s) peaks above `level`, if it rises at the start, falls at the end and does: its
// slope, a quadratic, changes sign once in between.
inline std::optional<double> hermite_peak(double u0, double d0, double u1, double d1, double level) {
  if (!(d0 > 0 && d1 < 0)) return std::nullopt;
  const double a = 6 * (u0 - u1) + 3 * (d0 + d1), b = 6 * (u1 - u0) - 4 * d0 - 2 * d1;  // slope a s^2 + b s + d0
  double s = -d0 / b;  // a = 0: linear
  if (a != 0) {
    const double root = std::sqrt(std::max(b * b - 4 * a * d0, 0.0));
    const double first = (-b - root) / (2 * a), second = (-b + root) / (2 * a);
    s = first > 0 && first < 1 ? first : second;
  }
  if (!(s > 0 && s < 1)) return std::nullopt;
  return hermite(s, u0, d0, u1, d1) > level ? std::optional(s) : std::nullopt;
}

// The step h* in (0, h] at which the event value of step(y, h*) crosses zero, given it is > 0 at y
// and <= 0 at out = step(y, h), by falling_root over re-made steps. Leaves in `out` the state just
// past the event (value <= 0) and returns h*. Suits steppers whose steps are cheap to repeat.
template <class Stepper>
double locate_by_restepping(Stepper& stepper, const ContactState& state, const Eigen::VectorXd& y, double h,
                            const ContactForce& law, ContactEvent event, Eigen::VectorXd& out) {
  Eigen::VectorXd trial(y.size());
  const auto value = [&](double step) {
    stepper.step(y, step, law, trial);
    return event_value(state, event, trial, law);
  };
  const Bracket root =
      falling_root(value, 0.0, h, event_value(state, event, y, law), event_value(state, event, out, law),
                   [h](double a, double b) { return b - a <= 1e-15 * h; }, 100);
  stepper.step(y, root.hi, law, out);
  return root.hi;
}

}  // namespace sweetspot::detail
