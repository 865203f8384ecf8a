#include "sweetspot/step_selection.hpp"

#include <algorithm>
#include <cmath>

#include "sweetspot/mode_selection.hpp"

namespace sweetspot {

CollisionOptions options_for_accuracy(CollisionOptions options, double accuracy, const Ball& ball,
                                      double approach_speed, double recoil, double omega_max) {
  const double pulse = pulse_duration(ball, approach_speed, recoil);
  const double allowed = accuracy / 2;
  switch (options.method) {
    case Method::exact:
      // Fast impacts (150 m/s) err about 4x more than the model at the same dt/T: budget for it.
      options.dt = std::clamp(pulse * std::pow(allowed / 28, 1 / 3.8), pulse / 5000, pulse / 10);
      break;
    case Method::rk4:
      options.dt = std::clamp(pulse * std::pow(allowed / 555, 0.25), pulse / 20000, pulse / 20);
      if (omega_max > 0) options.dt = std::min(options.dt, 0.99 * rk4_stability_limit / omega_max);
      break;
    case Method::dopri:
      options.tolerance = allowed / 50;
      break;
  }
  return options;
}

}  // namespace sweetspot
