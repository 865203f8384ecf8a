#pragma once
// The free-free beam's vibrational flexibility G = sum over every vibrational mode of
// x_n x_n^T / w_n^2 (the static compliance of all vibrational modes; physics.md §4), near its
// diagonal, from one banded linear solve and no eigen-decomposition. What a partial basis leaves
// unsolved at a point is then exact: G's part there minus the solved modes' psi^2 / w^2.
//
// Why it holds: with the full mass-orthonormal modes X, K = M X W^2 X^T M, and a load f that
// the rigid modes R do not feel (R^T f = 0) is statically balanced, so K u = f has solutions,
// among them the one with the beam held at the knob (both rigid motions fixed by the first two
// degrees of freedom): u = C f, C the inverse of K with those two removed. A point load w is
// made balanced by P = I - M R R^T (the rigid modes' share taken off); then w^T G w = (P w)^T C
// (P w), so G = P^T C P = C - V R^T - R V^T + R (R^T M V) R^T with V = C M R.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <memory>

#include "bat/beam_system.hpp"

namespace sweetspot {

class HeldBeam;

class VibrationalFlexibility {
 public:
  // `mass` is M's sparse copy; `rigid` holds the two exact M-orthonormal rigid modes
  // (ModalBasis::vectors' first two columns).
  VibrationalFlexibility(const BeamSystem& s, const Eigen::SparseMatrix<double>& mass, const Eigen::MatrixXd& rigid);

  // G(i, i + d) at (i, d) for d = 0 .. bandwidth (zero past the last degree of freedom): the
  // entries a point load, which reads at most bandwidth + 1 neighbouring degrees of freedom, needs.
  const Eigen::MatrixXd& band() const { return band_; }
  // G w, every degree of freedom's share of the vibrational modes' static yield under the load w:
  // P^T C P w, one banded solve, O(n kd). What two points far apart share (a held bat's pivot and
  // its struck point) lies outside the band.
  Eigen::VectorXd times(const Eigen::VectorXd& w) const;

 private:
  std::shared_ptr<const HeldBeam> held_;
  Eigen::MatrixXd rigid_, mass_rigid_, band_;
};

}  // namespace sweetspot
