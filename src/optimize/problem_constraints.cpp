// Reading an optimisation file's [constraints]: the standard's measure and its rules on the shape,
// and windows on the designer's numbers.
#include <algorithm>
#include <limits>

#include "problem_values.hpp"
#include "sweetspot/input_error.hpp"

namespace sweetspot::optimize_detail {

namespace {

// A window's bounds may be written with a unit ("2.625 in", "31 oz") where it has a dimension.
struct WindowKey {
  std::string_view name;
  Quantity quantity;
  const char* unit;
  std::optional<Dimension> dimension;
  bool positive;  // no bat has a value of 0 or below: a window there admits none
};
constexpr WindowKey windows[] = {
    {"barrel_diameter", Quantity::barrel_diameter, "m", Dimension::length, true},
    {"drop", Quantity::drop, "length in inches minus weight in ounces", std::nullopt, false},
    {"mass", Quantity::mass, "kg", Dimension::mass, true},
    {"moi_knob", Quantity::moi_knob, "kg m^2", std::nullopt, true},
    {"moi_pivot", Quantity::moi_pivot, "kg m^2", std::nullopt, true},
    {"length", Quantity::length, "m", Dimension::length, true}};

void read_window(const Where& at, const toml::node& node, const WindowKey& w, std::vector<Constraint>& out) {
  const std::string expected = std::string("{ min = ..., max = ... } (") + w.unit + "), either or both";
  if (!node.is_table() || node.as_table()->empty()) reject(at, describe(node), "expected " + expected);
  const toml::table& t = *node.as_table();
  reject_unknown(at, t, {"min", "max"});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double lo = number_key(at, t, "min", nan, finite, "a finite bound", w.dimension),
               hi = number_key(at, t, "max", nan, finite, "a finite bound", w.dimension);
  if (t.get("min") && t.get("max") && !(lo < hi))
    reject(at.child("max", *t.get("max")), format_number(hi), "expected a bound above min = " + format_number(lo));
  // The search would run every evaluation to find no feasible design.
  if (w.positive && t.get("max") && !(hi > 0))
    reject(at.child("max", *t.get("max")), format_number(hi),
           std::string("expected a bound above 0: no bat has a ") + std::string(w.name) + " of 0 or below");
  if (t.get("min")) out.push_back({w.quantity, std::string(w.name), false, lo});
  if (t.get("max")) out.push_back({w.quantity, std::string(w.name), true, hi});
}

}  // namespace

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

}  // namespace sweetspot::optimize_detail
