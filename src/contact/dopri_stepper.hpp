#pragma once
// Internal: adaptive Dormand-Prince 5(4), the reference-quality path. The local error of the
// fifth-order solution is estimated by the embedded fourth-order one and kept below the
// tolerance, relative to each component's scale; events are located inside accepted steps by
// re-stepping. Explicit, so the fastest kept mode still bounds the step (omega h < about 3.3).
#include <algorithm>
#include <cmath>
#include <string>

#include "contact/contact_state.hpp"

namespace sweetspot::detail {

class DopriStepper {
 public:
  DopriStepper(const ContactState& state, const CollisionOptions& options, double ball_speed)
      : state_(state), tolerance_(options.tolerance), h0_(options.dt) {
    for (Eigen::VectorXd* k : {&k1_, &k2_, &k3_, &k4_, &k5_, &k6_, &k7_, &tmp_, &error_}) k->resize(state.size());
    // Absolute scales: velocities ~ the approach speed, displacements ~ that speed over 1 ms.
    const int n = state.modes();
    const double v = std::max(std::abs(ball_speed), 1e-3);
    scale_ = Eigen::VectorXd::Constant(state.size(), v * 1e-3);
    scale_(1) = v;
    scale_.segment(2 + n, n).setConstant(v);
    // The damping's dissipated energy, on the scale of the ball's kinetic energy.
    if (const int k = state.dissipated_index(); k >= 0) scale_(k) = 0.5 * state.ball_mass() * v * v;
  }

  double first_step() const { return h0_; }
  std::string refusal() const { return {}; }

  StepOutcome attempt(const Eigen::VectorXd& y, double h, const ContactForce& law, Eigen::VectorXd& out) {
    step(y, h, law, out);
    error_ = h * (e1 * k1_ + e3 * k3_ + e4 * k4_ + e5 * k5_ + e6 * k6_ + e7 * k7_);
    double sum = 0;
    for (int i = 0; i < y.size(); ++i) {
      const double scale = tolerance_ * (scale_(i) + std::max(std::abs(y(i)), std::abs(out(i))));
      sum += (error_(i) / scale) * (error_(i) / scale);
    }
    const double norm = std::sqrt(sum / y.size());
    const double factor = norm == 0 ? 5.0 : std::clamp(0.9 * std::pow(norm, -0.2), 0.2, 5.0);
    return {norm <= 1, h * factor};
  }

  double locate(const Eigen::VectorXd& y, double h, const ContactForce& law, ContactEvent event,
                Eigen::VectorXd& out) {
    return locate_by_restepping(*this, state_, y, h, law, event, out);
  }

  void forget_step() {}  // a step leaves nothing for the next
  void step(const Eigen::VectorXd& y, double h, const ContactForce& law, Eigen::VectorXd& out) {
    state_.derivative(y, law, k1_);
    tmp_ = y + h * (a21 * k1_);
    state_.derivative(tmp_, law, k2_);
    tmp_ = y + h * (a31 * k1_ + a32 * k2_);
    state_.derivative(tmp_, law, k3_);
    tmp_ = y + h * (a41 * k1_ + a42 * k2_ + a43 * k3_);
    state_.derivative(tmp_, law, k4_);
    tmp_ = y + h * (a51 * k1_ + a52 * k2_ + a53 * k3_ + a54 * k4_);
    state_.derivative(tmp_, law, k5_);
    tmp_ = y + h * (a61 * k1_ + a62 * k2_ + a63 * k3_ + a64 * k4_ + a65 * k5_);
    state_.derivative(tmp_, law, k6_);
    out = y + h * (b1 * k1_ + b3 * k3_ + b4 * k4_ + b5 * k5_ + b6 * k6_);
    state_.derivative(out, law, k7_);
  }

 private:
  static constexpr double a21 = 1.0 / 5, a31 = 3.0 / 40, a32 = 9.0 / 40, a41 = 44.0 / 45, a42 = -56.0 / 15,
                          a43 = 32.0 / 9, a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                          a54 = -212.0 / 729, a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247,
                          a64 = 49.0 / 176, a65 = -5103.0 / 18656;
  static constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
  // Fifth- minus fourth-order weights: the error estimate.
  static constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                          e6 = 22.0 / 525, e7 = -1.0 / 40;

  const ContactState& state_;
  double tolerance_, h0_;
  Eigen::VectorXd scale_;
  Eigen::VectorXd k1_, k2_, k3_, k4_, k5_, k6_, k7_, tmp_, error_;
};

}  // namespace sweetspot::detail
