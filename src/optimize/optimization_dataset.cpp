#include "sweetspot/optimize/optimization_dataset.hpp"

#include <limits>
#include <string>

#include "sweetspot/version.hpp"

namespace sweetspot {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// A design parameter's units (design_parameters: material constants and lengths).
std::string parameter_units(const std::string& name) {
  if (name == "density") return "kg m-3";
  if (name == "youngs_modulus" || name == "shear_modulus") return "Pa";
  if (name == "shear_coefficient") return "1";
  return "m";  // length and every dimension
}

std::string quantity_units(Quantity q) {
  switch (q) {
    case Quantity::measure: return "1";
    case Quantity::drop: return "1";  // inches less ounces: no UDUNITS unit
    case Quantity::mass: return "kg";
    case Quantity::moi_knob:
    case Quantity::moi_pivot: return "kg m2";
    case Quantity::barrel_diameter:
    case Quantity::length: return "m";
  }
  return "1";
}

std::string objective_units(ObjectiveKind kind) {
  return kind == ObjectiveKind::sweet_spot_width || kind == ObjectiveKind::peak_distance ? "m" : "m s-1";
}

std::string objective_long_name(const ObjectiveSpec& o) {
  switch (o.kind) {
    case ObjectiveKind::peak_bbs: return "largest batted-ball speed over the impact scan";
    case ObjectiveKind::sweet_spot_width:
      return "sweet-spot width: length of the zone within " + std::to_string(o.fraction) + " of the peak speed";
    case ObjectiveKind::mean_bbs: return "batted-ball speed averaged over the player's impact points";
    case ObjectiveKind::peak_distance: return "longest carry of the batted ball over the impact scan";
  }
  return "";
}

void parameter_variables(const OptimizationProblem& p, std::ptrdiff_t best, const OptimizationHistory& h, Dataset& d) {
  std::vector<double> lower, upper, start, base, best_x;
  std::vector<std::string> units;
  for (std::size_t i = 0; i < p.free.size(); ++i) {
    lower.push_back(p.free[i].lower), upper.push_back(p.free[i].upper), start.push_back(p.free[i].start);
    base.push_back(design_parameter(p.base, p.free[i].name));
    best_x.push_back(best >= 0 ? h.evaluations[static_cast<std::size_t>(best)].x[i] : nan);
    units.push_back(parameter_units(p.free[i].name));
  }
  // Parameters of different units share these variables: each one's units are parameter_units.
  d.variables.push_back({"parameter_units", "", "units of each free parameter", {"parameter"}, units, {}, {}});
  d.variables.push_back({"lower_bound", "", "lower bound of each free parameter (units: parameter_units)", {"parameter"}, lower, {}, {}});
  d.variables.push_back({"upper_bound", "", "upper bound of each free parameter (units: parameter_units)", {"parameter"}, upper, {}, {}});
  d.variables.push_back({"start", "", "where the search started (units: parameter_units)", {"parameter"}, start, {}, {}});
  d.variables.push_back({"base_design", "", "the base bat's value (units: parameter_units)", {"parameter"}, base, {}, {}});
  d.variables.push_back({"best_design", "", "the best feasible design (units: parameter_units); NaN if none", {"parameter"}, best_x, {}, {}});
}

void constraint_variables(const OptimizationProblem& p, std::ptrdiff_t best, const OptimizationHistory& h, Dataset& d) {
  if (p.constraints.empty()) return;
  std::vector<std::string> labels, units;
  std::vector<double> limits, values, best_values;
  for (const Constraint& c : p.constraints) {
    labels.push_back(c.label()), units.push_back(quantity_units(c.quantity)), limits.push_back(c.limit);
  }
  d.coordinates.push_back({"constraint", "", "constraint: quantity_max (value <= limit) or quantity_min (value >= limit)", {}, labels});
  for (const DesignEvaluation& e : h.evaluations) values.insert(values.end(), e.constraints.begin(), e.constraints.end());
  for (std::size_t i = 0; i < p.constraints.size(); ++i)
    best_values.push_back(best >= 0 ? h.evaluations[static_cast<std::size_t>(best)].constraints[i] : nan);
  d.variables.push_back({"constraint_units", "", "units of each constrained quantity", {"constraint"}, units, {}, {}});
  d.variables.push_back({"constraint_limit", "", "each constraint's limit (units: constraint_units)", {"constraint"}, limits, {}, {}});
  d.variables.push_back({"constraint_value", "", "each design's constrained quantities (units: constraint_units); NaN where not computed",
                         {"evaluation", "constraint"}, values, {}, {}});
  d.variables.push_back({"best_constraint_value", "", "the best design's constrained quantities (units: constraint_units)",
                         {"constraint"}, best_values, {}, {}});
}

void evaluation_variables(const OptimizationProblem& p, const OptimizationHistory& h, Dataset& d) {
  std::vector<double> design, objective, slices_used, slicing_error, modes_error, step_error, total_error;
  std::vector<std::int32_t> status, is_feasible;
  std::vector<std::string> messages;
  bool any_failed = false;
  for (const DesignEvaluation& e : h.evaluations) {
    design.insert(design.end(), e.x.begin(), e.x.end());
    objective.push_back(e.objective);
    slices_used.push_back(e.slices_used);
    slicing_error.push_back(e.slicing_error);
    modes_error.push_back(e.modes_error);
    step_error.push_back(e.step_error);
    total_error.push_back(e.total_error);
    status.push_back(static_cast<std::int32_t>(e.status));
    is_feasible.push_back(feasible(p, e) ? 1 : 0);
    messages.push_back(e.message);
    any_failed = any_failed || e.status != EvaluationStatus::ok;
  }
  d.variables.push_back({"design", "", "the free parameters of each evaluated design (units: parameter_units)",
                         {"evaluation", "parameter"}, design, {}, {}});
  d.variables.push_back({"objective", objective_units(p.objective.kind), objective_long_name(p.objective), {"evaluation"},
                         objective, {}, {}});
  d.variables.push_back({"feasible", "", "every constraint met within its tolerance", {"evaluation"}, is_feasible,
                         {{"flag_meanings", "infeasible feasible"}}, {{"flag_values", {0, 1}}}});
  d.variables.push_back({"status", "", "evaluation status", {"evaluation"}, status, {{"flag_meanings", "ok failed"}},
                         {{"flag_values", {0, 1}}}});
  if (p.model.accuracy > 0) {  // what the stated accuracy chose, and the estimate it met
    d.variables.push_back({"slices_used", "1", "slices the design was scored at", {"evaluation"}, slices_used, {}, {}});
    d.variables.push_back({"slicing_error", "1",
                           "relative slicing error estimate: the larger of the objective's and the measure's",
                           {"evaluation"}, slicing_error, {}, {}});
    d.variables.push_back({"modes_error", "1",
                           "relative error estimate of the dropped modes: the largest of the design's impacts', "
                           "times the objective's sensitivity to them (a carry's 2, a sweet spot width's as read)",
                           {"evaluation"}, modes_error, {}, {}});
    d.variables.push_back({"step_error", "1",
                           "relative error estimate of the time step: the largest of the design's impacts', "
                           "times the objective's sensitivity to them (a carry's 2, a sweet spot width's as read)",
                           {"evaluation"}, step_error, {}, {}});
    d.variables.push_back({"total_error", "1", "the sum of the three estimates", {"evaluation"}, total_error, {}, {}});
  }
  if (any_failed) d.variables.push_back({"failure", "", "why an evaluation failed", {"evaluation"}, messages, {}, {}});
}

}  // namespace

