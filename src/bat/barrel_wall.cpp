#include "sweetspot/bat/barrel_wall.hpp"

#include <algorithm>
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
  w.spread = 2 / beta;
  w.mass = w.stiffness / (w.omega * w.omega);
  w.loss_factor = material.wall_loss_factor;
  return w;
}

namespace {

bool bored(const Bat& bat, int i) { return bat.inner_diameter[i] > 0 && bat.inner_diameter[i] < bat.outer_diameter[i]; }

}  // namespace

std::vector<WallMode> barrel_wall(const Bat& bat) {
  std::vector<WallMode> wall;
  if (!bat.hollow()) return wall;
  wall.resize(bat.slices());
  for (int first = 0; first < bat.slices();) {
    if (!bored(bat, first)) {
      ++first;
      continue;
    }
    int end = first;  // the run of hollow slices [first, end)
    while (end < bat.slices() && bored(bat, end)) ++end;
    // The bore is a tube only if it is longer than the widest spread of an ovaling along it.
    double spread = 0;
    for (int i = first; i < end; ++i) {
      wall[i] = wall_mode(bat.outer_diameter[i], bat.inner_diameter[i], bat.material);
      spread = std::max(spread, wall[i].spread);
    }
    if ((end - first) * bat.slice_thickness() < spread) std::fill(wall.begin() + first, wall.begin() + end, WallMode{});
    first = end;
  }
  return wall;
}

}  // namespace sweetspot
