#pragma once
// The discretised free-free beam (physics.md §2): stiffness and mass matrices of either theory,
// the rigid motions and the slices' rigidities. Internal to the modes' solvers.
#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "sweetspot/bat/bat.hpp"
#include "sweetspot/bat/beam_layout.hpp"

namespace sweetspot {

// Both theories' K and M couple degrees of freedom at most this far apart.
inline constexpr int beam_bandwidth = 3;

// A discretised free-free beam: K x = omega^2 M x, plus the degree-of-freedom vectors of the two
// rigid motions and the map from degrees of freedom to displacements at the slice centres. The
// matrices are stored sparse: each row couples at most beam_bandwidth neighbours, so that
// assembling them costs O(n), not the dense O(n^2) (512 MB each for 4096 slices); the dense solve
// makes its own dense copies.
struct BeamSystem {
  Eigen::SparseMatrix<double> stiffness;
  Eigen::SparseMatrix<double> mass;
  Eigen::VectorXd translation;     // y = 1 everywhere
  Eigen::VectorXd rotation_knob;   // y = z, cross-sections turned with it (rotation about the knob)
  Eigen::SparseMatrix<double> slice_displacement;  // rows: slice centres; maps x to y(z_i)
};

// Each slice's rigidities, and the length: what a point load needs of the beam (beam_layout.hpp).
BeamLayout beam_layout(const Bat& bat, BeamTheory theory);
BeamSystem timoshenko_system(const Bat& bat);
BeamSystem euler_bernoulli_system(const Bat& bat);

}  // namespace sweetspot
