#pragma once
// The discretised free-free beam (physics.md §2): stiffness and mass matrices of either theory,
// the rigid motions and the slices' rigidities. Internal to the modes' solvers.
#include <Eigen/Dense>

#include "sweetspot/bat/bat.hpp"
#include "sweetspot/bat/beam_layout.hpp"

namespace sweetspot {

// A discretised free-free beam: K x = omega^2 M x, plus the degree-of-freedom vectors of the two
// rigid motions and the map from degrees of freedom to displacements at the slice centres.
struct BeamSystem {
  Eigen::MatrixXd stiffness;
  Eigen::MatrixXd mass;
  Eigen::VectorXd translation;     // y = 1 everywhere
  Eigen::VectorXd rotation_knob;   // y = z, cross-sections turned with it (rotation about the knob)
  Eigen::MatrixXd slice_displacement;  // rows: slice centres; maps x to y(z_i)
};

// Each slice's rigidities, and the length: what a point load needs of the beam (beam_layout.hpp).
BeamLayout beam_layout(const Bat& bat, BeamTheory theory);
BeamSystem timoshenko_system(const Bat& bat);
BeamSystem euler_bernoulli_system(const Bat& bat);

}  // namespace sweetspot
