#include "sweetspot/contact/tangential_contact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sweetspot {

namespace {

// 1/x with 1/inf = 0: an infinite inertia takes no part.
double inverse(double x) { return std::isinf(x) ? 0.0 : 1 / x; }

// Each of the normal force's sample intervals (the collision's steps) is stepped in this many
// substeps: the tangential error then scales with the collision's step, at second order, and step
// doubling sees it with the normal collision's. (A cap on the grip's phase per substep kept them
// from growing past 13 us steps, where doubling the step then missed the error.)
constexpr int substeps_per_interval = 4;

// The normal force at t in a sample interval, never negative (the Hermite cubic may dip below
// zero between a separation and the next touch, where the force is zero).
double normal_at(const ForceSample& p, const ForceSample& q, double t) {
  if (p.force <= 0 && q.force <= 0) return 0;
  return std::max(0.0, interpolate_force(p, q, t).force);
}

// The stretch held from a step at stiffness `held`, seen at the next step's stiffness `k`. The
// grip's stiffness follows the normal force; a stretch held while it rose would raise the
// tangential force with no work done, and spring back with more energy than the bodies put in
// (friction giving energy: a curveball's topspin under a small undercut, at mu 0.2). So the grip
// loads incrementally (dF = k ds: the force is kept as the stiffness rises, the stretch scaled
// down) and unloads with its stretch kept (the force falls with the stiffness). Either way a
// change of stiffness takes energy or none, as in Mindlin & Deresiewicz's contact under varying
// oblique forces (J. Appl. Mech. 20, 327 (1953)) and the rescaled Mindlin law of granular codes
// (I. Agnolin & J.-N. Roux, Phys. Rev. E 76, 061302 (2007); LAMMPS's mindlin_rescale/force).
double stretch_at(double x, double held, double k) { return k > held && held > 0 ? x * (held / k) : x; }

// A piece of a substep in which the contact turns from gripping to sliding or back is halved, and
// each half made in turn, this many times at most: the switch is then found within 1/4096 of the
// substep. Left at the substep's end, a switch errs by up to a substep, which the spin follows at
// first order (1.4 % of the backspin at the default 10 us step).
constexpr int max_switch_halvings = 12;

// The tangential contact stepped through the normal force. The ball's surface is a spring of
// stiffness k with a damper c in parallel (stretch x), in series with Coulomb's slider: while the
// slider holds (the contact grips) the spring and damper take the whole slip s, a damped
// oscillation exact over a piece; while it slides their force is mu N, against the slider's motion
// s - x', and the stretch relaxes toward mu N / k at the rate k / c (exact over a piece, N linear in
// it). The slider starts once the force would pass mu N, and stops once its motion would turn. Each
// switch is found inside its substep by halving.
class GripRun {
 public:
  GripRun(const GripLaw& grip, double inverse_mass, double slip)
      : grip_(grip), inverse_mass_(inverse_mass), mass_(1 / inverse_mass), slip_(slip) {}

  // A piece of the sample interval p..q (its normal force the collision's cubic Hermite there),
  // from t0 for h, with the normal force at its ends and middle.
  struct Piece {
    double t0, h, n0, n_mid, n1;
    // The impulse of the normal force over the piece: Simpson's rule, exact for the cubic.
    double normal_impulse() const { return h / 6 * (n0 + 4 * n_mid + n1); }
  };
  Piece piece(const ForceSample& p, const ForceSample& q, double t0, double h, double n0, double n1) const {
    return {t0, h, n0, normal_at(p, q, t0 + h / 2), n1};
  }

  void advance(const ForceSample& p, const ForceSample& q, const Piece& piece, int halvings = 0) {
    if (!(piece.h > 0)) return;
    if (std::isinf(grip_.grip_stiffness)) return roll(piece);
    if (sliding_) return slide(p, q, piece, halvings);
    grip(p, q, piece, halvings);
  }
  // Apart: the grip lets go of its stretch.
  void release() { stretch_ = 0, held_ = 0, sliding_ = false; }

  double impulse() const { return impulse_; }
  double loss() const { return loss_; }
  bool slid() const { return slid_; }

 private:
  // An impulse j on the ball: the bodies' energy is quadratic in it, so the loss over the piece
  // is -j times the mean of the slips at its ends.
  void take(double j) {
    const double s1 = slip_ + j * inverse_mass_;
    loss_ -= j * 0.5 * (slip_ + s1);
    impulse_ += j;
    slip_ = s1;
  }

