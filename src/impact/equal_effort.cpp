#include "sweetspot/impact/equal_effort.hpp"

#include <cmath>

namespace sweetspot {

Swing equal_effort_swing(const Swing& reference, double reference_moi, double moi, double exponent) {
  if (moi == reference_moi) return reference;  // bit for bit: the player's own swing
  const double scale = std::pow(reference_moi / moi, exponent);
  Swing swing = reference;
  swing.omega *= scale;
  swing.cm_speed *= scale;
  return swing;
}

}  // namespace sweetspot
