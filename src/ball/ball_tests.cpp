#include "sweetspot/ball/ball_tests.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <utility>

#include "sweetspot/input_error.hpp"
#include "toml_values.hpp"

namespace sweetspot {

namespace {

[[noreturn]] void reject(const std::string& where, const std::string& key, double value, const std::string& expected) {
  throw InputError(where + ": " + key + " = " + detail::format_number(value) + ": " + expected);
}

void require_in(const std::string& where, const std::string& key, double value, double lo, double hi,
                const std::string& expected) {
  if (!(value > lo && value <= hi)) reject(where, key, value, expected);
}

void require_in(const std::string& where, const std::string& key, double value, BallRange range) {
  if (!in_range(range, value)) reject(where, key, value, "expected " + range_text(range));
}

// The least-squares line y = intercept + slope (x - mean x), its mean x and RMS residual.
struct Line {
  double mean_x = 0, intercept = 0, slope = 0, rms = 0;
};

Line fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  Line line;
  const double n = static_cast<double>(x.size());
  line.mean_x = std::accumulate(x.begin(), x.end(), 0.0) / n;
  line.intercept = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - line.mean_x) * (y[i] - line.intercept);
    sxx += (x[i] - line.mean_x) * (x[i] - line.mean_x);
  }
  line.slope = sxx > 0 ? sxy / sxx : 0;
  double squares = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double r = y[i] - (line.intercept + line.slope * (x[i] - line.mean_x));
    squares += r * r;
  }
  line.rms = std::sqrt(squares / n);
  return line;
}

void fit_cor(const BallTests& t, const std::string& where, BallFit& fit) {
  if (t.cor.empty()) throw InputError(where + ": cor is missing: expected the COR on a flat rigid wall (ASTM F1887)");
  std::vector<double> speeds, cors;
  for (const SpeedValue& p : t.cor) {
    require_in(where, "cor_speed", p.speed, 0, max_cor_law_speed, "expected a speed in (0, 100] m/s");
    require_in(where, "cor", p.value, ball_cor_range);
    speeds.push_back(p.speed), cors.push_back(p.value);
  }
  if (t.cor.size() > 1 && t.cor_slope != 0)
    reject(where, "cor_slope", t.cor_slope, "give it with one COR, or the CORs at several speeds without it");
  const Line line = t.cor.size() > 1 ? fit_line(speeds, cors) : Line{speeds[0], cors[0], t.cor_slope, 0};
  if (!std::isfinite(line.slope) || line.slope > 0)
    reject(where, "cor_slope", line.slope, "expected <= 0 per m/s: a ball's COR falls as it is struck harder");
  Ball& b = fit.ball;
  b.e0 = line.intercept, b.cor_speed = line.mean_x, b.cor_slope = line.slope;
  fit.cor_residual = line.rms;
  // The law must stay a COR over every speed a ball meets.
  if (const std::optional<double> v = cor_law_leaves_range(b))
    reject(where, "cor_slope", b.cor_slope,
           "gives a COR of " + detail::format_number(b.cor_at(*v)) + " at " + detail::format_number(*v) +
               " m/s: not a physical ball (expected " + range_text(ball_cor_range) + " from 0 to 100 m/s)");
}

// k1 of a ball of exponent a whose impact at v on a surface of curvature factor c peaks at F.
double k1_for_peak(double force, double speed, double mass, double a, double c) {
  const double energy = 0.5 * mass * speed * speed;
  return std::pow(force, a + 1) / std::pow((a + 1) * energy, a) / c;
}

