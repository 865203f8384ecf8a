#pragma once
// Internal: classical RK4 at a fixed step (N2000). Stable only while omega_max dt < 2.8.
#include <cstdio>
#include <string>

#include "contact/contact_state.hpp"

namespace sweetspot::detail {

class Rk4Stepper {
 public:
  Rk4Stepper(const ContactState& state, const CollisionOptions& options)
      : state_(state), options_(options), dt_(options.dt) {
    for (Eigen::VectorXd* k : {&k1_, &k2_, &k3_, &k4_, &tmp_}) k->resize(state.size());
  }

  double first_step() const { return dt_; }

  // Why the options cannot be integrated, or empty.
  std::string refusal() const {
    const double omega_max = state_.modes() ? state_.body().omega.maxCoeff() : 0.0;
    if (omega_max * dt_ <= rk4_stability_limit) return {};
    char text[320];
    std::snprintf(text, sizeof text,
                  "RK4 step dt = %g s is unstable for the fastest kept mode (omega = %.6g rad/s, omega*dt must "
                  "stay below 2.8): use dt <= %.3g s, keep fewer modes (%d kept) or another integrator",
                  dt_, omega_max, rk4_stability_limit / omega_max, state_.modes());
    return text;
  }

  StepOutcome attempt(const Eigen::VectorXd& y, double h, const ContactForce& law, Eigen::VectorXd& out) {
    step(y, h, law, out);
    if (too_stiff_at_end(state_, out, h, law, options_)) return {false, h / 2};
    return {true, dt_};
  }

  double locate(const Eigen::VectorXd& y, double h, const ContactForce& law, ContactEvent event,
                Eigen::VectorXd& out) {
    return locate_by_restepping(*this, state_, y, h, law, event, out);
  }

  void forget_step() {}  // a step leaves nothing for the next
  void step(const Eigen::VectorXd& y, double h, const ContactForce& law, Eigen::VectorXd& out) {
    state_.derivative(y, law, k1_);
    tmp_ = y + (h / 2) * k1_;
    state_.derivative(tmp_, law, k2_);
    tmp_ = y + (h / 2) * k2_;
    state_.derivative(tmp_, law, k3_);
    tmp_ = y + h * k3_;
    state_.derivative(tmp_, law, k4_);
    out = y + (h / 6) * (k1_ + 2 * k2_ + 2 * k3_ + k4_);
  }

 private:
  const ContactState& state_;
  CollisionOptions options_;
  double dt_;
  Eigen::VectorXd k1_, k2_, k3_, k4_, tmp_;
};

}  // namespace sweetspot::detail
