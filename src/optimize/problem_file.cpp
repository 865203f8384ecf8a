// Reading an optimisation file (README "Design optimisation"): every key checked, with the
// study files' one-line messages (file:line: key 'free.density.min' = ...: expected ...).
#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <string>

#include "study/study_settings.hpp"
#include "sweetspot/impact/scan_maximum.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/optimize/problem.hpp"
#include "toml_values.hpp"

namespace sweetspot {

namespace {

namespace fs = std::filesystem;
using detail::describe;
using detail::format_number;
using detail::quote;
using study_detail::reject;
using study_detail::reject_unknown;
using study_detail::Where;

// ---- Values --------------------------------------------------------------------------------

const toml::node* child(const toml::table& table, std::string_view key) { return table.get(key); }

double number(const Where& at, const toml::node& node, const std::string& expected) {
  if (!node.is_number() || !std::isfinite(*node.value<double>())) reject(at, describe(node), "expected " + expected);
  return *node.value<double>();
}

// A number that must satisfy `ok`; `fallback` when absent.
template <class Ok>
double number_key(const Where& table, const toml::table& t, std::string_view key, double fallback, Ok ok,
                  const std::string& expected) {
  const toml::node* node = child(t, key);
  if (!node) return fallback;
  const Where at = table.child(key, *node);
  const double v = number(at, *node, expected);
  if (!ok(v)) reject(at, describe(*node), "expected " + expected);
  return v;
}

template <class Ok>
double required_number(const Where& table, const toml::table& t, std::string_view key, Ok ok,
                       const std::string& expected) {
  if (!child(t, key)) reject(table.missing(key), "", "expected " + expected);
  return number_key(table, t, key, 0, ok, expected);
}

std::string string_key(const Where& table, const toml::table& t, std::string_view key, const std::string& fallback,
                       const std::string& expected) {
  const toml::node* node = child(t, key);
  if (!node) return fallback;
  if (!node->is_string() || node->as_string()->get().empty())
    reject(table.child(key, *node), describe(*node), "expected " + expected);
  return node->as_string()->get();
}

const toml::table& table_key(const Where& parent, const toml::table& t, std::string_view key, bool required) {
  static const toml::table empty;
  const toml::node* node = child(t, key);
  if (!node) {
    if (required) reject(parent.missing(key), "", "expected a table [" + std::string(key) + "]");
    return empty;
  }
  if (!node->is_table()) reject(parent.child(key, *node), describe(*node), "expected a table [" + std::string(key) + "]");
  return *node->as_table();
}

const auto finite = [](double) { return true; };
const auto positive = [](double v) { return v > 0; };

// ---- The bats ------------------------------------------------------------------------------

BatDesign read_bat(const Where& at, const fs::path& file, const std::string& name, BatSource& source) {
  try {
    return load_bat_design((file.parent_path() / name).lexically_normal(), source);
  } catch (const InputError& e) {
    reject(at, quote(name), e.what());
  }
}

// ---- [free] --------------------------------------------------------------------------------

FreeParameter read_free_parameter(const Where& at, const toml::node& node, const std::string& name,
                                  const BatDesign& base) {
  const std::vector<std::string> known = design_parameters(base);
  if (std::ranges::find(known, name) == known.end())
    reject(at, describe(node), "unknown parameter of the base bat; expected one of " + detail::join(known));
  if (!node.is_table()) reject(at, describe(node), "expected a table { min = ..., max = ... [, start = ...] }");
  const toml::table& t = *node.as_table();
  reject_unknown(at, t, {"min", "max", "start"});
  FreeParameter p{name, required_number(at, t, "min", finite, "a finite lower bound"),
                  required_number(at, t, "max", finite, "a finite upper bound"), 0};
  if (!(p.lower < p.upper))
    reject(at.child("max", *t.get("max")), format_number(p.upper), "expected a bound above min = " + format_number(p.lower));
  const double base_value = design_parameter(base, name);
  const auto inside = [&](double v) { return v >= p.lower && v <= p.upper; };
  if (t.get("start"))
    p.start = number_key(at, t, "start", 0, inside, "a start within [min, max]");
  else if (!inside(base_value))
    reject(at, describe(node),
           "the base bat's " + name + " = " + format_number(base_value) +
               " lies outside [min, max]; expected bounds around it, or a start");
  else
    p.start = base_value;
  return p;
}

// Every corner of the box a possible bat: the rules are linear in the parameters, so then is
// every design inside it.
void check_box(const Where& at, const OptimizationProblem& problem) {
  const std::size_t n = problem.free.size();
  for (std::size_t corner = 0; corner < (std::size_t{1} << n); ++corner) {
    std::vector<double> x(n);
    std::string where;
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = (corner >> i) & 1 ? problem.free[i].upper : problem.free[i].lower;
      where += (where.empty() ? "" : ", ") + problem.free[i].name + " = " + format_number(x[i]);
    }
    if (const auto broken = broken_rule(design_at(problem, x)))
      reject(at, "{...}", "the corner " + where + " of the bounds is an impossible bat (" + *broken +
                              "); expected bounds within which every design is a possible bat");
  }
}

std::vector<FreeParameter> read_free(const Where& top, const toml::table& doc, const BatDesign& base) {
  const toml::table& t = table_key(top, doc, "free", true);
  const Where at{top.file, "free", doc.get("free")->source().begin.line};
  if (t.empty()) reject(at, "{}", "expected at least one free parameter, e.g. barrel_diameter = { min = 0.06, max = 0.0667 }");
  if (t.size() > max_free_parameters)
    reject(at, "{...}", "has " + std::to_string(t.size()) + " parameters; expected at most " +
                            std::to_string(max_free_parameters));
  std::vector<FreeParameter> free;
  for (const auto& [key, node] : t) {
    // toml++ keeps keys sorted: the parameters' order is the alphabetical one, whatever the file's.
    free.push_back(read_free_parameter(at.child(key.str(), node), node, std::string(key.str()), base));
  }
  return free;
}

// ---- [player] ------------------------------------------------------------------------------

Player read_player(const Where& top, const toml::table& doc, OptimizationProblem& problem) {
  const toml::table& t = table_key(top, doc, "player", true);
  const Where at{top.file, "player", doc.get("player")->source().begin.line};
  reject_unknown(at, t, {"swing", "reference_bat", "swing_exponent", "center", "cm_speed", "omega", "ball_speed", "e0"});
  Player p;
  const std::string swing = string_key(at, t, "swing", "equal_effort", "\"equal_effort\" or \"given\"");
  if (swing != "equal_effort" && swing != "given")
    reject(at.child("swing", *t.get("swing")), quote(swing), "expected \"equal_effort\" or \"given\"");
  p.equal_effort = swing == "equal_effort";
  const bool center = t.get("center"), cm = t.get("cm_speed");
  if (center == cm)
    reject(center ? at.child("cm_speed", *t.get("cm_speed")) : at.missing("center"), center ? "given too" : "",
           "expected the swing's rotation centre `center` (m from the knob) or its `cm_speed` (m/s), one of them");
  p.swing.about_center = center;
  if (center) p.swing.center = number_key(at, t, "center", 0, finite, "a finite point (m from the knob)");
  if (cm) p.swing.cm_speed = number_key(at, t, "cm_speed", 0, finite, "a finite speed (m/s)");
  p.swing.omega = required_number(at, t, "omega", finite, "the swing's angular speed (rad/s), finite");
  p.ball_speed = required_number(at, t, "ball_speed", [](double v) { return v >= 0; },
                                 "the pitch's speed toward the bat (m/s), finite and >= 0");
  p.e0 = number_key(at, t, "e0", 0.5, [](double v) { return v > 0 && v <= 1; }, "a COR in (0, 1]");
  if (!p.equal_effort) {
    for (const char* key : {"reference_bat", "swing_exponent"})
      if (const toml::node* node = t.get(key))
        reject(at.child(key, *node), describe(*node), "applies only with swing = \"equal_effort\"");
    return p;
  }
  p.swing_exponent = number_key(at, t, "swing_exponent", 0.3, [](double v) { return v >= 0 && v <= 2; },
                                "a power-law exponent in [0, 2] (0.3 fits college hitters)");
  const toml::node* reference = t.get("reference_bat");
  if (reference) {
    const std::string name = string_key(at, t, "reference_bat", "", "a bat file (the player's swing was measured with it)");
    const BatDesign ref = read_bat(at.child("reference_bat", *reference), problem.file, name, problem.reference_source);
    p.reference_moi = design_mass_properties(ref).moment_of_inertia_about(0);
  } else {
    p.reference_moi = design_mass_properties(problem.base).moment_of_inertia_about(0);  // the base bat
  }
  return p;
}

// ---- [model] -------------------------------------------------------------------------------

ModelSettings read_model(const Where& top, const toml::table& doc) {
  const toml::table& t = table_key(top, doc, "model", false);
  const Where at{top.file, "model", doc.get("model") ? doc.get("model")->source().begin.line : 0};
  reject_unknown(at, t, {"modes", "slices", "theory"});
  ModelSettings m;
  if (const toml::node* node = t.get("modes")) {
    const auto text = node->value<std::string_view>();
    if (node->is_integer() && node->as_integer()->get() >= 0 && node->as_integer()->get() <= max_slices * 2)
      m.vibrational_modes = static_cast<int>(node->as_integer()->get());
    else if (node->is_string() && (text == "all" || text == "auto"))
      m.vibrational_modes = text == "all" ? all_modes : auto_modes;
    else
      reject(at.child("modes", *node), describe(*node), "expected a count of vibrational modes (0: rigid bats), \"all\" or \"auto\"");
  }
  if (const toml::node* node = t.get("slices")) {
    if (!node->is_integer() || node->as_integer()->get() < min_slices || node->as_integer()->get() > max_slices)
      reject(at.child("slices", *node), describe(*node), "expected an integer from 4 to 4096");
    m.slices = static_cast<int>(node->as_integer()->get());
  }
  if (const toml::node* node = t.get("theory")) {
    try {
      m.theory = parse_beam_theory(node->value<std::string>().value_or(""));
    } catch (const InputError&) {
      reject(at.child("theory", *node), describe(*node), "expected \"timoshenko\" or \"euler-bernoulli\"");
    }
  }
  return m;
}

// The model must serve the shortest design (fewest slices when they are about 1 cm each): its
// slicing and theory, and a count of modes it has.
void check_model(const Where& top, const toml::table& doc, const OptimizationProblem& problem, double length) {
  const Where at{top.file, "model", doc.get("model") ? doc.get("model")->source().begin.line : 0};
  BatDesign shortest = problem.base;
  set_design_parameter(shortest, "length", length);
  int modes = 0;
  try {
    Bat bat = build_bat(shortest);
    if (problem.model.slices > 0) bat = resample(bat, problem.model.slices);
    modes = static_cast<int>(compute_modes(bat, problem.model.theory, ModeRequest::rigid_only()).vectors.rows()) - 2;
  } catch (const InputError& e) {
    reject(at, "{...}", std::string("cannot model the shortest design: ") + e.what());
  }
  if (problem.model.vibrational_modes > modes)
    reject(at.child("modes", *doc["model"]["modes"].node()), std::to_string(problem.model.vibrational_modes),
           "expected at most the " + std::to_string(modes) + " vibrational modes of the shortest design, \"all\" or \"auto\"");
}

// ---- [objective] ---------------------------------------------------------------------------

// The shortest design in the box: every impact point must lie on it.
double shortest_length(const OptimizationProblem& problem) {
  const auto it = std::ranges::find(problem.free, "length", &FreeParameter::name);
  return it == problem.free.end() ? problem.base.length : it->lower;
}

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
  o.z_from = required_number(z, range, "start", on, on_bat);
  o.z_to = required_number(z, range, "stop", on, on_bat);
  if (!(o.z_to > o.z_from)) reject(z.child("stop", *range.get("stop")), format_number(o.z_to), "expected stop > start");
  o.z_step = required_number(z, range, "step", positive, "a step > 0 (m)");
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

std::vector<double> number_list(const Where& at, const toml::node& node, const std::string& expected) {
  if (!node.is_array() || node.as_array()->empty() || node.as_array()->size() > 1000)
    reject(at, describe(node), "expected a list of 1 to 1000 " + expected);
  std::vector<double> values;
  std::size_t i = 0;
  for (const toml::node& item : *node.as_array()) values.push_back(number(at.item(i++, item), item, expected));
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
    const double mean = required_number(s, st, "mean", finite, "the mean impact point (m from the knob)");
    const double sigma = required_number(s, st, "sigma", positive, "the spread's standard deviation > 0 (m)");
    const double count = number_key(s, st, "points", 7, [](double v) { return v == std::floor(v) && v >= 1 && v <= 40; },
                                    "an integer number of quadrature points from 1 to 40");
    gauss_hermite(mean, sigma, static_cast<int>(count), o);
  } else {
    const Where p = at.child("points", *points);
    o.z = number_list(p, *points, "impact points (m from the knob)");
    const toml::node* weights = t.get("weights");
    if (!weights) reject(at.missing("weights"), "", "expected one weight per impact point");
    const Where w = at.child("weights", *weights);
    o.weights = number_list(w, *weights, "weights >= 0");
    if (o.weights.size() != o.z.size())
      reject(w, describe(*weights), "has " + std::to_string(o.weights.size()) + " weights; expected one per point (" +
                                        std::to_string(o.z.size()) + ")");
    double sum = 0;
    for (const double v : o.weights) {
      if (v < 0) reject(w, format_number(v), "expected weights >= 0");
      sum += v;
    }
    if (!(sum > 0)) reject(w, describe(*weights), "expected weights with a sum > 0");
    for (double& v : o.weights) v /= sum;
  }
  for (const double z : o.z)
    if (!(z >= 0 && z <= length))
      reject(spread ? at.child("spread", *spread) : at.child("points", *points), format_number(z),
             "puts an impact point off the shortest design; expected points from 0 to " + format_number(length) + " m");
}

