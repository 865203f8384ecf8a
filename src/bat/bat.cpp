#include "sweetspot/bat/bat.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sweetspot {

namespace {

double disc_area(double diameter) { return std::numbers::pi * diameter * diameter / 4; }
double disc_second_moment(double diameter) {
  const double r = diameter / 2;
  return std::numbers::pi * r * r * r * r / 4;
}

// Mean of a piecewise-constant per-slice quantity over [a, b], weighted by overlap.
double overlap_mean(const std::vector<double>& values, double dz, double a, double b) {
  const int n = static_cast<int>(values.size());
  double sum = 0;
  const int first = std::clamp(static_cast<int>(std::floor(a / dz)), 0, n - 1);
  const int last = std::clamp(static_cast<int>(std::ceil(b / dz)), 1, n);
  for (int i = first; i < last; ++i) {
    const double overlap = std::min(b, (i + 1) * dz) - std::max(a, i * dz);
    if (overlap > 0) sum += values[i] * overlap;
  }
  return sum / (b - a);
}

}  // namespace

void Bat::set_slices(std::vector<double> outer, std::vector<double> inner) {
  outer_diameter = std::move(outer);
  inner_diameter = std::move(inner);
  section_area.clear();
  section_second_moment.clear();
  for (int i = 0; i < slices(); ++i) {
    const double d = hollow() ? inner_diameter[i] : 0.0;
    section_area.push_back(disc_area(outer_diameter[i]) - disc_area(d));
    section_second_moment.push_back(disc_second_moment(outer_diameter[i]) - disc_second_moment(d));
  }
}

Bat resample(const Bat& bat, int n) {
  if (n == bat.slices()) return bat;
  Bat out = bat;
  const double old_dz = bat.slice_thickness();
  const double new_dz = bat.length / n;
  for (auto* v : {&out.outer_diameter, &out.inner_diameter, &out.section_area, &out.section_second_moment})
    v->clear();
  for (int i = 0; i < n; ++i) {
    const double a = i * new_dz, b = (i + 1) * new_dz;
    out.outer_diameter.push_back(overlap_mean(bat.outer_diameter, old_dz, a, b));
    if (bat.hollow()) out.inner_diameter.push_back(overlap_mean(bat.inner_diameter, old_dz, a, b));
    out.section_area.push_back(overlap_mean(bat.section_area, old_dz, a, b));
    out.section_second_moment.push_back(overlap_mean(bat.section_second_moment, old_dz, a, b));
  }
  return out;
}

double MassProperties::radius_of_gyration() const { return std::sqrt(moment_of_inertia_cm / mass); }

double MassProperties::moment_of_inertia_about(double z) const {
  return moment_of_inertia_cm + mass * (z - z_cm) * (z - z_cm);
}

MassProperties mass_properties(const Bat& bat) {
  MassProperties p;
  double first_moment = 0;
  for (int i = 0; i < bat.slices(); ++i) {
    p.mass += bat.slice_mass(i);
    first_moment += bat.slice_mass(i) * bat.slice_center(i);
  }
  p.z_cm = first_moment / p.mass;
  for (int i = 0; i < bat.slices(); ++i) {
    const double arm = bat.slice_center(i) - p.z_cm;
    p.moment_of_inertia_cm += bat.slice_mass(i) * arm * arm + bat.slice_rotary_inertia(i);
  }
  return p;
}

}  // namespace sweetspot
