#include "sweetspot/bat/profile.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "sweetspot/input_error.hpp"

namespace sweetspot {

namespace {

double sign(double x) { return (x > 0) - (x < 0); }

// The end slope of the three-point formula, kept shape-preserving (scipy's PchipInterpolator).
double pchip_end_slope(double h0, double h1, double m0, double m1) {
  double d = ((2 * h0 + h1) * m0 - h0 * m1) / (h0 + h1);
  if (sign(d) != sign(m0)) return 0;
  if (sign(m0) != sign(m1) && std::abs(d) > 3 * std::abs(m0)) return 3 * m0;
  return d;
}

// Fritsch-Butland slopes: zero at a local extremum, else the weighted harmonic mean of the
// neighbouring secants, which keeps the cubic between its knots' values.
std::vector<double> pchip_slopes(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  std::vector<double> d(n, 0.0);
  if (n < 2) return d;
  std::vector<double> h(n - 1), m(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) h[k] = x[k + 1] - x[k], m[k] = (y[k + 1] - y[k]) / h[k];
  if (n == 2) return {m[0], m[0]};
  for (std::size_t k = 1; k + 1 < n; ++k) {
    if (m[k - 1] * m[k] <= 0) continue;
    const double w1 = 2 * h[k] + h[k - 1], w2 = h[k] + 2 * h[k - 1];
    d[k] = (w1 + w2) / (w1 / m[k - 1] + w2 / m[k]);
  }
  d[0] = pchip_end_slope(h[0], h[1], m[0], m[1]);
  d[n - 1] = pchip_end_slope(h[n - 2], h[n - 3], m[n - 2], m[n - 3]);
  return d;
}

// One diameter (outer or inner) along the bat, the slopes worked out once.
class Curve {
 public:
  Curve(Interpolation how, const std::vector<double>& z, const std::vector<double>& v)
      : how_(how), z_(z), v_(v), slope_(how == Interpolation::pchip ? pchip_slopes(z, v) : std::vector<double>{}) {}

  double operator()(double z) const {
    if (z <= z_.front()) return v_.front();
    if (z >= z_.back()) return v_.back();
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(z_.begin(), z_.end(), z) - z_.begin()) - 1;
    const double h = z_[k + 1] - z_[k], t = (z - z_[k]) / h;
    switch (how_) {
      case Interpolation::stepped: return t < 0.5 ? v_[k] : v_[k + 1];
      case Interpolation::linear: return (1 - t) * v_[k] + t * v_[k + 1];
      case Interpolation::pchip: break;
    }
    const double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * v_[k] + (t3 - 2 * t2 + t) * h * slope_[k] + (-2 * t3 + 3 * t2) * v_[k + 1] +
           (t3 - t2) * h * slope_[k + 1];
  }

  // Where the curve's pieces meet: knots, or for steps the midpoints between them.
  std::vector<double> breaks() const {
    if (how_ != Interpolation::stepped) return z_;
    std::vector<double> mid;
    for (std::size_t k = 0; k + 1 < z_.size(); ++k) mid.push_back((z_[k] + z_[k + 1]) / 2);
    return mid;
  }

 private:
  Interpolation how_;
  const std::vector<double>& z_;
  const std::vector<double>& v_;
  std::vector<double> slope_;
};

// 7-point Gauss-Legendre on [0, 1]: exact for degree 13, so for D^4 of a cubic piece.
constexpr std::array<double, 7> gl_x = {0.0254460438286207, 0.1292344072003028, 0.2970774243113014, 0.5,
                                        0.7029225756886986, 0.8707655927996972, 0.9745539561713793};
constexpr std::array<double, 7> gl_w = {0.0647424830844348, 0.1398526957446384, 0.1909150252525595,
                                        0.2089795918367347, 0.1909150252525595, 0.1398526957446384,
                                        0.0647424830844348};

// Calls f(z, weight, outer, inner) at the Gauss-Legendre points of each piece of [a, b] between
// the curves' breaks, the weights summing to b - a: every integral over the shape goes through it.
template <class F>
void integrate(const Curve& outer, const Curve* inner, const std::vector<double>& breaks, double a, double b,
               F&& f) {
  std::vector<double> cuts = {a};
  for (double x : breaks)
    if (x > a && x < b) cuts.push_back(x);
  cuts.push_back(b);
  for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
    const double width = cuts[p + 1] - cuts[p];
    for (std::size_t j = 0; j < gl_x.size(); ++j) {
      const double z = cuts[p] + gl_x[j] * width;
      f(z, gl_w[j] * width, outer(z), inner ? (*inner)(z) : 0.0);
    }
  }
}

// A section's area A and second moment I times a weight, in this order of operations (the
// slices of every bat file stay the same to the last bit).
double weighted_area(double w, double d, double di) { return w * std::numbers::pi / 4 * (d * d - di * di); }
double weighted_second_moment(double w, double d, double di) {
  return w * std::numbers::pi / 64 * (d * d * d * d - di * di * di * di);
}

// The outer and inner curves of a profile, which share its knots and so break at the same places.
struct Shape {
  Curve outer, inner;
  bool hollow;
  std::vector<double> breaks;

  explicit Shape(const Profile& p)
      : outer(p.interpolation, p.z, p.outer),
        inner(p.interpolation, p.z, p.inner.empty() ? p.outer : p.inner),
        hollow(!p.inner.empty()),
        breaks(outer.breaks()) {}

