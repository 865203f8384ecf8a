#pragma once
// The normal modes of a free-free bat (physics.md §2): Timoshenko (symmetric K x = w^2 M x on
// the slices) or Euler-Bernoulli (Hermite beam elements). Modes are mass-orthonormal; modes 0 and
// 1 are the exact rigid modes (translation, rotation about the centre of mass) with omega = 0.
#include <Eigen/Dense>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "sweetspot/bat/barrel_wall.hpp"
#include "sweetspot/bat/bat.hpp"
#include "sweetspot/bat/beam_layout.hpp"

namespace sweetspot {

class VibrationalFlexibility;

struct ModeRequest;
struct BasisWidening;  // what solves a partial basis's bat further (modes.cpp)

struct ModalBasis {
  BeamTheory theory = BeamTheory::timoshenko;
  std::vector<double> z;   // slice centres, m from the knob
  Eigen::VectorXd omega;   // angular frequencies, rad/s, ascending; omega(0) = omega(1) = 0
  Eigen::MatrixXd psi;     // psi(i, n): transverse displacement of mode n at slice centre i
  // Full mode vectors over the discretisation's degrees of freedom: Timoshenko (y_i, phi_i) per
  // slice; Euler-Bernoulli (w_j, w'_j) per slice boundary. vectors^T M vectors = identity.
  Eigen::MatrixXd vectors;
  // Modal velocities of the rigid motion y' = 1 (unit translation) and y' = z - z_cm, phi' = -1
  // (unit rotation about the centre of mass): a_n'(0) = v_cm * translation(n) + Omega * rotation(n).
  Eigen::VectorXd translation;
  Eigen::VectorXd rotation;
  // Mass properties of the discretised bat, consistent with the rigid modes.
  double mass = 0;
  double z_cm = 0;
  double moment_of_inertia_cm = 0;
  // Where the degrees of freedom sit and how stiff each slice is: how a point load reads them.
  BeamLayout layout;
  // A partial solve (ModeRequest) leaves the modes above this angular frequency unsolved (every
  // unsolved mode has omega >= solved_below); infinity when the basis is complete.
  double solved_below = std::numeric_limits<double>::infinity();
  // The vibrational flexibility G = sum_n x_n x_n^T / omega_n^2 over ALL vibrational modes, solved
  // or not (beam_flexibility.hpp): its band, and its product with any load. Null for a rigid-only
  // basis.
  std::shared_ptr<const VibrationalFlexibility> flexibility;
  // The barrel wall's hoop mode per slice (barrel_wall.hpp); empty for a solid bat.
  std::vector<WallMode> wall;
  // The bat's structural loss factor (Material::loss_factor): its vibrational modes' damping.
  double loss_factor = 0;
  // Outer radius of each slice, m: the surface the ball meets (Ball::curvature_factor).
  std::vector<double> section_radius;
  // The bat's moment of inertia about its own long axis, kg m^2 (the slices' rho (pi/2)(R2^4 - R1^4)
  // dz): how it rolls under a tangential force (oblique_impact.hpp). 0 when not known: no roll.
  double axial_moment_of_inertia = 0;
  // A basis solved below a frequency keeps its bat, to be solved further (widened); it and its
  // copies share what that solves. Null for any other basis.
  std::shared_ptr<BasisWidening> widening;