ObjectiveSpec read_objective(const Where& top, const toml::table& doc, double length) {
  const toml::table& t = table_key(top, doc, "objective", true);
  const Where at{top.file, "objective", doc.get("objective")->source().begin.line};
  ObjectiveSpec o;
  const std::string kind = string_key(at, t, "maximize", "", "\"peak_bbs\", \"sweet_spot_width\" or \"mean_bbs\"");
  if (kind == "peak_bbs") {
    o.kind = ObjectiveKind::peak_bbs;
    reject_unknown(at, t, {"maximize", "z", "tolerance"});
    o.tolerance = number_key(at, t, "tolerance", 1e-5, positive, "a tolerance > 0 (m) for where the peak is");
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
           "expected \"peak_bbs\", \"sweet_spot_width\" or \"mean_bbs\"");
  }
  return o;
}

// ---- [constraints] -------------------------------------------------------------------------

struct WindowKey {
  std::string_view name;
  Quantity quantity;
  const char* unit;
};
constexpr WindowKey windows[] = {{"barrel_diameter", Quantity::barrel_diameter, "m"},
                                 {"drop", Quantity::drop, "length in inches minus weight in ounces"},
                                 {"mass", Quantity::mass, "kg"},
                                 {"moi_knob", Quantity::moi_knob, "kg m^2"},
                                 {"moi_pivot", Quantity::moi_pivot, "kg m^2"},
                                 {"length", Quantity::length, "m"}};