  template <class F>
  void integrate(double a, double b, F&& f) const {
    sweetspot::integrate(outer, hollow ? &inner : nullptr, breaks, a, b, std::forward<F>(f));
  }
};

struct SliceMeans {
  double outer = 0, inner = 0, area = 0, second_moment = 0;
};

SliceMeans slice_means(const Shape& shape, double a, double b) {
  SliceMeans s;
  shape.integrate(a, b, [&](double, double weight, double d, double di) {
    const double w = weight / (b - a);
    s.outer += w * d;
    s.inner += w * di;
    s.area += weighted_area(w, d, di);
    s.second_moment += weighted_second_moment(w, d, di);
  });
  return s;
}

}  // namespace

double Profile::diameter(double at, bool of_inner) const {
  if (of_inner && this->inner.empty()) return 0;
  return Curve(interpolation, z, of_inner ? this->inner : outer)(at);
}

void cut_into_slices(const Profile& profile, int slices, Bat& bat) {
  const Shape shape(profile);
  for (auto* v : {&bat.outer_diameter, &bat.inner_diameter, &bat.section_area, &bat.section_second_moment})
    v->clear();
  const double dz = bat.length / slices;
  for (int i = 0; i < slices; ++i) {
    const SliceMeans m = slice_means(shape, i * dz, (i + 1) * dz);
    bat.outer_diameter.push_back(m.outer);
    if (shape.hollow) bat.inner_diameter.push_back(m.inner);
    bat.section_area.push_back(m.area);
    bat.section_second_moment.push_back(m.second_moment);
  }
}

MassProperties mass_properties(const Profile& profile, double length, double density) {
  const Shape shape(profile);
  MassProperties p;
  double first_moment = 0;
  shape.integrate(0, length, [&](double z, double w, double d, double di) {
    const double m = density * weighted_area(w, d, di);
    p.mass += m;
    first_moment += m * z;
  });
  p.z_cm = first_moment / p.mass;
  // A second pass about the CM itself: no cancellation between large moments about the knob.
  shape.integrate(0, length, [&](double z, double w, double d, double di) {
    p.moment_of_inertia_cm +=
        density * (weighted_area(w, d, di) * (z - p.z_cm) * (z - p.z_cm) + weighted_second_moment(w, d, di));
  });
  return p;
}

namespace {

// The smallest value over [0, 1] of the cubic through f(0), f(1/3), f(2/3), f(1), and where: at an
// end or where its slope vanishes. Exact for pchip's difference of two cubic pieces.
std::pair<double, double> cubic_minimum(const std::array<double, 4>& f) {
  const double b = (-11 * f[0] + 18 * f[1] - 9 * f[2] + 2 * f[3]) / 2;
  const double c = (18 * f[0] - 45 * f[1] + 36 * f[2] - 9 * f[3]) / 2;
  const double d = (-9 * f[0] + 27 * f[1] - 27 * f[2] + 9 * f[3]) / 2;
  const auto at = [&](double t) { return f[0] + t * (b + t * (c + t * d)); };
  std::pair<double, double> best = f[0] <= f[3] ? std::pair{f[0], 0.0} : std::pair{f[3], 1.0};
  std::vector<double> stationary;  // roots of b + 2 c t + 3 d t^2
  if (std::abs(d) > 1e-300) {
    const double disc = c * c - 3 * b * d;
    if (disc >= 0)
      for (const double sign : {-1.0, 1.0}) stationary.push_back((-c + sign * std::sqrt(disc)) / (3 * d));
  } else if (std::abs(c) > 1e-300) {
    stationary.push_back(-b / (2 * c));
  }
  for (const double t : stationary)
    if (t > 0 && t < 1 && at(t) < best.first) best = {at(t), t};
  return best;
}

}  // namespace

ThinnestWall thinnest_wall(const Profile& profile) {
  ThinnestWall thinnest{0, profile.z.front(), profile.outer.front() - profile.inner.front()};
  const auto wall = [&](double z) { return profile.diameter(z) - profile.diameter(z, true); };
  for (std::size_t i = 0; i + 1 < profile.z.size(); ++i) {
    const double a = profile.z[i], h = profile.z[i + 1] - a;
    if (h <= 0) continue;  // a step: both sides are knots of their own intervals
    // Lines (linear, stepped) are thinnest at their knots; the cubic's ends are the knots too.
    std::pair<double, double> least = {profile.outer[i + 1] - profile.inner[i + 1], 1.0};
    if (profile.outer[i] - profile.inner[i] < least.first) least = {profile.outer[i] - profile.inner[i], 0.0};
    if (profile.interpolation == Interpolation::pchip)
      least = cubic_minimum({wall(a), wall(a + h / 3), wall(a + 2 * h / 3), wall(a + h)});
    if (least.first < thinnest.wall) thinnest = {i, a + least.second * h, least.first};
  }
  return thinnest;
}

const char* to_string(Interpolation interpolation) {
  switch (interpolation) {
    case Interpolation::stepped: return "stepped";
    case Interpolation::linear: return "linear";
    case Interpolation::pchip: return "pchip";
  }
  return "";
}

Interpolation parse_interpolation(const std::string& text) {
  for (Interpolation i : {Interpolation::stepped, Interpolation::linear, Interpolation::pchip})
    if (text == to_string(i)) return i;
  throw InputError("interpolation '" + text + "': expected 'stepped', 'linear' or 'pchip'");
}

}  // namespace sweetspot