void fit_dynamic_stiffness(const BallTests& t, const std::string& where, BallFit& fit) {
  std::vector<double> log_v, log_ds;
  for (const SpeedValue& p : t.dynamic_stiffness) {
    require_in(where, "stiffness_speed", p.speed, 0, max_cor_law_speed, "expected a speed in (0, 100] m/s");
    require_in(where, "dynamic_stiffness", p.value, ball_dynamic_stiffness_range);
    log_v.push_back(std::log(p.speed)), log_ds.push_back(std::log(p.value));
  }
  Ball& b = fit.ball;
  b.a = t.exponent > 0 ? t.exponent : default_ball_exponent;
  // The exponent comes from the growth with speed: values at one speed only (replicates) have none
  // to give, and keep N2000's.
  const auto [slowest, fastest] = std::ranges::minmax(log_v);
  if (fastest > slowest && !(t.exponent > 0)) {
    // F_peak grows as v^(2a/(a+1)), so DS as v^s with s = 2 (a - 1) / (a + 1): a = (2 + s) / (2 - s).
    const double s = fit_line(log_v, log_ds).slope;
    b.a = (2 + s) / (2 - s);
    if (!(b.a >= 1 && b.a <= 3))
      reject(where, "dynamic_stiffness", t.dynamic_stiffness.back().value,
             "its growth with speed gives an exponent a = " + detail::format_number(b.a) +
                 ": not a physical ball (expected 1 to 3)");
  }
  const Ball probe = [&] {
    Ball x = b;
    x.curved_contact = true;
    return x;
  }();
  const double c = t.stiffness_cylinder_diameter > 0 ? probe.curvature_factor(t.stiffness_cylinder_diameter / 2) : 1;
  double log_k = 0;
  for (const SpeedValue& p : t.dynamic_stiffness)
    log_k += std::log(k1_for_peak(p.speed * std::sqrt(b.mass * p.value), p.speed, b.mass, b.a, c));
  b.k1 = std::exp(log_k / static_cast<double>(t.dynamic_stiffness.size()));
  double squares = 0;
  for (const SpeedValue& p : t.dynamic_stiffness) {
    Ball on_surface = b;
    on_surface.k1 *= c;
    const double r = dynamic_stiffness_on_rigid(on_surface, p.speed) / p.value - 1;
    squares += r * r;
  }
  fit.stiffness_residual = std::sqrt(squares / static_cast<double>(t.dynamic_stiffness.size()));
  fit.stiffness_from = "dynamic stiffness";
}

// A k1 fitted from other values must lie in its range as a k1 given would: `key` names the value
// that took it there.
void require_fitted_k1(const std::string& where, const std::string& key, double value, const Ball& b) {
  if (!in_range(ball_k1_range, b.k1))
    reject(where, key, value,
           "gives k1 = " + detail::format_number(b.k1) + " N/m^a: expected " + range_text(ball_k1_range));
}

void fit_stiffness(const BallTests& t, const std::string& where, BallFit& fit) {
  const int given = !t.dynamic_stiffness.empty() + (t.compression_force != 0) + (t.k1 != 0);
  if (given != 1)
    throw InputError(where + ": give the ball's stiffness one way: dynamic_stiffness, compression or k1 (" +
                     std::to_string(given) + " given)");
  if (t.exponent != 0) require_in(where, "a", t.exponent, ball_exponent_range);
  Ball& b = fit.ball;
  if (!t.dynamic_stiffness.empty()) {
    fit_dynamic_stiffness(t, where, fit);
    return require_fitted_k1(where, "dynamic_stiffness", t.dynamic_stiffness.back().value, b);
  }
  b.a = t.exponent > 0 ? t.exponent : default_ball_exponent;
  if (t.k1 != 0) {
    require_in(where, "k1", t.k1, ball_k1_range);
    b.k1 = t.k1;
    fit.stiffness_from = "k1";
    return;
  }
  require_in(where, "compression", t.compression_force, ball_compression_range);
  const BallRange displacement{ball_displacement_range.low, b.radius, ball_displacement_range.what,
                               ball_displacement_range.unit};
  if (!in_range(displacement, t.compression_displacement))
    reject(where, "compression_displacement", t.compression_displacement,
           "expected " + range_text(displacement) + " (at most the ball's radius)");
  // Squeezed between two flat plates, each side takes half the displacement, quasi-statically.
  b.k1 = t.compression_force / std::pow(t.compression_displacement / 2, b.a);
  fit.stiffness_from = "compression";
  require_fitted_k1(where, "compression_displacement", t.compression_displacement, b);
}

}  // namespace

