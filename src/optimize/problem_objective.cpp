// Reading an optimisation file's [objective]: what to maximise and where the ball strikes.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "problem_values.hpp"
#include "sweetspot/input_error.hpp"

namespace sweetspot::optimize_detail {

double shortest_length(const OptimizationProblem& problem) {
  const auto it = std::ranges::find(problem.free, "length", &FreeParameter::name);
  return it == problem.free.end() ? problem.base.length : it->lower;
}

namespace {

void read_scan(const Where& at, const toml::table& t, ObjectiveSpec& o, double length) {
  const toml::node* node = t.get("z");
  if (!node || !node->is_table())
    reject(node ? at.child("z", *node) : at.missing("z"), node ? describe(*node) : "",
           "expected the impact scan z = { start = ..., stop = ..., step = ... } (m from the knob)");
  const Where z = at.child("z", *node);
  const toml::table& range = *node->as_table();
  reject_unknown(z, range, {"start", "stop", "step"});
  const std::string on_bat = "a point on every design (0 to " + format_number(length) + " m)";
  const auto on = [&](double v) { return v >= 0 && v <= length; };
  o.z_from = required_number(z, range, "start", on, on_bat, Dimension::length);
  o.z_to = required_number(z, range, "stop", on, on_bat, Dimension::length);
  if (!(o.z_to > o.z_from)) reject(z.child("stop", *range.get("stop")), format_number(o.z_to), "expected stop > start");
  o.z_step = required_number(z, range, "step", positive, "a step > 0", Dimension::length);
  const double points = std::ceil((o.z_to - o.z_from) / o.z_step);
  if (points < 2 || points > 1e4)
    reject(z.child("step", *range.get("step")), format_number(o.z_step), "expected a step giving 3 to 10^4 points");
}

// The normal distribution N(mean, sigma^2) by Gauss-Hermite quadrature of `count` points: the
// nodes and weights of the probabilists' Hermite polynomials (weight e^{-x^2/2}) from the
// eigen-decomposition of their Jacobi matrix (Golub & Welsch, Math. Comp. 23, 221 (1969)).
void gauss_hermite(double mean, double sigma, int count, ObjectiveSpec& o) {
  Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(count, count);
  for (int k = 1; k < count; ++k) jacobi(k, k - 1) = jacobi(k - 1, k) = std::sqrt(static_cast<double>(k));
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(jacobi);
  for (int i = 0; i < count; ++i) {
    o.z.push_back(mean + sigma * solver.eigenvalues()(i));
    o.weights.push_back(solver.eigenvectors()(0, i) * solver.eigenvectors()(0, i));
  }
}

std::vector<double> number_list(const Where& at, const toml::node& node, const std::string& expected,
                                std::optional<Dimension> dimension = std::nullopt) {
  if (!node.is_array() || node.as_array()->empty() || node.as_array()->size() > 1000)
    reject(at, describe(node), "expected a list of 1 to 1000 " + expected);
  std::vector<double> values;
  std::size_t i = 0;
  for (const toml::node& item : *node.as_array())
    values.push_back(number(at.item(i++, item), item, expected, dimension));
  return values;
}

void read_spread(const Where& at, const toml::table& t, ObjectiveSpec& o, double length) {
  const toml::node* spread = t.get("spread");
  const toml::node* points = t.get("points");
  if (!spread == !points)
    reject(spread ? at.child("points", *points) : at.missing("spread"), spread ? "given too" : "",
           "mean_bbs expected the player's spread of impact points: spread = { mean, sigma, points } (a normal "
           "distribution) or points = [...] with weights = [...], one of them");
  if (spread) {
    const Where s = at.child("spread", *spread);
    if (!spread->is_table()) reject(s, describe(*spread), "expected { mean = ..., sigma = ..., points = ... }");
    const toml::table& st = *spread->as_table();
    reject_unknown(s, st, {"mean", "sigma", "points"});
    const double mean =
        required_number(s, st, "mean", finite, "the mean impact point from the knob", Dimension::length);
    const double sigma =
        required_number(s, st, "sigma", positive, "the spread's standard deviation > 0", Dimension::length);
    const double count = number_key(s, st, "points", 7, [](double v) { return v == std::floor(v) && v >= 1 && v <= 40; },
                                    "an integer number of quadrature points from 1 to 40");
    gauss_hermite(mean, sigma, static_cast<int>(count), o);
  } else {
    const Where p = at.child("points", *points);
    o.z = number_list(p, *points, "impact points from the knob", Dimension::length);
    const toml::node* weights = t.get("weights");
    if (!weights) reject(at.missing("weights"), "", "expected one weight per impact point");
    const Where w = at.child("weights", *weights);
    o.weights = number_list(w, *weights, "weights >= 0");
    if (o.weights.size() != o.z.size())
      reject(w, describe(*weights), "has " + std::to_string(o.weights.size()) + " weights; expected one per point (" +
                                        std::to_string(o.z.size()) + ")");
    double sum = 0;
    for (std::size_t i = 0; i < o.weights.size(); ++i) {
      if (o.weights[i] < 0)  // named by its index, as number_list names a NaN
        reject(w.item(i, *weights->as_array()->get(i)), format_number(o.weights[i]), "expected weights >= 0");
      sum += o.weights[i];
    }
    // The weights are divided by their sum: it must neither vanish nor overflow (1e308 + 1e308).
    if (!(sum > 0 && std::isfinite(sum)))
      reject(w, describe(*weights), "expected weights with a finite sum > 0 (they are divided by it), e.g. [1, 2]");
    for (double& v : o.weights) v /= sum;
  }
  for (const double z : o.z)
    if (!(z >= 0 && z <= length))
      reject(spread ? at.child("spread", *spread) : at.child("points", *points), format_number(z),
             "puts an impact point off the shortest design; expected points from 0 to " + format_number(length) + " m");
}

}  // namespace

ObjectiveSpec read_objective(const Where& top, const toml::table& doc, double length) {
  const toml::table& t = table_key(top, doc, "objective", true);
  const Where at{top.file, "objective", doc.get("objective")->source().begin.line};
  ObjectiveSpec o;
  const std::string kind =
      string_key(at, t, "maximize", "", "\"peak_bbs\", \"peak_distance\", \"sweet_spot_width\" or \"mean_bbs\"");
  if (kind == "peak_bbs" || kind == "peak_distance") {
    o.kind = kind == "peak_bbs" ? ObjectiveKind::peak_bbs : ObjectiveKind::peak_distance;
    reject_unknown(at, t, {"maximize", "z", "tolerance"});
    // The golden section narrows its bracket to the tolerance: below about 1e-12 m it would reach
    // the spacing of doubles near the bat and never end.
    o.tolerance = number_key(at, t, "tolerance", 1e-5, [](double v) { return v >= 1e-12; },
                             "a tolerance >= 1e-12 (m) for where the peak is");
    read_scan(at, t, o, length);
  } else if (kind == "sweet_spot_width") {
    o.kind = ObjectiveKind::sweet_spot_width;
    reject_unknown(at, t, {"maximize", "z", "fraction"});
    o.fraction = number_key(at, t, "fraction", 0.01, [](double v) { return v > 0 && v < 1; }, "a fraction in (0, 1)");
    read_scan(at, t, o, length);
  } else if (kind == "mean_bbs") {
    o.kind = ObjectiveKind::mean_bbs;
    reject_unknown(at, t, {"maximize", "spread", "points", "weights"});
    read_spread(at, t, o, length);
  } else {
    const toml::node* node = t.get("maximize");
    reject(node ? at.child("maximize", *node) : at.missing("maximize"), node ? describe(*node) : "",
           "expected \"peak_bbs\", \"peak_distance\", \"sweet_spot_width\" or \"mean_bbs\"");
  }
  return o;
}

}  // namespace sweetspot::optimize_detail
