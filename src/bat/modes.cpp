#include "sweetspot/bat/modes.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "sweetspot/input_error.hpp"

namespace sweetspot {

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// A discretised free-free beam: K x = omega^2 M x, plus the degree-of-freedom vectors of the two
// rigid motions and the map from degrees of freedom to displacements at the slice centres.
struct BeamSystem {
  MatrixXd stiffness;
  MatrixXd mass;
  VectorXd translation;     // y = 1 everywhere
  VectorXd rotation_knob;   // y = z, cross-sections turned with it (rotation about the knob)
  MatrixXd slice_displacement;  // rows: slice centres; maps x to y(z_i)
};

// Each slice's rigidities, and the length: what a point load needs of the beam (beam_layout.hpp).
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

// Solves K x = w^2 M x for mass-orthonormal x, ascending w^2.
void solve(const BeamSystem& s, bool diagonal_mass, VectorXd& omega_squared, MatrixXd& vectors) {
  if (diagonal_mass) {
    // With M diagonal the Cholesky factor of the generalized problem is M^(1/2) itself.
    const VectorXd scale = s.mass.diagonal().cwiseSqrt().cwiseInverse();
    const MatrixXd a = scale.asDiagonal() * s.stiffness * scale.asDiagonal();
    Eigen::SelfAdjointEigenSolver<MatrixXd> eig(a);
    omega_squared = eig.eigenvalues();
    vectors = scale.asDiagonal() * eig.eigenvectors();
  } else {
    Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> eig(s.stiffness, s.mass);
    omega_squared = eig.eigenvalues();
    vectors = eig.eigenvectors();
  }
}

// Replaces the two near-zero modes by the exact rigid ones and makes every vibrational mode
// exactly M-orthogonal to them, so that rigid motion stays in the rigid modes to round-off.
void set_rigid_modes(const BeamSystem& s, ModalBasis& basis, VectorXd& omega_squared, MatrixXd& x) {
  const VectorXd& t = s.translation;
  basis.mass = t.dot(s.mass * t);
  basis.z_cm = t.dot(s.mass * s.rotation_knob) / basis.mass;
  const VectorXd r = s.rotation_knob - basis.z_cm * t;
  basis.moment_of_inertia_cm = r.dot(s.mass * r);
  x.col(0) = t / std::sqrt(basis.mass);
  x.col(1) = r / std::sqrt(basis.moment_of_inertia_cm);
  omega_squared(0) = omega_squared(1) = 0;
  for (int n = 2; n < x.cols(); ++n) {
    for (int rigid = 0; rigid < 2; ++rigid) x.col(n) -= x.col(rigid).dot(s.mass * x.col(n)) * x.col(rigid);
    x.col(n) /= std::sqrt(x.col(n).dot(s.mass * x.col(n)));
  }
  basis.translation = x.transpose() * (s.mass * t);
  basis.rotation = x.transpose() * (s.mass * r);
  basis.translation.tail(x.cols() - 2).setZero();  // vibrational modes start at rest
  basis.rotation.tail(x.cols() - 2).setZero();
  basis.translation(1) = 0;
  basis.rotation(0) = 0;
}

}  // namespace

Eigen::VectorXd ModalBasis::shapes_at(double z) const {
  const PointLoad p = layout.point(z);
  Eigen::VectorXd shapes = Eigen::VectorXd::Zero(count());
  for (int k = 0; k < 4; ++k)
    if (p.weight[k] != 0) shapes += p.weight[k] * vectors.row(p.dof[k]).transpose();
  return shapes;
}

Eigen::MatrixXd beam_mass_matrix(const Bat& bat, BeamTheory theory) {
  return theory == BeamTheory::timoshenko ? timoshenko_system(bat).mass : euler_bernoulli_system(bat).mass;
}

ModalBasis compute_modes(const Bat& bat, BeamTheory theory, bool rigid_only) {
  const bool timoshenko = theory == BeamTheory::timoshenko;
  if (!timoshenko && bat.slices() > max_euler_bernoulli_slices)
    throw InputError("slices = " + std::to_string(bat.slices()) + ": at most " +
                     std::to_string(max_euler_bernoulli_slices) +
                     " for theory euler-bernoulli (its dense solve loses the lowest frequencies to round-off)");
  const BeamSystem s = timoshenko ? timoshenko_system(bat) : euler_bernoulli_system(bat);
  VectorXd omega_squared = VectorXd::Zero(2);
  MatrixXd x(s.mass.rows(), 2);
  if (!rigid_only) solve(s, timoshenko, omega_squared, x);

  ModalBasis basis;
  basis.theory = theory;
  basis.layout = beam_layout(bat, theory);
  for (int i = 0; i < bat.slices(); ++i) basis.z.push_back(bat.slice_center(i));
  set_rigid_modes(s, basis, omega_squared, x);
  basis.omega = omega_squared.cwiseMax(0.0).cwiseSqrt();
  // A fixed sign (barrel end moving +y) makes mode shapes reproducible across solvers.
  for (int n = 2; n < x.cols(); ++n)
    if (s.slice_displacement.row(bat.slices() - 1).dot(x.col(n)) < 0) x.col(n) *= -1;
  basis.psi = s.slice_displacement * x;
  basis.vectors = std::move(x);
  return basis;
}

std::vector<double> ModalBasis::vibrational_frequencies_hz() const {
  std::vector<double> f;
  for (int n = 2; n < count(); ++n) f.push_back(omega(n) / (2 * std::numbers::pi));
  return f;
}

std::vector<double> ModalBasis::nodes(int n) const {
  std::vector<double> zeros;
  for (int i = 0; i + 1 < slices(); ++i) {
    const double a = psi(i, n), b = psi(i + 1, n);
    if (a == 0) zeros.push_back(z[i]);
    else if (a * b < 0) zeros.push_back(z[i] + (z[i + 1] - z[i]) * a / (a - b));
  }
  return zeros;
}

const char* to_string(BeamTheory theory) {
  return theory == BeamTheory::timoshenko ? "timoshenko" : "euler-bernoulli";
}

BeamTheory parse_beam_theory(const std::string& text) {
  if (text == "timoshenko") return BeamTheory::timoshenko;
  if (text == "euler-bernoulli") return BeamTheory::euler_bernoulli;
  throw InputError("theory '" + text + "': expected 'timoshenko' or 'euler-bernoulli'");
}

}  // namespace sweetspot
