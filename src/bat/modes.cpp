#include "sweetspot/bat/modes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/SparseCore>

#include "bat/banded_eigensolver.hpp"
#include "bat/beam_flexibility.hpp"
#include "bat/beam_system.hpp"
#include "sweetspot/input_error.hpp"

namespace sweetspot {

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

int degrees_of_freedom(int slices, BeamTheory theory) {
  return theory == BeamTheory::timoshenko ? 2 * slices : 2 * (slices + 1);
}

int slices_of(int dofs, bool timoshenko) { return timoshenko ? dofs / 2 : dofs / 2 - 1; }

// What may be asked instead at this count of degrees of freedom.
std::string alternatives(int dofs) {
  return "expected modes = \"auto\" or at most " + std::to_string(practical_mode_count(dofs) - 2) +
         " vibrational modes at this slice count (a partial solve's time grows as the slices times the "
         "modes squared)";
}

std::string too_many(int dofs) { return ": more than is practical; " + alternatives(dofs); }

// Solves K x = w^2 M x for mass-orthonormal x, ascending w^2, densely (O(n^3)).
void solve(const BeamSystem& s, bool diagonal_mass, VectorXd& omega_squared, MatrixXd& vectors) {
  const MatrixXd stiffness = s.stiffness;
  if (diagonal_mass) {
    // With M diagonal the Cholesky factor of the generalized problem is M^(1/2) itself.
    const VectorXd scale = VectorXd(s.mass.diagonal()).cwiseSqrt().cwiseInverse();
    const MatrixXd a = scale.asDiagonal() * stiffness * scale.asDiagonal();
    Eigen::SelfAdjointEigenSolver<MatrixXd> eig(a);
    omega_squared = eig.eigenvalues();
    vectors = scale.asDiagonal() * eig.eigenvectors();
  } else {
    Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> eig(stiffness, MatrixXd(s.mass));
    omega_squared = eig.eigenvalues();
    vectors = eig.eigenvectors();
  }
}

// Replaces the two near-zero modes by the exact rigid ones and makes every vibrational mode
// exactly M-orthogonal to them, so that rigid motion stays in the rigid modes to round-off.
// `mass` is M's sparse copy (or Timoshenko's lumped M as a diagonal: the same products, without
// the sparse one's bookkeeping): a product per mode is O(n), where the dense M made this step
// O(n^3), half of the dense solve's instructions.
template <class Mass>
void set_rigid_modes(const BeamSystem& s, const Mass& mass, ModalBasis& basis, VectorXd& omega_squared, MatrixXd& x) {
  const VectorXd& t = s.translation;
  basis.mass = t.dot(mass * t);
  basis.z_cm = t.dot(mass * s.rotation_knob) / basis.mass;
  const VectorXd r = s.rotation_knob - basis.z_cm * t;
  basis.moment_of_inertia_cm = r.dot(mass * r);
  x.col(0) = t / std::sqrt(basis.mass);
  x.col(1) = r / std::sqrt(basis.moment_of_inertia_cm);
  omega_squared(0) = omega_squared(1) = 0;
  for (int n = 2; n < x.cols(); ++n) {
    for (int rigid = 0; rigid < 2; ++rigid) x.col(n) -= x.col(rigid).dot(mass * x.col(n)) * x.col(rigid);
    x.col(n) /= std::sqrt(x.col(n).dot(mass * x.col(n)));
  }
  basis.translation = x.transpose() * (mass * t);
  basis.rotation = x.transpose() * (mass * r);
  basis.translation.tail(x.cols() - 2).setZero();  // vibrational modes start at rest
  basis.rotation.tail(x.cols() - 2).setZero();
  basis.translation(1) = 0;
  basis.rotation(0) = 0;
}

void set_rigid_modes(const BeamSystem& s, const Eigen::SparseMatrix<double>& mass, bool timoshenko, ModalBasis& basis,
                     VectorXd& omega_squared, MatrixXd& x) {
  if (timoshenko) set_rigid_modes(s, Eigen::DiagonalMatrix<double, Eigen::Dynamic>(mass.diagonal()), basis, omega_squared, x);
  else set_rigid_modes(s, mass, basis, omega_squared, x);
}

// The banded solve of a partial request; false, with nothing done, when the request reaches past
// max_banded_share and the dense solve is cheaper. Throws InputError when a request below a
// frequency covers more modes than practical_mode_count.
bool solve_partial(const BeamSystem& s, const Eigen::SparseMatrix<double>& mass, bool timoshenko, ModeRequest request,
                   VectorXd& omega_squared, MatrixXd& x) {
  const int dofs = static_cast<int>(s.mass.rows()), most = practical_mode_count(dofs);
  const BandedRequest banded{request.vibrational > 0 ? request.vibrational + 2 : -1,
                             request.below_omega * request.below_omega, timoshenko, most};
  int counted = 0;
  if (solve_lowest(s, mass, banded, omega_squared, x, &counted)) return true;
  if (counted > most) {
    char omega[32];
    std::snprintf(omega, sizeof omega, "%.4g", request.below_omega);
    throw InputError("slices = " + std::to_string(slices_of(dofs, timoshenko)) + ": the " +
                     std::to_string(counted - 2) + " vibrational modes below " + omega +
                     " rad/s that modes = \"auto\" asks at this mode_tolerance" + too_many(dofs));
  }
  return false;
}

}  // namespace