  int count() const { return static_cast<int>(omega.size()); }
  // Every mode of the discretisation solved (rigid-only bases are not).
  bool complete() const { return count() == vectors.rows(); }
  int slices() const { return static_cast<int>(z.size()); }
  double length() const { return layout.length; }
  // Every mode's displacement at any point z of the bat (layout.point's weights, not snapped).
  Eigen::VectorXd shapes_at(double z) const;
  // Static compliance sum psi_n(z)^2 / omega_n^2 of every vibrational mode at z, m/N, from the
  // flexibility: exact whether or not the modes were all solved.
  double vibrational_compliance_at(double z) const;
  // The part of it that the unsolved modes carry (0 for a complete basis): the total minus the
  // solved modes' psi^2 / omega^2, never below 0.
  double unsolved_compliance_at(double z) const;
  // What the unsolved modes share between two points: sum over them of psi_n(a) psi_n(b) /
  // omega_n^2, the displacement at a under a unit load at b (0 for a complete basis). At a = b,
  // unsolved_compliance_at(a) to round-off.
  double unsolved_cross_compliance(double a, double b) const;
  // The wall's hoop mode at z: linear between the slice centres around z where both slices are
  // hollow, as the section's radius is (an impact's result then varies continuously along a
  // taper: the slice's own mode jumped v_f by 1 % at every slice boundary), else its slice's;
  // nothing where that slice is solid.
  std::optional<WallMode> wall_at(double z) const;
  // The outer radius at z, m, linear between slice centres; 0 when the basis has no slices.
  double section_radius_at(double z) const;
  // Vibrational frequencies in Hz (modes 2, 3, ...), ascending.
  std::vector<double> vibrational_frequencies_hz() const;
  // The same bat solved below request.below_omega (a ModeRequest::below), for an impact that
  // needs more of its modes than this partial basis holds (a ball caught again, impact.cpp):
  // solved once per frequency, thread-safely, and kept with this basis. This basis itself where
  // it reaches that far already, is not partial, or cannot be solved further in practice.
  const ModalBasis& widened(const ModeRequest& request) const;
  // Zeros of psi_n between slice centres, found by linear interpolation, m from the knob.
  std::vector<double> nodes(int n) const;
};

// The dense Euler-Bernoulli solve loses the lowest frequencies to round-off as the highest grow
// (as N^4): f1 of R161 errs 2e-6 at 420 slices, 5e-5 at 672 and 1e-3 at 1344, against 1e-8 up
// to 336. More slices than this are refused for that theory.
inline constexpr int max_euler_bernoulli_slices = 400;

// Which modes compute_modes solves for. all(): every mode, by the dense solve. rigid_only(): the
// two rigid modes alone, from the mass matrix (no eigen-decomposition), for scenes that keep no
// vibrational mode. lowest(k): the k lowest vibrational modes; below(omega): every vibrational
// mode below omega (rad/s). Those two use the banded solver (banded_eigensolver.hpp) and leave a
// partial basis; a request that covers every mode takes the dense solve.
struct ModeRequest {
  int vibrational = -1;  // -1: all; otherwise the count (lowest) or -2 for below
  double below_omega = 0;

  static ModeRequest all() { return {}; }
  static ModeRequest rigid_only() { return {0, 0}; }
  static ModeRequest lowest(int count) { return {count, 0}; }
  static ModeRequest below(double omega) { return {-2, omega}; }
  bool is_all() const { return vibrational == -1; }
  bool is_rigid_only() const { return vibrational == 0; }
  bool is_below() const { return vibrational == -2; }
};

// What an eigen-solve may cost. The full (dense) solve's time grows as the cube of the slices
// (Timoshenko, one core: 0.6 s at 512 slices, about 7 s at 1024, about 60 s at 2048 and 8 min at
// 4096): every mode is solved up to max_full_solve_slices. A partial solve of K modes over n
// degrees of freedom costs about n K^2 (its orthonormalisation; 3.3 s for 1000 modes at 4096
// slices on a Zen 3 core, 9.0 s with the Gram-Schmidt pass it had when this limit was set), so it
// may ask for as many as costs the full solve at that limit, (2 * 1024)^3 = n K^2.
inline constexpr int max_full_solve_slices = 1024;
// The most modes (rigid included) a solve over `dofs` degrees of freedom may ask: all of them
// while the full solve is practical.
int practical_mode_count(int dofs);
// Why solving `request` over `slices` slices would take longer than is practical (a clause for an
// error line), or nothing. A request below a frequency is known only once its modes are counted:
// compute_modes refuses it then.
std::optional<std::string> impractical_solve(int slices, BeamTheory theory, ModeRequest request);

// Throws InputError for an Euler-Bernoulli bat of more than max_euler_bernoulli_slices slices and
// for a request that impractical_solve refuses (or, below a frequency, that asks more modes than
// practical_mode_count).
ModalBasis compute_modes(const Bat& bat, BeamTheory theory, ModeRequest request = ModeRequest::all());

// The discretisation's mass matrix M (diagonal for Timoshenko, consistent for Euler-Bernoulli).
Eigen::MatrixXd beam_mass_matrix(const Bat& bat, BeamTheory theory);

// Vibrational modes a discretisation has: Timoshenko has two degrees of freedom per slice,
// Euler-Bernoulli two per slice boundary; two modes are rigid.
int vibrational_mode_count(int slices, BeamTheory theory);

const char* to_string(BeamTheory theory);
// Throws InputError for anything but "timoshenko" or "euler-bernoulli".
BeamTheory parse_beam_theory(const std::string& text);

}  // namespace sweetspot
