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

#include "bat/beam_system.hpp"

namespace sweetspot {

// G(i, i + d) for d = 0 .. bandwidth (zero past the last degree of freedom): the entries a point
// load, which reads at most bandwidth + 1 neighbouring degrees of freedom, needs. `mass` is M's
// sparse copy; `rigid` holds the two exact M-orthonormal rigid modes (ModalBasis::vectors' first
// two columns).
Eigen::MatrixXd vibrational_flexibility_band(const BeamSystem& s, const Eigen::SparseMatrix<double>& mass,
                                             const Eigen::MatrixXd& rigid);

}  // namespace sweetspot