void read_window(const Where& at, const toml::node& node, const WindowKey& w, std::vector<Constraint>& out) {
  const std::string expected = std::string("{ min = ..., max = ... } (") + w.unit + "), either or both";
  if (!node.is_table() || node.as_table()->empty()) reject(at, describe(node), "expected " + expected);
  const toml::table& t = *node.as_table();
  reject_unknown(at, t, {"min", "max"});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double lo = number_key(at, t, "min", nan, finite, "a finite bound"), hi = number_key(at, t, "max", nan, finite, "a finite bound");
  if (t.get("min") && t.get("max") && !(lo < hi))
    reject(at.child("max", *t.get("max")), format_number(hi), "expected a bound above min = " + format_number(lo));
  if (t.get("min")) out.push_back({w.quantity, std::string(w.name), false, lo});
  if (t.get("max")) out.push_back({w.quantity, std::string(w.name), true, hi});
}

void read_constraints(const Where& top, const toml::table& doc, OptimizationProblem& problem) {
  const toml::table& t = table_key(top, doc, "constraints", false);
  const Where at{top.file, "constraints", doc.get("constraints") ? doc.get("constraints")->source().begin.line : 0};
  reject_unknown(at, t, {"standard", "limit", "barrel_diameter", "drop", "mass", "moi_knob", "moi_pivot", "length"});
  if (const toml::node* node = t.get("standard")) {
    const std::string name = string_key(at, t, "standard", "", "\"bbcor\", \"besr\" or \"bpf\"");
    try {
      problem.standard = find_standard(name);
    } catch (const InputError&) {
      reject(at.child("standard", *node), describe(*node), "expected \"bbcor\", \"besr\" or \"bpf\"");
    }
    problem.standard.limit = number_key(at, t, "limit", problem.standard.limit, positive, "a limit > 0 on the measure");
    // The measure, and the standard's rules on the shape: a design that certify passes.
    problem.constraints.push_back({Quantity::measure, to_string(problem.standard.measure), true, problem.standard.limit});
    problem.constraints.push_back({Quantity::barrel_diameter, "barrel_diameter", true, problem.standard.max_barrel_diameter});
    if (problem.standard.max_drop) problem.constraints.push_back({Quantity::drop, "drop", true, *problem.standard.max_drop});
    if (problem.standard.max_length) problem.constraints.push_back({Quantity::length, "length", true, *problem.standard.max_length});
  } else if (const toml::node* limit = t.get("limit")) {
    reject(at.child("limit", *limit), describe(*limit), "applies only with a standard");
  }
  for (const WindowKey& w : windows)
    if (const toml::node* node = t.get(w.name)) read_window(at.child(w.name, *node), *node, w, problem.constraints);
}

