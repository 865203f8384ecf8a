#include "sweetspot/study/sweet_spot.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace sweetspot {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// The parabola y = c0 + c1 (x - x1) + c2 (x - x1)^2 through three points (Newton's form, centred
// on the middle one for round-off).
struct Parabola {
  double x1, c0, c1, c2;

  Parabola(const double* x, const double* y) : x1(x[1]), c0(y[1]) {
    const double d01 = (y[1] - y[0]) / (x[1] - x[0]), d12 = (y[2] - y[1]) / (x[2] - x[1]);
    c2 = (d12 - d01) / (x[2] - x[0]);
    c1 = d01 + c2 * (x[1] - x[0]);  // the slope at x1
  }
  double vertex() const { return x1 - c1 / (2 * c2); }
  double operator()(double x) const { return c0 + (x - x1) * (c1 + c2 * (x - x1)); }
  // Where it equals `level` within [a, b] (the root nearer the bracket's middle).
  double crossing(double level, double a, double b) const {
    const double c = c0 - level;
    if (c2 == 0) return x1 - c / c1;
    const double root = std::sqrt(std::max(0.0, c1 * c1 - 4 * c2 * c));
    // The two roots, each written so as not to subtract nearly equal numbers.
    const double q = -0.5 * (c1 + std::copysign(root, c1));
    const double r1 = x1 + q / c2, r2 = q != 0 ? x1 + c / q : r1;
    const double middle = 0.5 * (a + b);
    return std::abs(r1 - middle) <= std::abs(r2 - middle) ? r1 : r2;
  }
};

// The parabola through the three points that hold the bracket [i, i + 1], as centred as the line allows.
Parabola around(std::span<const double> z, std::span<const double> vf, std::size_t i) {
  const std::size_t first = std::clamp<std::size_t>(i == 0 ? 0 : i - 1, 0, z.size() - 3);
  return {&z[first], &vf[first]};
}

}  // namespace

SweetSpot sweet_spot(std::span<const double> z, std::span<const double> vf, double fraction) {
  const std::size_t n = z.size();
  if (n < 3 || std::ranges::any_of(vf, [](double v) { return !std::isfinite(v); })) return {nan, nan, nan};
  const std::size_t top = static_cast<std::size_t>(std::ranges::max_element(vf) - vf.begin());
  if (top == 0 || top + 1 == n) return {nan, nan, nan};
  const Parabola peak(&z[top - 1], &vf[top - 1]);
  SweetSpot s{peak.vertex(), peak(peak.vertex()), nan};
  const double level = (1 - fraction) * s.vf;
  std::size_t left = top, right = top;
  while (left > 0 && vf[left - 1] >= level) --left;
  while (right + 1 < n && vf[right + 1] >= level) ++right;
  if (left == 0 || right + 1 == n) return s;  // the zone runs off the scan
  const double from = around(z, vf, left - 1).crossing(level, z[left - 1], z[left]);
  const double to = around(z, vf, right).crossing(level, z[right], z[right + 1]);
  s.width = to - from;
  return s;
}

}  // namespace sweetspot
