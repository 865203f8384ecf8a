#include "sweetspot/bat/barrel_wall.hpp"

#include <cmath>

namespace sweetspot {

WallMode wall_mode(double outer_diameter, double inner_diameter, const Material& material) {
  const double h = (outer_diameter - inner_diameter) / 2;  // wall thickness
  const double a = (outer_diameter + inner_diameter) / 4;  // mid-surface radius
  const double hoop = material.wall_hoop_modulus(), axial = material.youngs_modulus;
  WallMode w;
  // Ring n = 2: omega^2 = 3 E_t h^2 / (5 rho a^4).
  w.omega = std::sqrt(3 * hoop * h * h / (5 * material.density * a * a * a * a));
  // Point stiffness of the ovaling as a beam on an elastic foundation (see the header).
  const double foundation = 3 * std::numbers::pi * hoop * h * h * h / (4 * a * a * a);
  const double beta = std::pow(3 * hoop / axial, 0.25) * std::sqrt(h) / std::pow(a, 1.5);
  w.stiffness = 2 * foundation / beta;
  w.mass = w.stiffness / (w.omega * w.omega);
  w.loss_factor = material.wall_loss_factor;
  return w;
}

std::vector<WallMode> barrel_wall(const Bat& bat) {
  std::vector<WallMode> wall;
  if (!bat.hollow()) return wall;
  for (int i = 0; i < bat.slices(); ++i) {
    const double outer = bat.outer_diameter[i], inner = bat.inner_diameter[i];
    wall.push_back(inner > 0 && inner < outer ? wall_mode(outer, inner, bat.material) : WallMode{});
  }
  return wall;
}

}  // namespace sweetspot