// The rig must fit every design: its pivot before the scanned barrel of the shortest.
void check_rig(const Where& top, const OptimizationProblem& problem, double length) {
  if (std::ranges::none_of(problem.constraints, [](const Constraint& c) { return c.quantity == Quantity::measure; }))
    return;
  try {
    certification_rig(problem.standard, problem.rig, length);
  } catch (const InputError& e) {
    reject(Where{top.file, "constraints.standard", 0}, quote(problem.standard.name),
           std::string("cannot test the shortest design: ") + e.what());
  }
}

// ---- [optimizer] ---------------------------------------------------------------------------

OptimizerSettings read_optimizer(const Where& top, const toml::table& doc) {
  const toml::table& t = table_key(top, doc, "optimizer", false);
  const Where at{top.file, "optimizer", doc.get("optimizer") ? doc.get("optimizer")->source().begin.line : 0};
  reject_unknown(at, t, {"algorithm", "max_evaluations", "xtol_rel", "initial_step", "constraint_tolerance", "seed"});
  OptimizerSettings o;
  const std::string algorithm = string_key(at, t, "algorithm", "cobyla", "\"cobyla\", \"bobyqa\" or \"mlsl\"");
  if (algorithm == "cobyla") o.algorithm = Algorithm::cobyla;
  else if (algorithm == "bobyqa") o.algorithm = Algorithm::bobyqa;
  else if (algorithm == "mlsl") o.algorithm = Algorithm::mlsl;
  else reject(at.child("algorithm", *t.get("algorithm")), quote(algorithm), "expected \"cobyla\", \"bobyqa\" or \"mlsl\"");
  const auto whole = [](double lo, double hi) { return [lo, hi](double v) { return v == std::floor(v) && v >= lo && v <= hi; }; };
  o.max_evaluations = static_cast<int>(number_key(at, t, "max_evaluations", o.max_evaluations,
                                                  whole(1, max_optimizer_evaluations), "an integer from 1 to 100000"));
  o.xtol_rel = number_key(at, t, "xtol_rel", o.xtol_rel, [](double v) { return v > 0 && v < 1; }, "a tolerance in (0, 1)");
  o.initial_step = number_key(at, t, "initial_step", o.initial_step, [](double v) { return v > 0 && v <= 1; },
                              "a fraction of each parameter's range in (0, 1]");
  o.constraint_tolerance = number_key(at, t, "constraint_tolerance", o.constraint_tolerance,
                                      [](double v) { return v >= 0 && v < 1; }, "a relative tolerance in [0, 1)");
  o.seed = static_cast<std::uint32_t>(number_key(at, t, "seed", o.seed, whole(0, 4294967295.0), "an integer from 0 to 2^32 - 1"));
  return o;
}

}  // namespace

