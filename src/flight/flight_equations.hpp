#pragma once
// Internal: the batted ball's equations of motion. State (x, y, z, vx, vy, vz, omega): position
// and velocity in the frame of flight.hpp, and the spin rate about a fixed axis.
//   dv/dt = -g z^ - K C_D |u| u + K C_L |u|^2 (w^ x u^)_perp,   u = v - wind,  K = rho A / (2 m)
//   domega/dt = -omega |u| / (tau v_ref)
// The lift is perpendicular to both the spin axis and the air velocity, along w x u; C_D and the
// spin factor S = R omega_perp / |u| use the spin's part perpendicular to u (the calculator's
// w_perp), which is all of it at launch and less once the path has turned.
#include <array>
#include <cmath>
#include <numbers>

#include "sweetspot/flight/flight.hpp"

namespace sweetspot::detail {

using FlightState = std::array<double, 7>;
using Vector3 = std::array<double, 3>;

inline Vector3 cross(const Vector3& a, const Vector3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline double norm(const Vector3& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

class FlightEquations {
 public:
  FlightEquations(const Vector3& spin_axis, const Vector3& wind, double air_density, const FlightOptions& options)
      : axis_(spin_axis), wind_(wind), options_(options) {
    const double area = std::numbers::pi * options.ball.radius * options.ball.radius;
    k_ = air_density * area / (2 * options.ball.mass);
  }

  void operator()(const FlightState& s, FlightState& ds, double /*t*/) const {
    const Vector3 u{s[3] - wind_[0], s[4] - wind_[1], s[5] - wind_[2]};
    const double speed = norm(u);
    Vector3 a{0, 0, -options_.gravity};
    const Vector3 w{axis_[0] * s[6], axis_[1] * s[6], axis_[2] * s[6]};
    const Vector3 w_cross_u = cross(w, u);
    // |w x u| = omega_perp |u|: the spin perpendicular to the air velocity.
    const double perpendicular_spin = speed > 0 ? norm(w_cross_u) / speed : 0;
    if (options_.drag && speed > 0) {
      const double drag = k_ * drag_coefficient(options_.aerodynamics, perpendicular_spin) * speed;
      for (int i = 0; i < 3; ++i) a[i] -= drag * u[i];
    }
    if (options_.lift && perpendicular_spin > 0) {
      const double s_factor = options_.ball.radius * perpendicular_spin / speed;
      // K C_L |u|^2 along w x u / |w x u|, with |w x u| = omega_perp |u|.
      const double lift = k_ * lift_coefficient(options_.aerodynamics, s_factor) * speed / perpendicular_spin;
      for (int i = 0; i < 3; ++i) a[i] += lift * w_cross_u[i];
    }
    ds = {s[3], s[4], s[5], a[0], a[1], a[2],
          -s[6] * speed / (options_.aerodynamics.spin_decay_time * spin_decay_reference_speed)};
  }

 private:
  Vector3 axis_, wind_;
  const FlightOptions& options_;
  double k_ = 0;
};

}  // namespace sweetspot::detail
