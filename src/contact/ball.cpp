#include "sweetspot/contact/ball.hpp"

#include <cmath>

namespace sweetspot {

double ContactForce::operator()(double u) const {
  if (u <= 0) return 0;  // also guards round-off: no tension, no pow of a negative number
  if (u == last_u_) return last_force_;
  last_u_ = u;
  last_force_ = expanding_ ? f_max_ * std::pow(u / u_max_, b_) : ball_.k1 * std::pow(u, ball_.a);
  return last_force_;
}

double ContactForce::stiffness(double u) const {
  if (u == 0 && !expanding_ && ball_.a == 1) return ball_.k1;
  if (u <= 0) return 0;
  return exponent() * (*this)(u) / u;
}

double ContactForce::compression_at(double force) const {
  return expanding_ ? u_max_ * std::pow(force / f_max_, 1 / b_) : std::pow(force / ball_.k1, 1 / ball_.a);
}

void ContactForce::start_expansion(double u_max) {
  last_u_ = -1;  // the branch changes
  u_max_ = u_max;
  f_max_ = ball_.k1 * std::pow(u_max, ball_.a);
  if (ball_.speed_dependent()) {
    const double stored = f_max_ * u_max / (ball_.a + 1);
    const double e = ball_.cor_at(ball_.wall_speed_storing(stored));
    b_ = (1 + ball_.a) / (e * e) - 1;
  }
  expanding_ = true;
}

void ContactForce::resume_compression() {
  last_u_ = -1;  // the branch changes
  expanding_ = false;
}

double ContactForce::loop_energy() const {
  return f_max_ * u_max_ * (1 / (ball_.a + 1) - 1 / (b_ + 1));
}

}  // namespace sweetspot
