#include "bat/beam_system.hpp"

#include <utility>
#include <vector>

namespace sweetspot {

using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// A square matrix assembled entry by entry into its band (beam_bandwidth on either side of the
// diagonal), each entry summed in the order the loops add to it, as a dense matrix would sum it:
// the dense solve then sees the same numbers bit for bit.
class SparseAssembly {
 public:
  explicit SparseAssembly(int n) : m_(n, n) { m_.reserve(Eigen::VectorXi::Constant(n, 2 * beam_bandwidth + 1)); }
  double& operator()(int i, int j) { return m_.coeffRef(i, j); }
  // The matrix compressed, entries that summed to exactly 0 dropped (as a dense matrix's zeros
  // were when its band was copied out).
  Eigen::SparseMatrix<double> matrix() {
    m_.prune(0.0, 0.0);
    m_.makeCompressed();
    return std::move(m_);
  }

 private:
  Eigen::SparseMatrix<double> m_;
};

Eigen::SparseMatrix<double> from_triplets(int rows, int cols, const std::vector<Eigen::Triplet<double>>& entries) {
  Eigen::SparseMatrix<double> m(rows, cols);
  m.setFromTriplets(entries.begin(), entries.end());
  m.prune(0.0, 0.0);
  return m;
}

}  // namespace

BeamLayout beam_layout(const Bat& bat, BeamTheory theory) {
  BeamLayout layout;
  layout.theory = theory;
  layout.length = bat.length;
  const Material& mat = bat.material;
  for (int i = 0; i < bat.slices(); ++i) {
    layout.bending.push_back(mat.youngs_modulus * bat.second_moment(i));
    layout.shear.push_back(mat.shear_coefficient * mat.shear_modulus * bat.area(i));
  }
  return layout;
}

// Timoshenko (physics.md §2): dofs (y_i, phi_i) per slice; lumped slice masses and rotary
// inertias; bending and shear energy on the N-1 joints. A joint spans half of each slice, and the
// halves act in series: its rigidities are the harmonic means of the slices' (joint_rigidity).
// For a stepped profile that is exact, and the frequencies converge at second order; the
// arithmetic mean overstates the stiffness across every step (first order; tests/test_modes.cpp).
BeamSystem timoshenko_system(const Bat& bat) {
  const int n = bat.slices();
  const double dz = bat.slice_thickness();
  const BeamLayout beam = beam_layout(bat, BeamTheory::timoshenko);
  SparseAssembly stiffness(2 * n), mass(2 * n);
  BeamSystem s;
  s.translation = VectorXd::Zero(2 * n);
  s.rotation_knob = VectorXd::Zero(2 * n);
  std::vector<Eigen::Triplet<double>> slice_displacement;
  for (int i = 0; i < n; ++i) {
    mass(2 * i, 2 * i) = bat.slice_mass(i);
    mass(2 * i + 1, 2 * i + 1) = bat.slice_rotary_inertia(i);
    s.translation(2 * i) = 1;
    s.rotation_knob(2 * i) = bat.slice_center(i);
    s.rotation_knob(2 * i + 1) = -1;  // shear-free rotation: dy/dz + phi = 0
    slice_displacement.emplace_back(i, 2 * i, 1.0);
  }
  for (int j = 0; j + 1 < n; ++j) {
    const int y0 = 2 * j, p0 = 2 * j + 1, y1 = 2 * j + 2, p1 = 2 * j + 3;
    const double bending = joint_rigidity(beam.bending[j], beam.bending[j + 1]) / dz;
    stiffness(p0, p0) += bending;
    stiffness(p1, p1) += bending;
    stiffness(p0, p1) -= bending;
    stiffness(p1, p0) -= bending;
    // Shear strain gamma = (y1 - y0)/dz + (phi0 + phi1)/2 = g . x
    const double shear = joint_rigidity(beam.shear[j], beam.shear[j + 1]) * dz;
    const int dof[4] = {y0, p0, y1, p1};
    const double g[4] = {-1 / dz, 0.5, 1 / dz, 0.5};
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) stiffness(dof[a], dof[b]) += shear * g[a] * g[b];
  }
  s.stiffness = stiffness.matrix();
  s.mass = mass.matrix();
  s.slice_displacement = from_triplets(n, 2 * n, slice_displacement);
  return s;
}

// Euler-Bernoulli: one cubic Hermite element per slice, dofs (w_j, w'_j) at the N+1 slice
// boundaries, consistent mass. Rayleigh-Ritz, so frequencies converge from above as h^4.
BeamSystem euler_bernoulli_system(const Bat& bat) {
  const int n = bat.slices();
  const int dofs = 2 * (n + 1);
  const double h = bat.slice_thickness();
  SparseAssembly stiffness(dofs), mass(dofs);
  BeamSystem s;
  s.translation = VectorXd::Zero(dofs);
  s.rotation_knob = VectorXd::Zero(dofs);
  std::vector<Eigen::Triplet<double>> slice_displacement;
  Eigen::Matrix4d k_unit, m_unit;
  k_unit << 12, 6 * h, -12, 6 * h, 6 * h, 4 * h * h, -6 * h, 2 * h * h, -12, -6 * h, 12, -6 * h,
      6 * h, 2 * h * h, -6 * h, 4 * h * h;
  m_unit << 156, 22 * h, 54, -13 * h, 22 * h, 4 * h * h, 13 * h, -3 * h * h, 54, 13 * h, 156, -22 * h,
      -13 * h, -3 * h * h, -22 * h, 4 * h * h;
  for (int e = 0; e < n; ++e) {
    const double ei = bat.material.youngs_modulus * bat.second_moment(e);
    const double rho_a = bat.material.density * bat.area(e);
    const double k_scale = ei / (h * h * h), m_scale = rho_a * h / 420;
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        stiffness(2 * e + a, 2 * e + b) += k_scale * k_unit(a, b);
        mass(2 * e + a, 2 * e + b) += m_scale * m_unit(a, b);
      }
    // Hermite shape functions at the element midpoint: 1/2, h/8, 1/2, -h/8.
    for (const auto& [dof, weight] : {std::pair{0, 0.5}, {1, h / 8}, {2, 0.5}, {3, -h / 8}})
      slice_displacement.emplace_back(e, 2 * e + dof, weight);
  }
  for (int j = 0; j <= n; ++j) {
    s.translation(2 * j) = 1;
    s.rotation_knob(2 * j) = j * h;
    s.rotation_knob(2 * j + 1) = 1;
  }
  s.stiffness = stiffness.matrix();
  s.mass = mass.matrix();
  s.slice_displacement = from_triplets(n, dofs, slice_displacement);
  return s;
}

}  // namespace sweetspot
