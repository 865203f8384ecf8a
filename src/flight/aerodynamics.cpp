#include "sweetspot/flight/aerodynamics.hpp"

#include <numbers>

namespace sweetspot {

double drag_coefficient(const Aerodynamics& aero, double perpendicular_spin) {
  const double rpm = perpendicular_spin * 30 / std::numbers::pi;
  return aero.cd0 + aero.cd_spin * rpm / 1000;
}

double lift_coefficient(const Aerodynamics& aero, double spin_factor) {
  return aero.cl2 * spin_factor / (aero.cl0 + aero.cl1 * spin_factor);
}

}  // namespace sweetspot
