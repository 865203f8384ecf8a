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
      if (p.vertex - p.width(fraction) / 2 > z.front() && p.vertex + p.width(fraction) / 2 < z.back())
        CHECK(s.width == Approx(p.width(fraction)).epsilon(1e-10));
      else
        CHECK(std::isnan(s.width));  // the zone runs off the scan
    }
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
