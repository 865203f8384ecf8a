#include "sweetspot/contact/tangential_contact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sweetspot {

namespace {

// 1/x with 1/inf = 0: an infinite inertia takes no part.
double inverse(double x) { return std::isinf(x) ? 0.0 : 1 / x; }

// Substeps are cut so that the grip's ringing turns by at most this angle (rad) in one: its
// oscillation is stepped exactly, this resolves the instants where grip turns to slide.
constexpr double max_grip_phase = 0.02;

// The normal force at t in a sample interval, never negative (the Hermite cubic may dip below
// zero between a separation and the next touch, where the force is zero).
double normal_at(const ForceSample& p, const ForceSample& q, double t) {
  if (p.force <= 0 && q.force <= 0) return 0;
  return std::max(0.0, interpolate_force(p, q, t).force);
}

struct Step {
  double impulse;    // on the ball
  double stretch;    // the ball's tangential stretch at the step's end
  double stiffness;  // the grip stiffness that stretch holds its force at
};

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

// One substep of length h from slip s and stretch x, with normal forces n0, n1 at its ends and the
// grip's stiffness k at their mean.
Step grip_step(const GripLaw& grip, double k, double inverse_mass, double s, double x, double n0, double n1, double h) {
  const double limit = grip.friction * 0.5 * (n0 + n1) * h;  // the most impulse sliding can give
  if (std::isinf(grip.grip_stiffness)) {  // rigid grip: bring the slip to rest if friction can, then roll
    const double stop = -s / inverse_mass;
    return {std::abs(stop) <= limit ? stop : std::copysign(limit, stop), 0.0, 0.0};
  }
  const double mass = 1 / inverse_mass;
  double s1 = s - k * x * h * inverse_mass, x1 = x + s * h;  // no stiffness: no force at all
  if (k > 0) {  // the ball's surface as a damped spring, gripping: exact motion over h
    const double w0 = std::sqrt(k * inverse_mass), zeta = grip.damping_ratio;
    const double a = zeta * w0, w = w0 * std::sqrt(1 - zeta * zeta);
    const double decay = std::exp(-a * h), c = std::cos(w * h), sn = std::sin(w * h);
    const double b = (s + a * x) / w;  // x(t) = e^(-at) (x cos wt + b sin wt)
    x1 = decay * (x * c + b * sn);
    s1 = decay * (s * c - (a * b + w * x) * sn);
  }
  const double force = -k * x1 - 2 * grip.damping_ratio * std::sqrt(k * mass) * s1;
  const double bound = grip.friction * n1;
  if (std::abs(force) <= bound) return {(s1 - s) * mass, x1, k};
  // Sliding: the force saturates at mu N in the direction it was loaded; the stretch holds it.
  const double sign = force > 0 ? 1.0 : -1.0;
  const double k1 = grip.stiffness(n1);
  return {sign * limit, k1 > 0 ? -sign * bound / k1 : 0.0, k1};
}

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
  double s = initial.slip(bodies), x = 0, held = 0, j = 0, loss = 0;
  for (std::size_t i = 1; i < normal_force.size(); ++i) {
    const ForceSample& p = normal_force[i - 1];
    const ForceSample& q = normal_force[i];
    const double interval = q.t - p.t;
    if (!(interval > 0)) continue;
    if (p.force <= 0 && q.force <= 0) {  // apart: the grip lets go
      x = 0, held = 0;
      continue;
    }
    const double k_max = grip.stiffness(std::max(p.force, q.force));
    const double turn = std::isinf(k_max) ? 0.0 : std::sqrt(k_max * inverse_mass) * interval;
    const int substeps = std::max(4, static_cast<int>(std::ceil(turn / max_grip_phase)));
    const double h = interval / substeps;
    double n0 = normal_at(p, q, p.t);
    for (int sub = 1; sub <= substeps; ++sub) {
      const double n1 = normal_at(p, q, sub == substeps ? q.t : p.t + sub * h);
      const double k = grip.stiffness(0.5 * (n0 + n1));
      const Step step = grip_step(grip, k, inverse_mass, s, stretch_at(x, held, k), n0, n1, h);
      const double s1 = s + step.impulse * inverse_mass;
      loss -= step.impulse * 0.5 * (s + s1);  // the bodies' energy is quadratic in the impulse
      if (std::abs(step.impulse) >= grip.friction * 0.5 * (n0 + n1) * h && step.impulse != 0) r.slid = true;
      j += step.impulse;
      s = s1;
      x = step.stretch, held = step.stiffness;
      n0 = n1;
    }
  }
  r.impulse = j;
  r.friction_loss = loss;
  r.final = after_impulse(bodies, initial, j);
  return r;
}

}  // namespace sweetspot