int practical_mode_count(int dofs) {
  constexpr double full = 2.0 * max_full_solve_slices, budget = full * full * full;
  return dofs <= 2 * max_full_solve_slices ? dofs : static_cast<int>(std::sqrt(budget / dofs));
}

std::optional<std::string> impractical_solve(int slices, BeamTheory theory, ModeRequest request) {
  const int dofs = degrees_of_freedom(slices, theory);
  if (request.is_rigid_only() || (request.is_below() && request.below_omega < 1e300)) return std::nullopt;
  const bool every = request.is_all() || request.is_below() || request.vibrational + 2 >= dofs;
  if (every && dofs > 2 * max_full_solve_slices)
    return "every mode (the full eigen-solve) is practical up to " + std::to_string(max_full_solve_slices) +
           " slices (its time grows as the cube of the slices: about 7 s at 1024, some 8 min at 4096); " +
           alternatives(dofs);
  if (!every && request.vibrational + 2 > practical_mode_count(dofs))
    return std::to_string(request.vibrational) + " vibrational modes" + too_many(dofs);
  return std::nullopt;
}

Eigen::VectorXd ModalBasis::shapes_at(double z) const {
  const PointLoad p = layout.point(z);
  Eigen::VectorXd shapes = Eigen::VectorXd::Zero(count());
  for (int k = 0; k < 4; ++k)
    if (p.weight[k] != 0) shapes += p.weight[k] * vectors.row(p.dof[k]).transpose();
  return shapes;
}

Eigen::MatrixXd beam_mass_matrix(const Bat& bat, BeamTheory theory) {
  return MatrixXd(theory == BeamTheory::timoshenko ? timoshenko_system(bat).mass : euler_bernoulli_system(bat).mass);
}

struct BasisWidening {
  explicit BasisWidening(Bat b) : bat(std::move(b)) {}
  const Bat bat;
  std::mutex mutex;
  std::map<double, std::unique_ptr<const ModalBasis>> solved;  // by the frequency solved below
};

const ModalBasis& ModalBasis::widened(const ModeRequest& request) const {
  if (!widening || complete() || !request.is_below() || !(request.below_omega > solved_below)) return *this;
  const std::lock_guard lock(widening->mutex);
  std::unique_ptr<const ModalBasis>& slot = widening->solved[request.below_omega];
  if (!slot) {
    try {
      slot = std::make_unique<const ModalBasis>(compute_modes(widening->bat, theory, request));
    } catch (const InputError&) {  // impractical at this slicing: the modes solved serve
      return *this;
    }
  }
  return *slot;
}

ModalBasis compute_modes(const Bat& bat, BeamTheory theory, ModeRequest request) {
  const bool timoshenko = theory == BeamTheory::timoshenko;
  if (!timoshenko && bat.slices() > max_euler_bernoulli_slices)
    throw InputError("slices = " + std::to_string(bat.slices()) + ": at most " +
                     std::to_string(max_euler_bernoulli_slices) +
                     " for theory euler-bernoulli (its dense solve loses the lowest frequencies to round-off)");
  if (const auto why = impractical_solve(bat.slices(), theory, request))
    throw InputError("slices = " + std::to_string(bat.slices()) + ": " + *why);
  const BeamSystem s = timoshenko ? timoshenko_system(bat) : euler_bernoulli_system(bat);
  const int dofs = static_cast<int>(s.mass.rows());
  if (request.vibrational + 2 >= dofs || (request.is_below() && !(request.below_omega < 1e300)))
    request = ModeRequest::all();
  bool partial = !request.is_all() && !request.is_rigid_only();
  ModalBasis basis;
  basis.theory = theory;
  basis.layout = beam_layout(bat, theory);
  for (int i = 0; i < bat.slices(); ++i) basis.z.push_back(bat.slice_center(i));
  VectorXd omega_squared = VectorXd::Zero(2);
  MatrixXd x(dofs, 2);
  const Eigen::SparseMatrix<double>& mass = s.mass;
  if (partial) partial = solve_partial(s, mass, timoshenko, request, omega_squared, x);
  if (!partial && !request.is_rigid_only()) solve(s, timoshenko, omega_squared, x);
  set_rigid_modes(s, mass, timoshenko, basis, omega_squared, x);
  basis.omega = omega_squared.cwiseMax(0.0).cwiseSqrt();
  // A fixed sign (barrel end moving +y) makes mode shapes reproducible across solvers.
  const VectorXd barrel_end = s.slice_displacement.transpose() * VectorXd::Unit(bat.slices(), bat.slices() - 1);
  for (int n = 2; n < x.cols(); ++n)
    if (barrel_end.dot(x.col(n)) < 0) x.col(n) *= -1;
  // Row i of the map reads the degrees of freedom 2i to 2i + 3 (both theories: beam_system.cpp).
  basis.psi = s.slice_displacement * x;
  basis.vectors = std::move(x);
  if (partial && !basis.complete()) {
    basis.solved_below = request.vibrational > 0 ? basis.omega(basis.count() - 1) : request.below_omega;
    if (request.is_below()) basis.widening = std::make_shared<BasisWidening>(bat);
  }
  if (!request.is_rigid_only())
    basis.flexibility = std::make_shared<const VibrationalFlexibility>(s, mass, basis.vectors.leftCols(2));
  basis.wall = barrel_wall(bat);
  for (const double d : bat.outer_diameter) basis.section_radius.push_back(d / 2);
  // About the long axis a section's polar moment is twice its diametral one: 2 rho I dz per slice.
  for (int i = 0; i < bat.slices(); ++i) basis.axial_moment_of_inertia += 2 * bat.slice_rotary_inertia(i);
  basis.loss_factor = bat.material.loss_factor;
  return basis;
}

