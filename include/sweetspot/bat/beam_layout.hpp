#pragma once
// The discretised beam as a point load sees it (physics.md §2, §4). The modes give displacements
// at the discretisation's nodes (slice centres for Timoshenko, slice boundaries for
// Euler-Bernoulli); a ball may strike anywhere between them. The displacement there is read from
// the nodes' degrees of freedom with fixed weights, and the same weights spread the ball's force
// over them, so the work the force does is the work the modes receive and energy stays exact.
// A point load inside a segment also bends that segment locally, in a way no interpolation of
// nodal values carries: with the nodes held, the segment yields like a beam clamped at both ends
// (a cantilever on the end half-slices beyond the outermost Timoshenko nodes). That yield is a
// massless spring in series with the ball, as the dropped modes' residual compliance is; without
// it the impact point's stiffness converges only at first order between nodes.
#include <array>
#include <vector>

namespace sweetspot {

enum class BeamTheory { timoshenko, euler_bernoulli };

struct PointLoad {
  std::array<int, 4> dof{};          // degrees of freedom the point reads
  std::array<double, 4> weight{};    // y(z) = sum_k weight_k x[dof_k]; unused entries have weight 0
  double compliance = 0;             // m/N: the segment's own yield under a load at z
};

struct BeamLayout {
  BeamTheory theory = BeamTheory::timoshenko;
  double length = 0;                 // m
  std::vector<double> bending;       // Y I of each slice, N m^2
  std::vector<double> shear;         // kappa S A of each slice, N

  int slices() const { return static_cast<int>(bending.size()); }
  // How a point load at z (clamped to the bat) acts on the degrees of freedom. At a Timoshenko
  // slice centre it reads that slice's y alone, with no compliance.
  PointLoad point(double z) const;
};

// The rigidity of the joint between two slices of rigidities a and b: the two half-slices act as
// springs in series, so a stepped profile is represented exactly (the harmonic mean).
double joint_rigidity(double a, double b);

}  // namespace sweetspot