namespace {

// A bound as a reader writes it: 0.001, 1000, 1e12 (not 1e+12).
std::string bound_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  std::string s = text;
  if (const auto e = s.find("e+"); e != std::string::npos) s.erase(e + 1, 1);
  if (const auto e = s.find('e'); e != std::string::npos)
    while (s.size() > e + 2 && (s[e + 1] == '0' || (s[e + 1] == '-' && s[e + 2] == '0')))
      s.erase(s[e + 1] == '0' ? e + 1 : e + 2, 1);
  return s;
}

}  // namespace

std::string range_text(BallRange r) {
  std::string text = r.what;
  text.append(" in [").append(bound_text(r.low)).append(", ").append(bound_text(r.high));
  text.append("]");
  if (*r.unit) text.append(" ").append(r.unit);
  return text;
}

std::optional<OutOfRange> ball_out_of_range(const Ball& ball) {
  const std::pair<const char*, std::pair<double, BallRange>> values[] = {
      {"ball_mass", {ball.mass, ball_mass_range}}, {"ball_radius", {ball.radius, ball_radius_range}},
      {"k1", {ball.k1, ball_k1_range}},            {"a", {ball.a, ball_exponent_range}},
      {"e0", {ball.e0, ball_cor_range}}};
  for (const auto& [key, value] : values)
    if (!in_range(value.second, value.first)) return OutOfRange{key, value.first, value.second};
  return std::nullopt;
}

double peak_force_on_rigid(const Ball& ball, double speed) {
  const double q = ball.a + 1;
  const double u_max = std::pow(q * ball.mass * speed * speed / (2 * ball.k1), 1 / q);
  return ball.k1 * std::pow(u_max, ball.a);
}

double dynamic_stiffness_on_rigid(const Ball& ball, double speed) {
  const double f = peak_force_on_rigid(ball, speed) / speed;
  return f * f / ball.mass;
}

BallFit fit_ball(const BallTests& t, const std::string& where) {
  BallFit fit;
  // 0 is a value not given (a [ball] table refuses a given 0 when it reads it), as cor's absence.
  for (const auto& [key, value] : {std::pair{"mass", t.mass}, std::pair{"radius", t.radius}})
    if (value == 0)
      throw InputError(where + ": " + key + " is missing: expected the ball's " + key + " (or a preset that gives it)");
  require_in(where, "mass", t.mass, ball_mass_range);
  require_in(where, "radius", t.radius, ball_radius_range);
  if (t.stiffness_cylinder_diameter != 0)
    require_in(where, "stiffness_cylinder_diameter", t.stiffness_cylinder_diameter, ball_cylinder_diameter_range);
  fit.ball.mass = t.mass, fit.ball.radius = t.radius;
  fit_cor(t, where, fit);
  fit_stiffness(t, where, fit);
  fit.ball.curved_contact = t.curved_contact;
  return fit;
}

std::optional<double> cor_law_leaves_range(const Ball& ball) {
  for (const double v : {0.0, max_cor_law_speed})
    if (!in_range(ball_cor_range, ball.cor_at(v))) return v;
  return std::nullopt;
}

std::optional<std::string> cor_law_misfit(const Ball& ball) {
  const std::optional<double> v = ball.speed_dependent() ? cor_law_leaves_range(ball) : std::nullopt;
  if (!v) return std::nullopt;
  return "with cor_slope = " + detail::format_number(ball.cor_slope) + " per m/s about " +
         detail::format_number(ball.cor_speed) + " m/s gives a COR of " + detail::format_number(ball.cor_at(*v)) +
         " at " + detail::format_number(*v) + " m/s: not a physical ball (expected " + range_text(ball_cor_range) + ")";
}

}  // namespace sweetspot
