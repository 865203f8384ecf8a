#include "sweetspot/bat/beam_layout.hpp"

#include <algorithm>
#include <cmath>

namespace sweetspot {

namespace {

// Deflection under a unit load at fraction w of a segment of length h clamped at both ends:
// shear w (1 - w) h / (kappa S A) and bending w^3 (1 - w)^3 h^3 / (3 Y I) (Roark, fixed-fixed beam
// with a point load; the shear part of a Timoshenko beam). Zero at the ends.
double clamped_segment_compliance(double w, double h, double bending, double shear) {
  const double v = w * (1 - w);
  return v * h / shear + v * v * v * h * h * h / (3 * bending);
}

// Deflection at distance s from a clamped section of a free overhang, under a unit load there.
double cantilever_compliance(double s, double bending, double shear) {
  return s / shear + s * s * s / (3 * bending);
}

// Timoshenko dofs (y_i, phi_i) at slice centres; each slice is rigid between its joints, y along
// it being y_i - phi_i (z - z_i) (a shear-free turn has phi = -dy/dz); y linear along a joint.
PointLoad timoshenko_point(const BeamLayout& beam, double z) {
  const int n = beam.slices();
  const double dz = beam.length / n;
  const double x = z / dz - 0.5;  // in units of dz from the first centre
  PointLoad p;
  if (x <= 0 || x >= n - 1) {
    const int i = x <= 0 ? 0 : n - 1;
    const double offset = z - (i + 0.5) * dz;
    p.dof = {2 * i, 2 * i + 1, 0, 0};
    p.weight = {1, -offset, 0, 0};
    p.compliance = cantilever_compliance(std::abs(offset), beam.bending[i], beam.shear[i]);
    return p;
  }
  const int j = std::min(static_cast<int>(x), n - 2);
  const double w = x - j;
  p.dof = {2 * j, 2 * j + 2, 0, 0};
  p.weight = {1 - w, w, 0, 0};
  p.compliance = clamped_segment_compliance(w, dz, joint_rigidity(beam.bending[j], beam.bending[j + 1]),
                                            joint_rigidity(beam.shear[j], beam.shear[j + 1]));
  return p;
}

// Euler-Bernoulli dofs (w_j, w'_j) at slice boundaries; cubic Hermite within each element.
PointLoad euler_bernoulli_point(const BeamLayout& beam, double z) {
  const int n = beam.slices();
  const double h = beam.length / n;
  const int e = std::clamp(static_cast<int>(z / h), 0, n - 1);
  const double s = z / h - e, s2 = s * s, s3 = s2 * s;
  PointLoad p;
  p.dof = {2 * e, 2 * e + 1, 2 * e + 2, 2 * e + 3};
  p.weight = {1 - 3 * s2 + 2 * s3, h * (s - 2 * s2 + s3), 3 * s2 - 2 * s3, h * (s3 - s2)};
  const double v = s * (1 - s);
  p.compliance = v * v * v * h * h * h / (3 * beam.bending[e]);
  return p;
}

}  // namespace

double joint_rigidity(double a, double b) { return 2 * a * b / (a + b); }

PointLoad BeamLayout::point(double z) const {
  z = std::clamp(z, 0.0, length);
  return theory == BeamTheory::timoshenko ? timoshenko_point(*this, z) : euler_bernoulli_point(*this, z);
}

}  // namespace sweetspot
