#pragma once
// Internal: the exact stepper's loops over the modes, written so that the compiler vectorises
// them across the modes (structure of arrays, no branch, no call but the sine and cosine).
#include <array>

namespace sweetspot::detail {

inline constexpr int interpolant_powers = 6;  // polynomials of degree up to 5
inline constexpr int interpolant_data = 6;    // the data they weight (Datum)

// Row j: the polynomial (coefficients of t^0..t^5) that datum j weights over the step.
using InterpolantBasis = std::array<std::array<double, interpolant_powers>, interpolant_data>;

// Where undamped_responses writes mode i's response: column arrays of n entries each.
struct ResponseColumns {
  double *c, *sn, *w2sn, *cv;
  std::array<double*, interpolant_data> d, q;
};

// The closed-form response over a step of length h of the n undamped modes of frequencies
// omega (ExactStepper's ModeResponse): the free evolution c = cos wh, sn = sin wh / w (h at
// w = 0), w2sn = w sin wh, cv = c, and the displacement d_j and velocity q_j a unit weight of
// datum j drives, d_j = sum_k b(j, k) P_k, q_j = sum_k b(j, k) Q_k, from the responses to t^k,
//   P_k = int_0^h sin(w (h - t)) / w t^k dt,  Q_k = int_0^h cos(w (h - t)) t^k dt.
// For w h >= 4 they follow upward from P_0 = (1 - cos) / w^2, Q_0 = sin / w by parts (Q_k = k
// P_(k-1), P_k = (h^k - k Q_(k-1)) / w^2). Below, that recursion cancels; there the power series
// of P_5 and Q_5 (Horner, a fixed number of terms) are run down by the same identities solved the
// other way, which is stable for small w h: in x = w h, p_k = P_k / h^(k+2), q_k = Q_k / h^(k+1),
//   p_(k-1) = q_k / k,  q_(k-1) = (1 - x^2 p_k) / k.
// Agrees with the term-by-term series within a few units in the last place (tests/test_mode_kernels.cpp).
void undamped_responses(const double* omega, int n, double h, const InterpolantBasis& b, const ResponseColumns& out);

}  // namespace sweetspot::detail