  // The rigid grip of the textbooks: bring the slip to rest if friction can, then roll.
  void roll(const Piece& piece) {
    const double limit = grip_.friction * piece.normal_impulse(), stop = -slip_ / inverse_mass_;
    const bool slides = std::abs(stop) > limit;
    take(slides ? std::copysign(limit, stop) : stop);
    slid_ = slid_ || (slides && limit > 0);
  }

  double damper(double k) const { return 2 * grip_.damping_ratio * std::sqrt(k * mass_); }

  // Gripping: the spring and damper take the slip, exact over the piece, at the stiffness of its
  // mean normal force. Where their force ends past mu N the piece is halved, each half made in
  // turn, until the switch to sliding is found.
  void grip(const ForceSample& p, const ForceSample& q, const Piece& piece, int halvings) {
    const double h = piece.h, n1 = piece.n1;
    const double k = grip_.stiffness(0.5 * (piece.n0 + piece.n1)), x = stretch_at(stretch_, held_, k), s = slip_;
    double s1 = s, x1 = 0;  // no normal force: no force, and no stretch held
    if (k > 0) {
      const double w0 = std::sqrt(k * inverse_mass_), zeta = grip_.damping_ratio;
      const double a = zeta * w0, w = w0 * std::sqrt(1 - zeta * zeta);
      const double decay = std::exp(-a * h), c = std::cos(w * h), sn = std::sin(w * h);
      const double b = (s + a * x) / w;  // x(t) = e^(-at) (x cos wt + b sin wt)
      x1 = decay * (x * c + b * sn);
      s1 = decay * (s * c - (a * b + w * x) * sn);
    }
    // The force at the piece's end as the next piece holds it: its stretch at the end's stiffness.
    const double k_end = grip_.stiffness(n1);
    const double force = -k_end * stretch_at(x1, k, k_end) - damper(k_end) * s1;
    if (std::abs(force) <= grip_.friction * n1) {
      take((s1 - s) * mass_);
      stretch_ = x1, held_ = k;
      return;
    }
    if (halvings < max_switch_halvings) return halve(p, q, piece, halvings);
    slide_sign_ = force > 0 ? 1.0 : -1.0;  // found: the slider starts, against the force
    sliding_ = true;
    slide(p, q, piece, halvings);
  }

  // Sliding: the force on the ball sign * mu N(t). The stretch follows k x + c x' = -sign mu N(t)
  // (N linear over the piece) from where it is (without a damper, at once). Where the slider's
  // motion s - x' has turned by the piece's end (it moves against the force while it slides), the
  // piece is halved until the switch to gripping is found.
  void slide(const ForceSample& p, const ForceSample& q, const Piece& piece, int halvings) {
    const double h = piece.h, n0 = piece.n0, n1 = piece.n1;
    const double k = grip_.stiffness(0.5 * (n0 + n1)), x0 = stretch_at(stretch_, held_, k), c = damper(k);
    const double j = slide_sign_ * grip_.friction * piece.normal_impulse(), s1 = slip_ + j * inverse_mass_;
    double x1 = 0, rate1 = 0;  // the stretch and its rate at the end
    if (k > 0) {
      // x relaxes toward the moving target a + b t (-sign mu N / k) with the time constant c / k.
      const double a = -slide_sign_ * grip_.friction * n0 / k, b = -slide_sign_ * grip_.friction * (n1 - n0) / (k * h);
      const double tau = c / k, transient = tau > 0 ? (x0 - a + b * tau) * std::exp(-h / tau) : 0.0;
      x1 = a + b * (h - tau) + transient;
      // Its rate at the end from the stretch as the next piece holds it, at the end's stiffness.
      const double k_end = grip_.stiffness(n1), c_end = damper(k_end);
      rate1 = c_end > 0 ? (-slide_sign_ * grip_.friction * n1 - k_end * stretch_at(x1, k, k_end)) / c_end : b;
    }
    const bool held = (s1 - rate1) * slide_sign_ >= 0;
    if (held && halvings < max_switch_halvings) return halve(p, q, piece, halvings);
    slid_ = true;
    take(j);
    stretch_ = x1, held_ = k;
    if (held) sliding_ = false;  // found: the slider stops, and the contact grips again
  }

