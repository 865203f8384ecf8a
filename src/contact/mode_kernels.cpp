#include "contact/mode_kernels.hpp"

#include <cmath>

namespace sweetspot::detail {

namespace {

constexpr int powers = interpolant_powers, data = interpolant_data;

// Terms of the series of p_5 and q_5 in y = -x^2 (x = w h < 4): the last one's weight, 16^15 /
// 37!, is 1e-23 of the first's.
constexpr int series_terms = 16;

// 5! / (2j + first)! for j = 0 .. series_terms - 1.
constexpr std::array<double, series_terms> series_coefficients(int first) {
  std::array<double, series_terms> c{};
  double factorial = 1;  // (2j + first)!
  for (int m = 2; m <= first; ++m) factorial *= m;
  for (int j = 0; j < series_terms; ++j) {
    c[j] = 120 / factorial;
    factorial *= (2 * j + first + 1) * (2 * j + first + 2);
  }
  return c;
}
// p_5(x) = 5! sum_j y^j / (2j + 7)!,  q_5(x) = 5! sum_j y^j / (2j + 6)!.
constexpr std::array<double, series_terms> p5_series = series_coefficients(7), q5_series = series_coefficients(6);

}  // namespace

void undamped_responses(const double* omega, int n, double h, const InterpolantBasis& b, const ResponseColumns& out) {
  // The sine and cosine first, as the library computes them (the free evolution is then that of
  // any other path), into the columns the loop below reads them from.
  for (int i = 0; i < n; ++i) {
    const double x = omega[i] * h;
    out.c[i] = std::cos(x);
    out.sn[i] = std::sin(x);
  }
  double hp[powers + 2] = {1};  // h^0 .. h^7
  for (int k = 1; k < powers + 2; ++k) hp[k] = hp[k - 1] * h;
  const double inverse[powers] = {0, 1, 1 / 2.0, 1 / 3.0, 1 / 4.0, 1 / 5.0};
  double *c = out.c, *sn = out.sn, *w2sn = out.w2sn, *cv = out.cv;
#pragma omp simd
  for (int i = 0; i < n; ++i) {
    const double w = omega[i], x = w * h, cos_x = c[i], sin_x = sn[i];
    // Small w h: p_5, q_5 by Horner, then down to k = 0.
    const double x2 = x * x, y = -x2;
    double ps[powers], qs[powers];
    ps[5] = p5_series[series_terms - 1], qs[5] = q5_series[series_terms - 1];
    for (int j = series_terms - 2; j >= 0; --j) ps[5] = ps[5] * y + p5_series[j], qs[5] = qs[5] * y + q5_series[j];
    for (int k = 5; k >= 1; --k) {
      ps[k - 1] = qs[k] * inverse[k];
      qs[k - 1] = (1 - x2 * ps[k]) * inverse[k];
    }
    // Large w h: up from k = 0 by parts.
    const double w2 = w * w;
    double pr[powers], qr[powers];
    pr[0] = (1 - cos_x) / w2;
    qr[0] = sin_x / w;
    for (int k = 1; k < powers; ++k) {
      qr[k] = k * pr[k - 1];
      pr[k] = (hp[k] - k * qr[k - 1]) / w2;
    }
    const bool large = x >= 4;
    double p[powers], q[powers];
    for (int k = 0; k < powers; ++k) {
      p[k] = large ? pr[k] : hp[k + 2] * ps[k];
      q[k] = large ? qr[k] : hp[k + 1] * qs[k];
    }
    for (int j = 0; j < data; ++j) {
      double dj = 0, qj = 0;
      for (int k = 0; k < powers; ++k) dj += b[j][k] * p[k], qj += b[j][k] * q[k];
      out.d[j][i] = dj;
      out.q[j][i] = qj;
    }
    c[i] = cos_x;
    sn[i] = w == 0 ? h : sin_x / w;
    w2sn[i] = w * sin_x;
    cv[i] = cos_x;
  }
}

}  // namespace sweetspot::detail
