#include "bat/beam_system.hpp"

namespace sweetspot {

using Eigen::MatrixXd;
using Eigen::VectorXd;

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
  BeamSystem s;
  s.stiffness = MatrixXd::Zero(2 * n, 2 * n);
  s.mass = MatrixXd::Zero(2 * n, 2 * n);
  s.translation = VectorXd::Zero(2 * n);
  s.rotation_knob = VectorXd::Zero(2 * n);
  s.slice_displacement = MatrixXd::Zero(n, 2 * n);
  for (int i = 0; i < n; ++i) {
    s.mass(2 * i, 2 * i) = bat.slice_mass(i);
    s.mass(2 * i + 1, 2 * i + 1) = bat.slice_rotary_inertia(i);
    s.translation(2 * i) = 1;
    s.rotation_knob(2 * i) = bat.slice_center(i);
    s.rotation_knob(2 * i + 1) = -1;  // shear-free rotation: dy/dz + phi = 0
    s.slice_displacement(i, 2 * i) = 1;
  }
  for (int j = 0; j + 1 < n; ++j) {
    const int y0 = 2 * j, p0 = 2 * j + 1, y1 = 2 * j + 2, p1 = 2 * j + 3;
    const double bending = joint_rigidity(beam.bending[j], beam.bending[j + 1]) / dz;
    s.stiffness(p0, p0) += bending;
    s.stiffness(p1, p1) += bending;
    s.stiffness(p0, p1) -= bending;
    s.stiffness(p1, p0) -= bending;
    // Shear strain gamma = (y1 - y0)/dz + (phi0 + phi1)/2 = g . x
    const double shear = joint_rigidity(beam.shear[j], beam.shear[j + 1]) * dz;
    const int dof[4] = {y0, p0, y1, p1};
    const double g[4] = {-1 / dz, 0.5, 1 / dz, 0.5};
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) s.stiffness(dof[a], dof[b]) += shear * g[a] * g[b];
  }
  return s;
}

// Euler-Bernoulli: one cubic Hermite element per slice, dofs (w_j, w'_j) at the N+1 slice
// boundaries, consistent mass. Rayleigh-Ritz, so frequencies converge from above as h^4.
BeamSystem euler_bernoulli_system(const Bat& bat) {
  const int n = bat.slices();
  const int dofs = 2 * (n + 1);
  const double h = bat.slice_thickness();
  BeamSystem s;
  s.stiffness = MatrixXd::Zero(dofs, dofs);
  s.mass = MatrixXd::Zero(dofs, dofs);
  s.translation = VectorXd::Zero(dofs);
  s.rotation_knob = VectorXd::Zero(dofs);
  s.slice_displacement = MatrixXd::Zero(n, dofs);
  Eigen::Matrix4d k_unit, m_unit;
  k_unit << 12, 6 * h, -12, 6 * h, 6 * h, 4 * h * h, -6 * h, 2 * h * h, -12, -6 * h, 12, -6 * h,
      6 * h, 2 * h * h, -6 * h, 4 * h * h;
  m_unit << 156, 22 * h, 54, -13 * h, 22 * h, 4 * h * h, 13 * h, -3 * h * h, 54, 13 * h, 156, -22 * h,
      -13 * h, -3 * h * h, -22 * h, 4 * h * h;
  for (int e = 0; e < n; ++e) {
    const double ei = bat.material.youngs_modulus * bat.second_moment(e);
    const double rho_a = bat.material.density * bat.area(e);
    s.stiffness.block<4, 4>(2 * e, 2 * e) += ei / (h * h * h) * k_unit;
    s.mass.block<4, 4>(2 * e, 2 * e) += rho_a * h / 420 * m_unit;
    // Hermite shape functions at the element midpoint: 1/2, h/8, 1/2, -h/8.
    s.slice_displacement(e, 2 * e) = 0.5;
    s.slice_displacement(e, 2 * e + 1) = h / 8;
    s.slice_displacement(e, 2 * e + 2) = 0.5;
    s.slice_displacement(e, 2 * e + 3) = -h / 8;
  }
  for (int j = 0; j <= n; ++j) {
    s.translation(2 * j) = 1;
    s.rotation_knob(2 * j) = j * h;
    s.rotation_knob(2 * j + 1) = 1;
  }
  return s;
}

}  // namespace sweetspot
