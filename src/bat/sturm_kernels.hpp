#pragma once
// Internal: the inner loops of the Sturm counts (banded_eigensolver.cpp), eight shifts at once,
// built for each x86-64 vector unit as the exact stepper's loops are (contact/mode_kernels.hpp)
// and run on the path the library takes for those (detail::vector_path()). Every path makes the
// same operations in the same order on each shift, with no fused multiply-add, so that all count
// alike (tests/test_partial_modes.cpp).

namespace sweetspot::detail {

inline constexpr int sturm_shifts = 8;

// One slice of Timoshenko's K - x M: K's 2 x 2 block on the slice's (y, phi), the lumped mass and
// rotary inertia, and K between the previous slice's (y, phi) and this one's (row-major; zero
// for the first slice).
struct PencilBlock {
  double yy, yphi, phiphi, mass, inertia;
  double coupling[4];
};

// count[s]: how many pivots of the block LDL^T factorisation of K - x[s] M are negative (each 2 x 2
// pivot counted by its eigenvalues' signs), over the n blocks.
void pencil_counts(const PencilBlock* blocks, int n, const double* x, double* count);

// count[s]: how many pivots of T - x[s] I are negative, T the symmetric tridiagonal matrix of
// diagonal d (n entries) and squared off-diagonal e2 (n - 1 entries, each at least the smallest
// normal double).
void tridiagonal_counts(const double* d, const double* e2, int n, const double* x, double* count);

}  // namespace sweetspot::detail