namespace {

// The mode a fraction t of the way from a to b, each quantity linear (a itself at t = 0).
WallMode between(const WallMode& a, const WallMode& b, double t) {
  const auto at = [t](double x, double y) { return x + t * (y - x); };
  WallMode w = a;
  w.omega = at(a.omega, b.omega);
  w.stiffness = at(a.stiffness, b.stiffness);
  w.mass = at(a.mass, b.mass);
  w.loss_factor = at(a.loss_factor, b.loss_factor);
  w.spread = at(a.spread, b.spread);
  w.outer_radius = at(a.outer_radius, b.outer_radius);
  w.radius = at(a.radius, b.radius);
  w.thickness = at(a.thickness, b.thickness);
  w.hoop_modulus = at(a.hoop_modulus, b.hoop_modulus);
  w.axial_modulus = at(a.axial_modulus, b.axial_modulus);
  return w;
}

}  // namespace

std::optional<WallMode> ModalBasis::wall_at(double z) const {
  if (wall.empty() || std::isnan(z)) return std::nullopt;
  const int n = static_cast<int>(wall.size());
  const int slice = std::clamp(static_cast<int>(std::floor(z / length() * n)), 0, n - 1);
  if (!(wall[slice].mass > 0)) return std::nullopt;
  if (n == 1) return wall[slice];
  // Between slice centres as section_radius_at: past the first and last centres, the end slice's.
  const double x = std::clamp(z / length() * n - 0.5, 0.0, n - 1.0);
  const int i = std::min(static_cast<int>(x), n - 2);
  if (!(wall[i].mass > 0 && wall[i + 1].mass > 0)) return wall[slice];  // where the wall ends
  return between(wall[i], wall[i + 1], x - i);
}

double ModalBasis::section_radius_at(double z) const {
  if (section_radius.empty()) return 0;
  if (std::isnan(z)) return z;  // no section: an index from it would be undefined
  // Linear between slice centres, so that what the ball meets varies continuously along a taper
  // (a certification's scan locates its maximum between points).
  const int n = static_cast<int>(section_radius.size());
  const double x = std::clamp(z / length() * n - 0.5, 0.0, n - 1.0);
  const int i = std::min(static_cast<int>(x), n - 2 < 0 ? 0 : n - 2);
  if (n == 1) return section_radius[0];
  const double t = x - i;
  return section_radius[i] + t * (section_radius[i + 1] - section_radius[i]);
}

double ModalBasis::vibrational_compliance_at(double z) const {
  if (!flexibility) return 0;
  const PointLoad p = layout.point(z);
  const MatrixXd& band = flexibility->band();
  double sum = 0;
  for (int k = 0; k < 4; ++k)
    for (int l = 0; l < 4; ++l)
      if (p.weight[k] != 0 && p.weight[l] != 0)
        sum += p.weight[k] * p.weight[l] * band(std::min(p.dof[k], p.dof[l]), std::abs(p.dof[k] - p.dof[l]));
  return sum;
}

double ModalBasis::unsolved_compliance_at(double z) const {
  if (complete()) return 0;
  const Eigen::VectorXd shapes = shapes_at(z);
  double solved = 0;
  for (int n = 2; n < count(); ++n) solved += shapes(n) * shapes(n) / (omega(n) * omega(n));
  return std::max(0.0, vibrational_compliance_at(z) - solved);
}

double ModalBasis::unsolved_cross_compliance(double a, double b) const {
  if (complete() || !flexibility) return 0;
  const PointLoad at_a = layout.point(a), at_b = layout.point(b);
  VectorXd load = VectorXd::Zero(vectors.rows());
  for (int k = 0; k < 4; ++k) load(at_b.dof[k]) += at_b.weight[k];
  const VectorXd yield = flexibility->times(load);
  double all = 0;
  for (int k = 0; k < 4; ++k) all += at_a.weight[k] * yield(at_a.dof[k]);
  const VectorXd shapes_a = shapes_at(a), shapes_b = shapes_at(b);
  double solved = 0;
  for (int n = 2; n < count(); ++n) solved += shapes_a(n) * shapes_b(n) / (omega(n) * omega(n));
  return all - solved;
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

int vibrational_mode_count(int slices, BeamTheory theory) { return degrees_of_freedom(slices, theory) - 2; }

}  // namespace sweetspot