  void halve(const ForceSample& p, const ForceSample& q, const Piece& whole, int halvings) {
    const double h = whole.h / 2;
    advance(p, q, piece(p, q, whole.t0, h, whole.n0, whole.n_mid), halvings + 1);
    advance(p, q, piece(p, q, whole.t0 + h, h, whole.n_mid, whole.n1), halvings + 1);
  }

  const GripLaw& grip_;
  double inverse_mass_, mass_;
  double slip_, stretch_ = 0, held_ = 0;
  bool sliding_ = false, slid_ = false;
  double slide_sign_ = 0;
  double impulse_ = 0, loss_ = 0;
};

}  // namespace

double TangentialBodies::inverse_mass() const {
  return 1 / ball_mass + ball_radius * ball_radius * inverse(ball_inertia) + bat_mobility +
         bat_radius * bat_radius * inverse(bat_axial_inertia);
}

double TangentialMotion::slip(const TangentialBodies& b) const {
  return ball_velocity - b.ball_radius * ball_spin - (bat_velocity + b.bat_radius * bat_roll);
}

double TangentialMotion::energy_change_from(const TangentialMotion& initial, const TangentialBodies& b) const {
  const double j = b.ball_mass * (ball_velocity - initial.ball_velocity);  // the impulse on the ball
  const double ball = 0.5 * b.ball_mass * (ball_velocity * ball_velocity - initial.ball_velocity * initial.ball_velocity) +
                      0.5 * b.ball_inertia * (ball_spin * ball_spin - initial.ball_spin * initial.ball_spin);
  // The bat takes -j at a point moving from V0 to V1 (and W0 to W1): work -j (V0 + V1) / 2, exact
  // for a body linear in its impulse, also where its inertia is infinite (V1 = V0).
  const double bat = -j * 0.5 * (initial.bat_velocity + bat_velocity) -
                     j * b.bat_radius * 0.5 * (initial.bat_roll + bat_roll);
  return ball + bat;
}

double damping_ratio_for(double e) {
  if (!(e < 1)) return 0;
  const double log_e = std::log(e);
  return -log_e / std::sqrt(std::numbers::pi * std::numbers::pi + log_e * log_e);
}

double GripLaw::stiffness(double n) const {
  if (!(n > 0)) return 0;
  // dN/du = a k1 u^(a-1) at the u where k1 u^a = n.
  return grip_stiffness * a * std::pow(k1, 1 / a) * std::pow(n, (a - 1) / a);
}

TangentialMotion after_impulse(const TangentialBodies& b, const TangentialMotion& m, double j) {
  TangentialMotion next = m;
  next.ball_velocity += j / b.ball_mass;
  next.ball_spin -= b.ball_radius * j * inverse(b.ball_inertia);
  next.bat_velocity -= j * b.bat_mobility;
  next.bat_roll -= b.bat_radius * j * inverse(b.bat_axial_inertia);
  return next;
}

TangentialMotion rolling_exit(const TangentialBodies& b, const TangentialMotion& initial) {
  return after_impulse(b, initial, -initial.slip(b) / b.inverse_mass());
}

TangentialResult tangential_contact(const std::vector<ForceSample>& normal_force, const TangentialBodies& bodies,
                                    const TangentialMotion& initial, const GripLaw& grip) {
  TangentialResult r;
  r.final = initial;
  if (grip.friction == 0) return r;  // no force: nothing changes, bit for bit
  const double inverse_mass = bodies.inverse_mass();
  GripRun run(grip, inverse_mass, initial.slip(bodies));
  for (std::size_t i = 1; i < normal_force.size(); ++i) {
    const ForceSample& p = normal_force[i - 1];
    const ForceSample& q = normal_force[i];
    const double interval = q.t - p.t;
    if (!(interval > 0)) continue;
    if (p.force <= 0 && q.force <= 0) {  // apart: the grip lets go
      run.release();
      continue;
    }
    const double h = interval / substeps_per_interval;
    double n0 = normal_at(p, q, p.t);
    for (int sub = 1; sub <= substeps_per_interval; ++sub) {
      const double n1 = normal_at(p, q, sub == substeps_per_interval ? q.t : p.t + sub * h);
      run.advance(p, q, run.piece(p, q, p.t + (sub - 1) * h, h, n0, n1));
      n0 = n1;
    }
  }
  r.impulse = run.impulse();
  r.friction_loss = run.loss();
  r.slid = run.slid();
  r.final = after_impulse(bodies, initial, r.impulse);
  return r;
}

}  // namespace sweetspot
