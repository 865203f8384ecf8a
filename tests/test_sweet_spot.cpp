// The sweet-spot reduction of v_f along z: on a v_f(z) that is a parabola it recovers the vertex
// and the zone's width exactly, between grid points of any spacing; it says NaN where the scan
// cannot tell (the peak at its end, the zone running off it, a failed point).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "sweetspot/study/sweet_spot.hpp"

using namespace sweetspot;

namespace {

// v_f = peak - c (z - vertex)^2: within fraction f of the peak over a width 2 sqrt(f peak / c).
struct Parabola {
  double vertex, peak, c;
  double operator()(double z) const { return peak - c * (z - vertex) * (z - vertex); }
  double width(double fraction) const { return 2 * std::sqrt(fraction * peak / c); }
};

std::vector<double> values(const Parabola& p, const std::vector<double>& z) {
  std::vector<double> vf;
  for (const double x : z) vf.push_back(p(x));
  return vf;
}

std::vector<double> grid(double start, double step, int n) {
  std::vector<double> z;
  for (int i = 0; i < n; ++i) z.push_back(start + i * step);
  return z;
}

}  // namespace

TEST_CASE("The sweet spot of a parabola is its vertex and its exact width, between grid points") {
  const Parabola p{0.7137, 45.0, 2500.0};  // about 19 cm wide at 1 %
  for (const double fraction : {0.01, 0.05, 0.2}) {
    // A 1-cm grid, a coarse 2.5-cm one, and an uneven one: the vertex is on none of them.
    std::vector<double> uneven{0.40, 0.43, 0.47, 0.52, 0.58, 0.61, 0.66, 0.69, 0.71, 0.75, 0.78, 0.80, 0.83, 0.835};
    for (const std::vector<double>& z : {grid(0.405, 0.01, 44), grid(0.40, 0.025, 18), uneven}) {
      const SweetSpot s = sweet_spot(z, values(p, z), fraction);
      CHECK(s.z == Approx(p.vertex).epsilon(1e-12));
      CHECK(s.vf == Approx(p.peak).epsilon(1e-12));
      if (p.vertex - p.width(fraction) / 2 > z.front() && p.vertex + p.width(fraction) / 2 < z.back()) {
        CHECK(s.width == Approx(p.width(fraction)).epsilon(1e-10));
        // (1 - f) / f from the ends' slopes, times the Lagrange weights' spread between grid points
        // (at most 1.25 on an even grid, more on an uneven one)
        CHECK(s.width_sensitivity >= (1 - fraction) / fraction * (1 - 1e-9));
        CHECK(s.width_sensitivity <= 1.5 * (1 - fraction) / fraction);
      } else {
        CHECK(std::isnan(s.width));  // the zone runs off the scan
      }
    }
  }
}

TEST_CASE("The width's sensitivity bounds its change when every speed errs by a small fraction") {
  const Parabola p{0.7137, 45.0, 2500.0};
  const std::vector<double> z = grid(0.405, 0.01, 44);
  const std::vector<double> exact = values(p, z);
  for (const double fraction : {0.01, 0.05}) {
    const SweetSpot s = sweet_spot(z, exact, fraction);
    const double e = 1e-7;
    double largest = 0;
    // Each speed up or down by e in patterns that move the ends most (the zone's ends up and the
    // peak down widen it) and in alternating ones.
    for (int pattern = 0; pattern < 64; ++pattern) {
      std::vector<double> vf = exact;
      for (std::size_t i = 0; i < vf.size(); ++i) {
        const bool near_peak = std::abs(z[i] - p.vertex) < s.width / 4;
        const int sign = pattern == 0 ? (near_peak ? -1 : 1) : pattern == 1 ? (near_peak ? 1 : -1)
                                                             : ((i * 7 + pattern) % 3 == 0 ? 1 : -1);
        vf[i] *= 1 + sign * e;
      }
      largest = std::max(largest, std::abs(sweet_spot(z, vf, fraction).width / s.width - 1));
    }
    INFO("fraction " << fraction << ": largest relative change " << largest << " per " << e);
    CHECK(largest <= s.width_sensitivity * e * (1 + 1e-3));  // first order in e
    CHECK(largest >= 0.5 * s.width_sensitivity * e);  // and not far above what can happen
  }
}

TEST_CASE("The sweet spot is NaN where the scan cannot tell where it is") {
  const Parabola p{0.7137, 45.0, 2500.0};
  const std::vector<double> z = grid(0.405, 0.01, 44);
  std::vector<double> vf = values(p, z);
  SECTION("a failed point on the line") {
    vf[3] = std::nan("");
    CHECK(std::isnan(sweet_spot(z, vf, 0.01).z));
  }
  SECTION("the largest v_f at an end of the scan") {
    const std::vector<double> rising = values({0.9, 45.0, 2500.0}, z);
    const SweetSpot s = sweet_spot(z, rising, 0.01);
    CHECK(std::isnan(s.z));
    CHECK(std::isnan(s.width));
  }
  SECTION("fewer than three points") {
    const std::vector<double> two{0.6, 0.7};
    CHECK(std::isnan(sweet_spot(two, values(p, two), 0.01).z));
  }
  SECTION("a zone wider than the scan keeps its peak") {
    const SweetSpot s = sweet_spot(z, vf, 0.9);
    CHECK(s.z == Approx(p.vertex).epsilon(1e-12));
    CHECK(std::isnan(s.width));
  }
}
