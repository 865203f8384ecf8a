#pragma once
// The lowest modes of the banded pencil K x = w^2 M x without the dense solve's O(n^3) (README,
// "Numerics"): Sturm counts bracket each eigenvalue wanted, and only those, within 1e-8 of its
// distance to the others; each eigenpair then comes from inverse iteration at that shift on the
// banded K - w^2 M itself (a band LU, O(n) per step), its eigenvalue the Rayleigh quotient. The
// counts run on the tridiagonal form LAPACK reduces the pencil to without forming the
// transformation (dsbtrd, as dsbgvx does, O(n^2) once), or, for Timoshenko requests of a few
// modes over many degrees of freedom, on the block LDL^T factorisation of K - x M itself (its M
// is diagonal, and K couples only neighbouring slices), O(n) each. Both theories' matrices couple
// degrees of freedom at most beam_bandwidth apart (beam_system.hpp).
#include <limits>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "bat/beam_system.hpp"

namespace sweetspot {

// Which eigenpairs: the lowest `count` (rigid ones included), or (count < 0) every one with
// w^2 <= upper.
struct BandedRequest {
  int count = -1;
  double upper = 0;
  bool diagonal_mass = false;  // Timoshenko's lumped M
  int most = std::numeric_limits<int>::max();  // more eigenpairs than this: nothing solved
};

// Beyond this share of all modes the dense solve may be the better buy. R161 (Timoshenko)
// measured by tests/benchmarks/bench_partial_modes.cpp's method, against the dense solve with its
// sparse rigid step: 80 of 168 modes cost 0.39 of the dense solve at N = 84 and 120 of 168 0.67;
// 160 of 336 0.31 at N = 168 and 240 of 336 0.48. The banded cost grows by about 17 us (N = 84)
// and 40 us (N = 168) per mode up there, so at this share it still costs less than the dense
// solve; the limit stays short of the spectrum's crowded top. (With every eigenvalue from dsterf
// and the dense rigid step, 80 of 168 cost 0.35; before the inline band LU and dsterf, 60 of 168
// cost as much as all 168, and 0.3 was the limit.)
inline constexpr double max_banded_share = 0.75;

// Ascending eigenvalues and M-normalised eigenvectors (columns) of the request. The two rigid
// modes come out as round-off; the caller replaces them by the exact ones. False, with nothing
// usable solved, when the request covers more than max_banded_share of the modes (the dense solve
// is then the cheaper) or more than request.most, when the bisection cannot bracket an eigenvalue
// apart from the others (eigenvalues equal to round-off), or when the vectors found cannot be
// made M-orthonormal: the dense solve then serves.
// `counted`, when given, receives how many eigenpairs the request covers (rigid ones included),
// solved or not.
bool solve_lowest(const BeamSystem& s, const Eigen::SparseMatrix<double>& mass, BandedRequest request,
                  Eigen::VectorXd& omega_squared, Eigen::MatrixXd& vectors, int* counted = nullptr);

// How many eigenvalues of the pencil lie below x (rigid ones included), by the Sturm count on
// K - x M (Timoshenko) or on the tridiagonal form (Euler-Bernoulli).
int count_below(const BeamSystem& s, bool diagonal_mass, double x);

}  // namespace sweetspot
