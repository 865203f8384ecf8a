#pragma once
// Internal: the exact stepper's loops over the modes, written so that the compiler vectorises
// them across the modes (structure of arrays, no branch, no call but the sine and cosine), and
// built for each of the x86-64 vector units, SSE2 (any x86-64), AVX2 and AVX-512, the one the
// running processor has taken at run time (mode_kernels.cpp). Every path makes the same
// operations in the same order on each mode, with no fused multiply-add and fixed-order sums, so
// that all give the same results bit for bit (tests/test_mode_kernels.cpp).

namespace sweetspot::detail {

inline constexpr int interpolant_powers = 6;  // polynomials of degree up to 5
inline constexpr int interpolant_data = 6;    // the data they weight (Datum)

// Where undamped_responses writes mode i's response: column arrays of n entries each.
struct ResponseColumns {
  double *c, *sn, *w2sn, *cv;
  double* d[interpolant_data];
  double* q[interpolant_data];
};

// The closed-form response over a step of length h of the n undamped modes of frequencies
// omega (ExactStepper's ModeResponse): the free evolution c = cos wh, sn = sin wh / w (h at
// w = 0), w2sn = w sin wh, cv = c, and the displacement d_j and velocity q_j a unit weight of
// datum j drives, d_j = sum_k b(j, k) P_k, q_j = sum_k b(j, k) Q_k (basis: b row-major, row j the
// polynomial in t that datum j weights), from the responses to t^k,
//   P_k = int_0^h sin(w (h - t)) / w t^k dt,  Q_k = int_0^h cos(w (h - t)) t^k dt.
// For w h >= 4 they follow upward from P_0 = (1 - cos) / w^2, Q_0 = sin / w by parts (Q_k = k
// P_(k-1), P_k = (h^k - k Q_(k-1)) / w^2). Below, that recursion cancels; there the power series
// of P_5 and Q_5 (Horner, a fixed number of terms) are run down by the same identities solved the
// other way, which is stable for small w h: in x = w h, p_k = P_k / h^(k+2), q_k = Q_k / h^(k+1),
//   p_(k-1) = q_k / k,  q_(k-1) = (1 - x^2 p_k) / k.
// Agrees with the integrals within 1e-13 of their size (tests/test_mode_kernels.cpp).
void undamped_responses(const double* omega, int n, double h, const double* basis, const ResponseColumns& out);

// One exact step's pass over the modes before the end force is known: for each mode
//   a = c a0 + sn v0 - psi sum_j data_j d_j,  v = cv v0 - w2sn a0 - psi sum_j data_j q_j
// over the past and start data (j = 0..3: past force and rate, start force and rate), and the
// sums sum psi a, sum psi v, sum psi_w2 a0.
struct StepArrays {
  const double *a0, *v0, *c, *sn, *w2sn, *cv, *psi, *psi_w2;
  const double* d[4];
  const double* q[4];
  double *a, *v;
};
struct StepSums {
  double psi_a = 0, psi_v = 0, psi_w2a = 0;
};
StepSums step_known(int n, const StepArrays& s, const double (&data)[4]);
// The pass after it: a -= psi (f1 dC + r1 dD), v -= psi (f1 qC + r1 qD).
void step_end(int n, double* a, double* v, const double* psi, const double* dC, const double* dD, const double* qC,
              const double* qD, double f1, double r1);

// The vector units a path takes; the library takes the widest the processor has.
enum class VectorPath { sse2, avx2, avx512 };
const char* to_string(VectorPath path);
VectorPath vector_path();
bool vector_path_supported(VectorPath path);
// Takes that path from now on (tests compare the paths); false, and no change, if the processor
// or the build has it not.
bool use_vector_path(VectorPath path);

}  // namespace sweetspot::detail
