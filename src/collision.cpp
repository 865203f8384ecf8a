#include "sweetspot/collision.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace sweetspot {

namespace {

using Eigen::VectorXd;

constexpr int max_contacts = 50;  // more than this is chatter, not a collision

// The contact phase: ball and modes coupled by the force law, advanced by classical RK4.
// State y = [s, v, a_0..a_{n-1}, a_0'..a_{n-1}'], s the ball's displacement from first touch.
class ContactStepper {
 public:
  ContactStepper(const ModalContact& body, const Ball& ball)
      : body_(body), n_(body.count()), mass_(ball.mass), omega2_(body.omega.array().square()) {
    for (VectorXd* k : {&k1_, &k2_, &k3_, &k4_, &tmp_}) k->resize(2 + 2 * n_);
  }

  double compression(const VectorXd& y) const { return body_.psi.dot(y.segment(2, n_)) - y(0); }
  double compression_rate(const VectorXd& y) const { return body_.psi.dot(y.segment(2 + n_, n_)) - y(1); }

  ForceSample sample(double t, const VectorXd& y, const ContactForce& law) const {
    const double u = compression(y);
    return {t, law(u), law.stiffness(u) * compression_rate(y)};
  }

  void step(const VectorXd& y, double h, const ContactForce& law, VectorXd& out) {
    derivative(y, law, k1_);
    tmp_ = y + (h / 2) * k1_;
    derivative(tmp_, law, k2_);
    tmp_ = y + (h / 2) * k2_;
    derivative(tmp_, law, k3_);
    tmp_ = y + h * k3_;
    derivative(tmp_, law, k4_);
    out = y + (h / 6) * (k1_ + 2 * k2_ + 2 * k3_ + k4_);
  }

  // The step h* in (0, h] at which event(step(y, h*)) crosses zero, given event(y) > 0 and
  // event(out) <= 0 for out = step(y, h). Illinois regula falsi on the step length; leaves in
  // `out` the state just past the event (event <= 0).
  template <class Event>
  double locate(const VectorXd& y, double h, const ContactForce& law, Event event, VectorXd& out) {
    double lo = 0, hi = h, f_lo = event(y), f_hi = event(out);
    int side = 0;
    VectorXd trial(y.size());
    for (int iteration = 0; iteration < 100 && hi - lo > 1e-15 * h; ++iteration) {
      double mid = hi - f_hi * (hi - lo) / (f_hi - f_lo);
      if (!(mid > lo && mid < hi)) mid = (lo + hi) / 2;
      step(y, mid, law, trial);
      const double f = event(trial);
      if (f > 0) {
        lo = mid, f_lo = f;
        if (side == 1) f_hi /= 2;
        side = 1;
      } else {
        hi = mid, f_hi = f, out = trial;
        if (side == -1) f_lo /= 2;
        side = -1;
        if (f == 0) break;
      }
    }
    if (hi == h) step(y, h, law, out);
    return hi;
  }

 private:
  void derivative(const VectorXd& y, const ContactForce& law, VectorXd& dy) const {
    const double force = law(compression(y));
    dy(0) = y(1);
    dy(1) = force / mass_;
    dy.segment(2, n_) = y.segment(2 + n_, n_);
    dy.segment(2 + n_, n_) = -(omega2_ * y.segment(2, n_).array()).matrix() - force * body_.psi;
  }

  const ModalContact& body_;
  int n_;
  double mass_;
  Eigen::ArrayXd omega2_;
  VectorXd k1_, k2_, k3_, k4_, tmp_;
};

// Free flight: the ball coasts, every mode oscillates in closed form (rigid modes drift).
void evolve_free(const ModalContact& body, const VectorXd& y, double tau, VectorXd& out) {
  const int n = body.count();
  out = y;
  out(0) = y(0) + y(1) * tau;
  for (int i = 0; i < n; ++i) {
    const double w = body.omega(i), a = y(2 + i), v = y(2 + n + i);
    if (w == 0) {
      out(2 + i) = a + v * tau;
      continue;
    }
    const double c = std::cos(w * tau), s = std::sin(w * tau);
    out(2 + i) = a * c + v / w * s;
    out(2 + n + i) = -a * w * s + v * c;
  }
}

// Integral over [0, tau] of the cubic Hermite interpolant of F on a segment of length h.
double hermite_integral(const ForceSample& p, const ForceSample& q, double tau) {
  const double h = q.t - p.t, s = tau / h, s2 = s * s, s3 = s2 * s, s4 = s3 * s;
  return h * ((s4 / 2 - s3 + s) * p.force + (s4 / 4 - 2 * s3 / 3 + s2 / 2) * h * p.rate +
              (-s4 / 2 + s3) * q.force + (s4 / 4 - s3 / 3) * h * q.rate);
}

std::string format(const char* pattern, double x, double y) {
  char buf[256];
  std::snprintf(buf, sizeof buf, pattern, x, y);
  return buf;
}

class CollisionRun {
 public:
  CollisionRun(const ModalContact& body, const Ball& ball, double ball_speed, const CollisionOptions& options)
      : body_(body), ball_(ball), options_(options), stepper_(body, ball), y_(2 + 2 * body.count()) {
    y_.setZero();
    y_(1) = -ball_speed;
    y_.tail(body.count()) = body.velocity0;
  }

  Collision run() {
    if (refuse_unstable_step()) return result_;
    while (contact() && free_flight()) {
    }
    finish();
    return result_;
  }