OptimizationProblem load_optimization(const fs::path& file) {
  OptimizationProblem problem;
  problem.file = file;
  problem.text = study_detail::read_text(file);
  const toml::table doc = study_detail::parse_toml(file, problem.text);
  const Where top{&problem.file, "", 0};
  reject_unknown(top, doc, {"title", "bat", "free", "player", "model", "objective", "constraints", "optimizer"});
  problem.title = string_key(top, doc, "title", file.stem().string(), "a title (string)");
  const std::string bat = string_key(top, doc, "bat", "", "the base bat file (its [dimensions] are what is optimised)");
  if (bat.empty()) reject(top.missing("bat"), "", "expected the base bat file (a bat of named [dimensions])");
  const Where bat_at = top.child("bat", *doc.get("bat"));
  problem.base = read_bat(bat_at, file, bat, problem.base_source);
  if (!problem.base.dimensions)
    reject(bat_at, quote(bat), "is a bat given by a profile; expected a bat of named [dimensions] (a parametric bat)");
  problem.free = read_free(top, doc, problem.base);
  check_box(Where{&problem.file, "free", doc.get("free")->source().begin.line}, problem);
  problem.player = read_player(top, doc, problem);
  problem.model = read_model(top, doc);
  const double length = shortest_length(problem);
  check_model(top, doc, problem, length);
  problem.objective = read_objective(top, doc, length);
  problem.rig.vibrational_modes = problem.model.vibrational_modes;
  problem.rig.slices = problem.model.slices;
  problem.rig.theory = problem.model.theory;
  read_constraints(top, doc, problem);
  check_rig(top, problem, length);
  problem.optimizer = read_optimizer(top, doc);
  return problem;
}

}  // namespace sweetspot