Dataset optimization_dataset(const OptimizationProblem& p, const OptimizationHistory& h, const OptimizationRunInfo& info) {
  Dataset d;
  std::vector<std::int32_t> numbers;
  for (std::size_t i = 0; i < h.evaluations.size(); ++i) numbers.push_back(static_cast<std::int32_t>(i));
  std::vector<std::string> names;
  for (const FreeParameter& f : p.free) names.push_back(f.name);
  d.coordinates.push_back({"evaluation", "", "evaluation number, in the order the optimiser asked", {}, {}, numbers});
  d.coordinates.push_back({"parameter", "", "free parameter of the base bat", {}, names});
  evaluation_variables(p, h, d);
  parameter_variables(p, h.best, h, d);
  constraint_variables(p, h.best, h, d);
  const bool found = h.best >= 0;
  d.variables.push_back({"best_evaluation", "", "the best feasible evaluation; -1 if none", {},
                         std::vector<std::int32_t>{static_cast<std::int32_t>(h.best)}, {}, {}});
  d.variables.push_back({"best_objective", objective_units(p.objective.kind), "the best feasible design's objective", {},
                         std::vector<double>{found ? h.evaluations[static_cast<std::size_t>(h.best)].objective : nan}, {}, {}});
  d.text_attributes = {{"Conventions", "CF-1.8"},
                       {"title", p.title},
                       {"source", std::string("sweetspot ") + version + " (" + git_commit + ")"},
                       {"program_version", version},
                       {"git_commit", git_commit},
                       {"optimization", p.text},
                       {"optimization_file", p.file.string()},
                       {"bat_file", p.base_source.toml_file.string()},
                       {"bat_toml", p.base_source.toml_text},
                       {"objective_kind", to_string(p.objective.kind)},
                       {"algorithm", to_string(p.optimizer.algorithm)},
                       {"stop_reason", h.stop_reason}};
  if (!p.reference_source.toml_file.empty()) {
    d.text_attributes.push_back({"reference_bat_file", p.reference_source.toml_file.string()});
    d.text_attributes.push_back({"reference_bat_toml", p.reference_source.toml_text});
  }
  if (!info.best_bat_file.empty()) d.text_attributes.push_back({"best_bat_file", info.best_bat_file.string()});
  d.number_attributes = {{"wall_time_s", info.wall_time}, {"constraint_tolerance", p.optimizer.constraint_tolerance}};
  d.int_attributes = {{"mpi_ranks", {info.ranks}},
                      {"omp_threads", {info.threads}},
                      {"evaluations", {static_cast<std::int32_t>(h.evaluations.size())}},
                      {"resumed", {info.resumed_evaluations > 0 ? 1 : 0}},
                      {"resumed_evaluations", {info.resumed_evaluations}}};
  return d;
}

}  // namespace sweetspot
