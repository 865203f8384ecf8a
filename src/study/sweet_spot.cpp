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
  const double *xs, *ys;  // the three points

  Parabola(const double* x, const double* y) : x1(x[1]), c0(y[1]), xs(x), ys(y) {
    const double d01 = (y[1] - y[0]) / (x[1] - x[0]), d12 = (y[2] - y[1]) / (x[2] - x[1]);
    c2 = (d12 - d01) / (x[2] - x[0]);
    c1 = d01 + c2 * (x[1] - x[0]);  // the slope at x1
  }
  double vertex() const { return x1 - c1 / (2 * c2); }
  double operator()(double x) const { return c0 + (x - x1) * (c1 + c2 * (x - x1)); }
  double slope(double x) const { return c1 + 2 * c2 * (x - x1); }
  // The most its value at x moves when each point's y moves by e |y| (over e): sum |l_i(x) y_i|
  // over the Lagrange weights l_i, whose sum of magnitudes exceeds 1 between the points.
  double spread(double x) const {
    double sum = 0;
    for (int i = 0; i < 3; ++i) {
      double weight = 1;
      for (int j = 0; j < 3; ++j)
        if (j != i) weight *= (x - xs[j]) / (xs[i] - xs[j]);
      sum += std::abs(weight * ys[i]);
    }
    return sum;
  }
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
  if (n < 3 || std::ranges::any_of(vf, [](double v) { return !std::isfinite(v); })) return {nan, nan, nan, nan};
  const std::size_t top = static_cast<std::size_t>(std::ranges::max_element(vf) - vf.begin());
  if (top == 0 || top + 1 == n) return {nan, nan, nan, nan};
  const Parabola peak(&z[top - 1], &vf[top - 1]);
  SweetSpot s{peak.vertex(), peak(peak.vertex()), nan, nan};
  const double level = (1 - fraction) * s.vf;
  std::size_t left = top, right = top;
  while (left > 0 && vf[left - 1] >= level) --left;
  while (right + 1 < n && vf[right + 1] >= level) ++right;
  if (left == 0 || right + 1 == n) return s;  // the zone runs off the scan
  const Parabola rising = around(z, vf, left - 1), falling = around(z, vf, right);
  const double from = rising.crossing(level, z[left - 1], z[left]);
  const double to = falling.crossing(level, z[right], z[right + 1]);
  s.width = to - from;
  // Each end moves by the speed's error there less the level's, (1 - fraction) times the peak's.
  const double level_spread = (1 - fraction) * peak.spread(s.z);
  s.width_sensitivity = ((rising.spread(from) + level_spread) / std::abs(rising.slope(from)) +
                         (falling.spread(to) + level_spread) / std::abs(falling.slope(to))) /
                        s.width;
  return s;
}

}  // namespace sweetspot
