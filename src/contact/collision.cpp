#include "sweetspot/contact/collision.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "contact/contact_state.hpp"
#include "contact/damped_mode.hpp"
#include "contact/dopri_stepper.hpp"
#include "contact/exact_stepper.hpp"
#include "contact/thread_memory.hpp"
#include "contact/rigid_collision.hpp"
#include "contact/rk4_stepper.hpp"
#include "sweetspot/input_error.hpp"

namespace sweetspot {

namespace {

using Eigen::VectorXd;
using detail::ContactState;

constexpr int max_contacts = 50;  // more than this is chatter, not a collision

// Mode i's coordinate and rate a time tau after the state y, free of force: a rigid mode drifts,
// a damped one decays, an undamped one turns.
struct ModeState {
  double a, v;
};
ModeState free_mode(const ModalContact& body, const VectorXd& y, int i, double tau) {
  const int n = body.count();
  const double w = body.omega(i), a = y(2 + i), v = y(2 + n + i);
  if (w == 0) return {a + v * tau, v};
  if (const double zeta = body.damping(i); zeta != 0) {
    const detail::FreeEvolution e = detail::damped_free_evolution(w, zeta, tau);
    return {e.aa * a + e.av * v, e.va * a + e.vv * v};
  }
  const double c = std::cos(w * tau), s = std::sin(w * tau);
  return {a * c + v / w * s, -a * w * s + v * c};
}

// Free flight: the ball coasts and every mode moves free of force; what the damped ones lose is
// added to the dissipated energy, y's last entry.
void evolve_free(const ModalContact& body, const VectorXd& y, double tau, VectorXd& out) {
  const int n = body.count();
  out = y;
  out(0) = y(0) + y(1) * tau;
  for (int i = 0; i < n; ++i) {
    const ModeState m = free_mode(body, y, i, tau);
    out(2 + i) = m.a, out(2 + n + i) = m.v;
    if (body.damping(i) != 0 && out.size() > 2 + 2 * n)
      out(2 + 2 * n) += detail::free_decay_loss(body.omega(i), y(2 + i), y(2 + n + i), m.a, m.v);
  }
}

// The compression a time tau after the state y, free of force (evolve_free's, without the state).
double free_compression(const ModalContact& body, const VectorXd& y, double tau) {
  double u = -(y(0) + y(1) * tau);
  for (int i = 0; i < body.count(); ++i) u += body.psi(i) * free_mode(body, y, i, tau).a;
  return u;
}

// The time u + rate t + max_acceleration t^2 / 2 takes to rise from u < 0 to 0 (0 unless u < 0).
double time_to_reach(double u, double rate, double max_acceleration) {
  if (!(u < 0)) return 0;
  if (!(max_acceleration > 0)) return rate > 0 ? -u / rate : std::numeric_limits<double>::infinity();
  // The positive root, in the form without cancellation for the sign of the rate.
  const double root = std::sqrt(rate * rate - 2 * max_acceleration * u);
  return rate <= 0 ? (root - rate) / max_acceleration : -2 * u / (rate + root);
}

// Integral over [0, tau] of the cubic Hermite interpolant of F on a segment of length h.
double hermite_integral(const ForceSample& p, const ForceSample& q, double tau) {
  if (q.t <= p.t) return 0;  // a touch found right at separation leaves two samples at one time
  const double h = q.t - p.t, s = tau / h, s2 = s * s, s3 = s2 * s, s4 = s3 * s;
  return h * ((s4 / 2 - s3 + s) * p.force + (s4 / 4 - 2 * s3 / 3 + s2 / 2) * h * p.rate +
              (-s4 / 2 + s3) * q.force + (s4 / 4 - s3 / 3) * h * q.rate);
}

std::string format(const char* pattern, double x, double y) {
  char buf[256];
  std::snprintf(buf, sizeof buf, pattern, x, y);
  return buf;
}

// Free rotations of every mode over 1 us, 2 us, 4 us, ... 8 ms: the free-flight search jumps
// by these. The same for every impact that keeps the same modes, so each thread keeps them, all
// of a set's in one table (a set is new at nearly every impact with modes = auto: one allocation,
// not one per power and coefficient). a -> c a + sn v, a' -> cv a' - w2sn a; cv = c but for damped
// modes (damped_mode.hpp).
struct FreeRotations {
  static constexpr double base_step = 1e-6;
  static constexpr int powers = 14;  // 1 us, 2 us, ... 8.192 ms
  static constexpr int columns = 4;  // c, sn, w2sn, cv
  struct Power {
    double step;
    Eigen::Map<const Eigen::ArrayXd> c, sn, w2sn, cv;
  };
  Eigen::ArrayXd omega, damping;
  Eigen::ArrayXXd table;  // column columns k + j: power k's coefficient j, one row per mode