 private:
  bool refuse_unstable_step() {
    const double omega_max = body_.count() ? body_.omega.maxCoeff() : 0.0;
    if (omega_max * options_.dt <= rk4_stability_limit) return false;
    result_.status = CollisionStatus::refused_step;
    result_.message = format("RK4 step dt = %g s is unstable for the fastest kept mode (omega = %.6g rad/s, "
                             "omega*dt must stay below 2.8)",
                             options_.dt, omega_max) +
                      format(": use dt <= %.3g s or keep fewer modes (%.0f kept)", rk4_stability_limit / omega_max,
                             body_.count());
    return true;
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
    samples_.push_back(stepper_.sample(t_, y_, law));
    VectorXd next(y_.size());
    while (true) {
      if (t_ - touch > options_.max_contact_time)
        return fail(CollisionStatus::no_separation,
                    format("the ball did not separate within %g s of touching (contact %g)", options_.max_contact_time,
                           result_.contacts));
      double h = options_.dt;
      stepper_.step(y_, h, law, next);
      if (!next.allFinite())
        return fail(CollisionStatus::non_finite, format("non-finite state at t = %g s (dt = %g s)", t_, h));
      bool separated = false;
      if (!law.expanding() && stepper_.compression_rate(next) <= 0) {
        h = stepper_.locate(y_, h, law, [&](const VectorXd& y) { return stepper_.compression_rate(y); }, next);
        law.start_expansion(stepper_.compression(next));
      } else if (law.expanding() && stepper_.compression(next) <= 0) {
        h = stepper_.locate(y_, h, law, [&](const VectorXd& y) { return stepper_.compression(y); }, next);
        separated = true;
      }
      y_.swap(next);
      t_ += h;
      samples_.push_back(stepper_.sample(t_, y_, law));
      if (separated) break;
    }
    result_.contact_time += t_ - touch;
    result_.u_max = std::max(result_.u_max, law.u_max());
    result_.peak_force = std::max(result_.peak_force, law.f_max());
    result_.impulse += ball_.mass * (y_(1) - v_start);
    result_.dissipated += law.loop_energy();
    if (result_.contacts == 1) result_.first_separation = t_;
    return true;
  }

  // Follows ball and body for the window after a separation. True if they touch again; then the
  // state is moved to the moment of touch.
  bool free_flight() {
    const int n = body_.count();
    const double dt = options_.dt;
    // One exact rotation per mode per sample step: no trigonometry inside the scan.
    Eigen::ArrayXd c(n), s(n);
    for (int i = 0; i < n; ++i) c(i) = std::cos(body_.omega(i) * dt), s(i) = std::sin(body_.omega(i) * dt);
    VectorXd scan = y_, previous;
    for (double tau = dt; tau <= options_.window + 0.5 * dt; tau += dt) {
      previous = scan;
      scan(0) += scan(1) * dt;
      for (int i = 0; i < n; ++i) {
        const double w = body_.omega(i), a = scan(2 + i), v = scan(2 + n + i);
        if (w == 0) {
          scan(2 + i) = a + v * dt;
        } else {
          scan(2 + i) = a * c(i) + v / w * s(i);
          scan(2 + n + i) = -a * w * s(i) + v * c(i);
        }
      }
      if (stepper_.compression(scan) > 0) {
        move_to_touch(tau - dt, tau);
        return true;
      }
    }
    return false;
  }

  // Bisection for the instant of the next touch in (lo, hi] after the separation state y_.
  void move_to_touch(double lo, double hi) {
    VectorXd trial;
    for (int iteration = 0; iteration < 200 && hi - lo > 1e-15 * (t_ + hi); ++iteration) {
      const double mid = (lo + hi) / 2;
      evolve_free(body_, y_, mid, trial);
      (stepper_.compression(trial) > 0 ? hi : lo) = mid;
    }
    evolve_free(body_, y_, hi, trial);
    y_ = trial;
    samples_.push_back({t_ + lo, 0.0, 0.0});  // the force stays zero over the gap
    t_ += hi;
  }

  void finish() {
    const int n = body_.count();
    result_.ball_velocity = y_(1);
    result_.a = y_.segment(2, n);
    result_.a_dot = y_.segment(2 + n, n);
    if (result_.status == CollisionStatus::ok) result_.collision_time = impulse_time(samples_, 0.99);
    if (options_.record_force) result_.force = std::move(samples_);
  }

  const ModalContact& body_;
  Ball ball_;
  CollisionOptions options_;
  ContactStepper stepper_;
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
  }
  return "unknown";
}

double Collision::mode_energy(const ModalContact& body, int n) const {
  return 0.5 * (a_dot(n) * a_dot(n) + body.omega(n) * body.omega(n) * a(n) * a(n));
}

double impulse_time(const std::vector<ForceSample>& force, double fraction) {
  double total = 0;
  for (std::size_t i = 1; i < force.size(); ++i) total += hermite_integral(force[i - 1], force[i], force[i].t - force[i - 1].t);
  const double target = fraction * total;
  double delivered = 0;
  for (std::size_t i = 1; i < force.size(); ++i) {
    const ForceSample &p = force[i - 1], &q = force[i];
    const double segment = hermite_integral(p, q, q.t - p.t);
    if (delivered + segment < target) {
      delivered += segment;
      continue;
    }
    double lo = 0, hi = q.t - p.t;
    for (int iteration = 0; iteration < 100; ++iteration) {
      const double mid = (lo + hi) / 2;
      (delivered + hermite_integral(p, q, mid) < target ? lo : hi) = mid;
    }
    return p.t + (lo + hi) / 2;
  }
  return force.empty() ? 0.0 : force.back().t;
}

Collision collide(const ModalContact& body, const Ball& ball, double ball_speed, const CollisionOptions& options) {
  return CollisionRun(body, ball, ball_speed, options).run();
}

}  // namespace sweetspot