  static double step(int k) { return base_step * std::exp2(k); }
  // The longest rotation not longer than `jump` (the shortest when none is).
  Power largest_within(double jump) const {
    int k = 0;
    while (k + 1 < powers && step(k + 1) <= jump) ++k;
    const auto column = [&](int j) {
      return Eigen::Map<const Eigen::ArrayXd>(table.col(columns * k + j).data(), table.rows());
    };
    return {step(k), column(0), column(1), column(2), column(3)};
  }
};

// One mode's rotations over each of the powers' steps. A thread keeps them by frequency and
// damping: `auto` keeps a different set of a bat's modes at nearly every impact, so a set's
// rotations are mostly new while each mode's are not (a sine and cosine per power and mode).
struct ModeRotations {
  double c[FreeRotations::powers], sn[FreeRotations::powers], w2sn[FreeRotations::powers], cv[FreeRotations::powers];
};

ModeRotations rotations_of(double w, double zeta) {
  ModeRotations m;
  for (int k = 0; k < FreeRotations::powers; ++k) {
    const double step = FreeRotations::step(k);
    if (zeta != 0) {  // damped_mode.hpp
      const detail::FreeEvolution e = detail::damped_free_evolution(w, zeta, step);
      m.c[k] = e.aa, m.sn[k] = e.av, m.w2sn[k] = -e.va, m.cv[k] = e.vv;
      continue;
    }
    const double sine = std::sin(w * step), cosine = std::cos(w * step);
    m.c[k] = m.cv[k] = cosine;
    m.sn[k] = w == 0 ? step : sine / w;
    m.w2sn[k] = w * sine;
  }
  return m;
}

const ModeRotations& mode_rotations(double w, double zeta) {
  struct Key {
    double w, zeta;
    bool operator==(const Key&) const = default;
  };
  struct Hash {
    std::size_t operator()(const Key& k) const { return detail::bits_hash(k.w, k.zeta); }
  };
  thread_local detail::ThreadMemory<Key, ModeRotations, Hash> memory(4096);  // about 4 MB per thread
  return memory.get(Key{w, zeta}, [&] { return rotations_of(w, zeta); });
}

const FreeRotations& free_rotations(const ModalContact& body) {
  const VectorXd& omega = body.omega;
  const Eigen::ArrayXd damping = body.damped() ? Eigen::ArrayXd(body.damping_ratio.array()) : Eigen::ArrayXd();
  const std::size_t key = detail::hash_range(detail::hash_range(omega.size(), omega), damping);
  thread_local std::unordered_multimap<std::size_t, FreeRotations> cache;
  thread_local std::size_t stored = 0;
  const auto [first, last] = cache.equal_range(key);
  for (auto it = first; it != last; ++it)
    if (it->second.omega.size() == omega.size() && (it->second.omega == omega.array()).all() &&
        it->second.damping.size() == damping.size() && (it->second.damping == damping).all())
      return it->second;
  if (stored > 400'000) cache.clear(), stored = 0;  // doubles held: about 3 MB per thread at most
  const int n = body.count();
  FreeRotations r;
  r.omega = omega.array();
  r.damping = damping;
  r.table.resize(n, FreeRotations::columns * FreeRotations::powers);
  for (int i = 0; i < n; ++i) {
    const ModeRotations& m = mode_rotations(omega(i), body.damping(i));
    for (int k = 0; k < FreeRotations::powers; ++k) {
      double* power = r.table.col(FreeRotations::columns * k).data();  // its columns follow, n apart
      power[i] = m.c[k], power[n + i] = m.sn[k], power[2 * n + i] = m.w2sn[k], power[3 * n + i] = m.cv[k];
    }
  }
  stored += r.table.size();
  return cache.emplace(key, std::move(r))->second;
}

template <class Stepper>
class CollisionRun {
 public:
  CollisionRun(const ModalContact& body, const Ball& ball, double ball_speed, const CollisionOptions& options)
      : body_(body), ball_(ball), options_(options), state_(body, ball, options.damping_loss),
        stepper_(make_stepper(ball_speed)), y_(state_.size()) {
    y_.setZero();
    y_(1) = -ball_speed;
    if (keeps_samples()) samples_.reserve(256);  // a contact's steps, mostly, without reallocation
    y_.segment(2 + body.count(), body.count()) = body.velocity0;
  }

  Collision run() {
    if (const std::string why = stepper_.refusal(); !why.empty()) {
      result_.status = CollisionStatus::refused_step;
      result_.message = why;
      return result_;
    }
    if (never_approach()) return no_contact(state_.compression_rate(y_));
    while (contact() && free_flight()) {
      if (options_.stop_when_caught_again) {
        ++result_.contacts;  // the one that has just begun
        break;
      }
    }
    finish();
    return std::move(result_);  // run once: the result is the run's last use of it
  }

 private:
  Stepper make_stepper(double ball_speed) {
    if constexpr (std::is_same_v<Stepper, detail::DopriStepper>) return Stepper(state_, options_, ball_speed);
    else return Stepper(state_, options_);
  }

  // Ball and body move apart (or together at the same speed) at first touch: they never meet.
  // The struck point's speed is a sum over the modes, exact only to round-off: a closing speed
  // within that of zero is zero.
  bool never_approach() const {
    const double bat = body_.psi.dot(body_.velocity0), ball = -y_(1);
    return !(bat + ball > 1e-12 * (std::abs(bat) + std::abs(ball)));
  }

  Collision no_contact(double closing) {
    const double nan = std::nan("");
    result_.status = CollisionStatus::no_contact;
    char text[120];
    std::snprintf(text, sizeof text, "ball and bat never approach: closing speed %g m/s at the impact point", closing);
    result_.message = text;
    result_.ball_velocity = result_.contact_time = result_.collision_time = nan;
    result_.u_max = result_.peak_force = result_.impulse = result_.dissipated = result_.damping_dissipated = nan;
    return result_;
  }

  bool fail(CollisionStatus status, std::string message) {
    result_.status = status;
    result_.message = std::move(message);
    return false;
  }

  // One contact from first touch (u = 0) to separation. False if it fails.
  bool contact() {
    if (++result_.contacts > max_contacts)
      return fail(CollisionStatus::no_separation, "more than 50 contacts: the ball chatters on the bat");
    ContactForce law(ball_);
    const double touch = t_;
    const double v_start = y_(1);
    record_sample(law);
    VectorXd next(y_.size());
    double h = stepper_.first_step();
    bool rising = state_.compression_rate(y_) > 0;  // at the last step's end
    for (double steps = 1;; ++steps) {
      h = stiffness_limited(h, law);
      if (steps > max_contact_steps)
        return fail(CollisionStatus::failed, "more than 1e7 steps (max_contact_steps) in contact " +
                                                 std::to_string(result_.contacts) +
                                                 ": the step or the tolerance is too fine");
      if (t_ - touch > options_.max_contact_time) return overran();
      // The step's start: the last step's end, whose u and u' its stepper left known (no pass).
      const double u_start = state_.compression(y_), du_start = state_.compression_rate(y_);
      const detail::StepOutcome outcome = stepper_.attempt(y_, h, law, next);
      if (!outcome.accepted && outcome.next_h > 0) {  // a NaN proposal (from a NaN state) fails below
        h = outcome.next_h;
        continue;
      }
      // u and u' sum every mode, so a non-finite one shows there without a pass of its own.
      const double du_end = state_.compression_rate(next);
      if (!std::isfinite(next(0) + next(1) + state_.compression(next) + du_end))
        return fail(CollisionStatus::non_finite, format("non-finite state at t = %g s (step %g s)", t_, h));
      bool separated = false;
      bool located = true;  // an event's step ends at the event, no longer at `next` as stepped
      if (!law.expanding() && du_end <= 0) {
        h = stepper_.locate(y_, h, law, detail::ContactEvent::max_compression, next);
        const double u_max = state_.ball_compression(state_.compression(next), law);
        // A graze that never compressed the ball is over (and F_m = k1 u_m^a needs u_m > 0).
        if (u_max > 0) law.start_expansion(u_max);
        else separated = true;
      } else if (law.expanding() &&
                 (state_.compression(next) <= 0 || parts_within(h, law, u_start, du_start, next))) {
        h = stepper_.locate(y_, h, law, detail::ContactEvent::separation, next);
        separated = state_.compression(next) <= 0;  // else the root was early: the contact goes on
      } else if (law.expanding() && reloads(h, law, u_start, du_start, next)) {
        h = stepper_.locate(y_, h, law, detail::ContactEvent::reloading, next);
        law.resume_compression();
      } else {
        located = false;
      }
      // Whether the force still rises at the step's end: a force maximum where it stops.
      const bool rises = (located ? state_.compression_rate(next) : du_end) > 0;
      y_.swap(next);
      t_ += h;
      if (rising && !rises) ++result_.force_peaks;
      rising = rises;
      record_sample(law);
      if (separated) break;
      h = outcome.next_h;
    }
    // An adaptive step may pass the limit and find the separation inside it: as long a contact.
    if (t_ - touch > options_.max_contact_time) return overran();
    result_.contact_time += t_ - touch;
    result_.u_max = std::max(result_.u_max, law.u_max());
    result_.peak_force = std::max(result_.peak_force, law.f_max());
    result_.impulse += ball_.mass * (y_(1) - v_start);
    result_.dissipated += law.loop_energy();
    return true;
  }

  // A contact longer than max_contact_time is reported as one that did not separate.
  bool overran() {
    return fail(CollisionStatus::no_separation, format("the ball did not separate within %g s of touching (contact %g)",
                                                       options_.max_contact_time, result_.contacts));
  }

  // Whether the expanding ball is pressed past its maximum compression again within the step from
  // y_ (compression u0, rate du0) to `next`, of length h. The bat's ringing can press it there for
  // a few us only, inside a step whose ends both lie below. Missing such a reload loses its
  // hysteresis loop: up to 2e-4 of v_f at 150 m/s near the handle, at steps of 14 us.
  bool reloads(double& h, const ContactForce& law, double u0, double du0, VectorXd& next) {
    const double level = detail::reloading_compression(state_, law);
    return state_.compression(next) > level || turns_past(h, law, u0, du0, next, level, true);
  }

  // Whether the expanding ball leaves the bat and is struck again within the step, though both
  // ends of the step find it touching. On a nearly dead ball's expansion branch (F ~ u^b, b = 17
  // at e0 = 0.4) the force is all but nil long before u reaches 0, and the bat's ringing can carry
  // the struck point away and back within one step. Missed, the ball stays on that branch, whose
  // force at the new compression is nil, where a new contact compresses it afresh: 4.3e-3 of v_f
  // at the torpedo's tip (83.5 cm, 42 m/s, e0 0.4) at steps of 20 us.
  bool parts_within(double& h, const ContactForce& law, double u0, double du0, VectorXd& next) {
    return turns_past(h, law, u0, du0, next, 0.0, false);
  }

  // Whether u passes `level` inside the step from y_ (compression u0, rate du0) to `next`, of
  // length h, though its end does not: rising at the step's start and falling at its end through a
  // peak above the level (rising), or falling and then rising through a trough below it. The
  // cubic Hermite of u through both ends says where it turns; the step is made again to there, and
  // if that state lies past the level, h and `next` become that step, which then ends past the
  // event (as locate expects them).
  bool turns_past(double& h, const ContactForce& law, double u0, double du0, VectorXd& next, double level,
                  bool rising) {
    const double sign = rising ? 1.0 : -1.0;
    const double u1 = state_.compression(next), du1 = state_.compression_rate(next);
    const std::optional<double> turn =
        detail::hermite_peak(sign * u0, sign * (h * du0), sign * u1, sign * (h * du1), sign * level);
    if (!turn) return false;
    VectorXd turned(y_.size());
    stepper_.step(y_, *turn * h, law, turned);
    if (!(sign * state_.compression(turned) > sign * level)) {  // the cubic overshot: as if not tried
      stepper_.forget_step();
      return false;
    }
    h *= *turn;
    next.swap(turned);
    return true;
  }

  // The fixed-step methods must also resolve the contact's own ringing (contact_frequency): a
  // nearly dead ball is so stiff on the expansion branch that a step fit for the modes would
  // blow up. Such steps are halved until omega_c h <= contact_phase_limit (2, or less for a
  // stated accuracy; powers of two, so the exact stepper's responses are reused), here at the
  // start and by the steppers at the end; the adaptive method finds its own.
  double stiffness_limited(double h, const ContactForce& law) const {
    if constexpr (std::is_same_v<Stepper, detail::DopriStepper>) return h;
    const double omega_c = state_.contact_frequency(y_, law);
    while (omega_c * h > options_.contact_phase_limit && h > detail::smallest_step) h /= 2;
    return h;
  }

  // Follows ball and body for the window after a separation. True if they touch again; then the
  // state is moved to the moment of touch. The compression is the rigid part, linear in time,
  // plus vibrations bounded by sum |psi_n| A_n (amplitude A_n), changing no faster than
  // sum |psi_n| omega_n A_n and accelerating no faster than M = sum |psi_n| omega_n^2 A_n (1 + 2
  // zeta_n): from a sample's u < 0 and u', the ball cannot touch within the larger of -u over the
  // speed bound and the time u + u' t + M t^2 / 2 takes to reach 0. Samples skip ahead that far,
  // and the scan ends once the rigid part alone keeps the ball clear.
  bool free_flight() {
    double u0_rigid = -y_(0), rate_rigid = -y_(1), bound = 0, speed_bound = 0, acceleration_bound = 0;
    for (int i = 0; i < body_.count(); ++i) {
      const double w = body_.omega(i), psi = body_.psi(i), a = y_(2 + i), v = y_(2 + body_.count() + i);
      if (w == 0) {
        u0_rigid += psi * a, rate_rigid += psi * v;
      } else {
        const double amplitude = std::sqrt(a * a + v / w * (v / w));  // not hypot: no overflow here, and 5x cheaper
        bound += std::abs(psi) * amplitude;
        speed_bound += std::abs(psi) * w * amplitude;
        acceleration_bound += std::abs(psi) * w * w * amplitude * (1 + 2 * body_.damping(i));
      }
    }
    double end = options_.window;
    if (rate_rigid < 0) end = std::min(end, (u0_rigid + bound) / -rate_rigid);
    const double slope = std::abs(rate_rigid) + speed_bound;
    // Where the bounds allow only tiny jumps (a grazing approach), sample at least every 1 us:
    // a touch shorter than that may pass unseen. Jumps are whole powers of two of that, whose
    // rotations are kept, so a sample costs a few products per mode and no trigonometry.
    const FreeRotations& rotations = free_rotations(body_);
    const int n = body_.count();
    Eigen::ArrayXd a = y_.segment(2, n).array(), v = y_.segment(2 + n, n).array(), next_a(n);
    const auto psi = body_.psi.array();
    double s = y_(0), tau = 0, previous = 0, u_previous = 0;
    while (tau < end) {
      const double u = (psi * a).sum() - s;
      // At tau = 0 the ball has just been found to separate: the step to that root may leave a
      // trace of compression (1e-12 m), which is this contact ending, not the next one starting.
      if (u > 0 && tau > 0) {
        move_to_touch(previous, tau, u_previous, u);
        return true;
      }
      previous = tau, u_previous = u;
      const double clear = std::max(-u / slope, time_to_reach(u, (psi * v).sum() - y_(1), acceleration_bound));
      const FreeRotations::Power r = rotations.largest_within(std::max(clear, FreeRotations::base_step));
      next_a = r.c * a + r.sn * v;
      v = r.cv * v - r.w2sn * a;
      a.swap(next_a);
      s += y_(1) * r.step;
      tau += r.step;
    }
    return false;
  }

  // The instant of the next touch in (lo, hi] after the separation state y_, where the compression
  // rises through 0: detail::falling_root on -u, each evaluation a sine and cosine per mode. The
  // compressions at the ends come with them; the state moves to the end inside the contact, hi.
  void move_to_touch(double lo, double hi, double u_lo, double u_hi) {
    const auto clearance = [&](double tau) { return -free_compression(body_, y_, tau); };
    const detail::Bracket touch = detail::falling_root(
        clearance, lo, hi, -u_lo, -u_hi, [&](double a, double b) { return b - a <= 1e-15 * (t_ + b); }, 200);
    VectorXd trial;
    evolve_free(body_, y_, touch.hi, trial);
    y_ = trial;
    if (keeps_samples()) samples_.push_back({t_ + touch.lo, 0.0, 0.0});  // the force stays zero over the gap
    t_ += touch.hi;
  }

  // The force samples serve the collision time and the recorded profile: nothing else.
  bool keeps_samples() const { return options_.record_force || options_.find_collision_time; }
  void record_sample(const ContactForce& law) {
    if (keeps_samples()) samples_.push_back(state_.sample(t_, y_, law));
  }

  void finish() {
    const int n = body_.count();
    result_.ball_velocity = y_(1);
    result_.a = y_.segment(2, n);
    result_.a_dot = y_.segment(2 + n, n);
    if (const int k = state_.dissipated_index(); k >= 0) result_.damping_dissipated = y_(k);
    else if (body_.damped()) result_.damping_dissipated = std::nan("");  // not asked
    if (!options_.find_collision_time) result_.collision_time = std::nan("");
    else if (result_.status == CollisionStatus::ok) result_.collision_time = impulse_time(samples_, collision_time_fraction);
    if (options_.record_force) result_.force = std::move(samples_);
  }

  const ModalContact& body_;
  Ball ball_;
  CollisionOptions options_;
  ContactState state_;
  Stepper stepper_;
  VectorXd y_;
  double t_ = 0;
  std::vector<ForceSample> samples_;
  Collision result_;
};

}  // namespace

const char* to_string(CollisionStatus status) {
  switch (status) {
    case CollisionStatus::ok: return "ok";
    case CollisionStatus::no_separation: return "no_separation";
    case CollisionStatus::non_finite: return "non_finite";
    case CollisionStatus::refused_step: return "refused_step";
    case CollisionStatus::unbalanced: return "unbalanced";
    case CollisionStatus::no_contact: return "no_contact";
    case CollisionStatus::failed: return "failed";
    case CollisionStatus::inaccurate: return "inaccurate";
  }
  return "unknown";
}

double Collision::mode_energy(const ModalContact& body, int n) const {
  return 0.5 * (a_dot(n) * a_dot(n) + body.omega(n) * body.omega(n) * a(n) * a(n));
}

ForceSample interpolate_force(const ForceSample& p, const ForceSample& q, double t) {
  const double h = q.t - p.t, s = (t - p.t) / h, s2 = s * s, s3 = s2 * s;
  const double value = (2 * s3 - 3 * s2 + 1) * p.force + (s3 - 2 * s2 + s) * h * p.rate +
                       (-2 * s3 + 3 * s2) * q.force + (s3 - s2) * h * q.rate;
  const double rate = ((6 * s2 - 6 * s) * p.force + (3 * s2 - 4 * s + 1) * h * p.rate +
                       (-6 * s2 + 6 * s) * q.force + (3 * s2 - 2 * s) * h * q.rate) /
                      h;
  return {t, value, rate};
}

double impulse_time(const std::vector<ForceSample>& force, double fraction) {
  double total = 0;
  for (std::size_t i = 1; i < force.size(); ++i) total += hermite_integral(force[i - 1], force[i], force[i].t - force[i - 1].t);
  const double target = fraction * total;
  double delivered = 0;
  for (std::size_t i = 1; i < force.size(); ++i) {
    const ForceSample &p = force[i - 1], &q = force[i];
    const double segment = hermite_integral(p, q, q.t - p.t);
    if (delivered + segment < target || q.t <= p.t) {
      delivered += segment;
      continue;
    }
    // The impulse is a quartic in time over the segment, its slope the force: Newton, kept
    // inside the bracket by bisection where the interpolant's force dips to zero or below.
    const double h = q.t - p.t;
    double lo = 0, hi = h, tau = segment > 0 ? (target - delivered) / segment * h : h / 2;
    for (int iteration = 0; iteration < 100 && hi - lo > 1e-15 * h; ++iteration) {
      const double excess = delivered + hermite_integral(p, q, tau) - target;
      (excess < 0 ? lo : hi) = tau;
      const double rate = interpolate_force(p, q, p.t + tau).force, step = rate > 0 ? excess / rate : 0.0;
      double next = tau - step;
      if (!(next > lo && next < hi) || rate <= 0) next = (lo + hi) / 2;
      if (std::abs(step) <= 1e-15 * h && rate > 0) return p.t + next;
      tau = next;
    }
    return p.t + tau;
  }
  return force.empty() ? 0.0 : force.back().t;
}

Collision collide(const ModalContact& body, const Ball& ball, double ball_speed, const CollisionOptions& options) {
  Collision c;
  switch (options.method) {
    case Method::exact: {
      std::optional<Collision> rigid;
      if (options.rigid_closed_form) rigid = detail::rigid_collision(body, ball, ball_speed, options);
      c = rigid ? std::move(*rigid) : CollisionRun<detail::ExactStepper>(body, ball, ball_speed, options).run();
      break;
    }
    case Method::dopri: return CollisionRun<detail::DopriStepper>(body, ball, ball_speed, options).run();
    case Method::rk4: c = CollisionRun<detail::Rk4Stepper>(body, ball, ball_speed, options).run(); break;
  }
  c.step = options.dt;
  return c;
}

const char* to_string(Method method) {
  switch (method) {
    case Method::rk4: return "rk4";
    case Method::exact: return "exact";
    case Method::dopri: return "dopri";
  }
  return "unknown";
}

double default_step(Method method) {
  switch (method) {
    case Method::exact: return 1e-5;
    case Method::dopri: return 1e-6;
    case Method::rk4: break;
  }
  return 5e-6;
}

Method parse_method(const std::string& text) {
  if (text == "rk4") return Method::rk4;
  if (text == "exact") return Method::exact;
  if (text == "dopri") return Method::dopri;
  throw InputError("integrator '" + text + "': expected 'rk4', 'exact' or 'dopri'");
}

}  // namespace sweetspot
