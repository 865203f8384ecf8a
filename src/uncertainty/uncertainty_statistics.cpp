// An uncertainty study's statistics, added to its dataset on rank 0, and its run.
#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include "sweetspot/bat/bat_design.hpp"
#include "sweetspot/bat/inch_pound.hpp"
#include "sweetspot/impact/certification.hpp"
#include "sweetspot/impact/standards.hpp"
#include "sweetspot/uncertainty/statistics.hpp"
#include "sweetspot/uncertainty/uncertainty_study.hpp"

namespace sweetspot {

namespace {

// A variable's values as numbers (flags and counts are integers on disk); -1, a failed point's
// flag, reads as NaN.
std::vector<double> as_numbers(const Variable& v) {
  if (const auto* numbers = std::get_if<std::vector<double>>(&v.values)) return *numbers;
  std::vector<double> out;
  for (const std::int32_t x : std::get<std::vector<std::int32_t>>(v.values))
    out.push_back(x < 0 ? std::nan("") : static_cast<double>(x));
  return out;
}

void push(std::vector<double>& out, const Estimate& e) { out.insert(out.end(), {e.value, e.lower, e.upper}); }

Variable statistic(const Variable& of, const std::string& suffix, const std::string& what,
                   std::vector<std::string> extra_dims, const std::string& units) {
  std::vector<std::string> dims(of.dims.begin() + 1, of.dims.end());
  dims.insert(dims.end(), extra_dims.begin(), extra_dims.end());
  dims.push_back("bound");
  return Variable{of.name + suffix, units, what + " of " + (of.long_name.empty() ? of.name : of.long_name), dims,
                  std::vector<double>{}, {}, {}};
}

// The statistics of one output over the sample axis, for each combination of its other axes.
void add_output_statistics(const UncertaintyStudy& u, const Variable& v, std::vector<Variable>& out) {
  const std::vector<double> values = as_numbers(v);
  const std::size_t total = u.plan.points(u.inputs.size()), inner = values.size() / total;
  const std::size_t used = u.plan.statistics_points();
  Variable mean = statistic(v, "_mean", "mean", {}, v.units), sd = statistic(v, "_std", "standard deviation", {}, v.units),
           quantile = statistic(v, "_quantile", "quantiles", {"quantile"}, v.units),
           first = statistic(v, "_sobol_first", "first-order Sobol' indices", {"input"}, "1"),
           total_index = statistic(v, "_sobol_total", "total Sobol' indices", {"input"}, "1");
  std::vector<double> means, sds, quantiles, firsts, totals, column(total);
  std::vector<std::vector<double>> inputs;
  if (u.plan.sensitivity)
    for (const Axis& drawn : u.study.sampled) inputs.push_back(drawn.values);
  for (std::size_t j = 0; j < inner; ++j) {
    for (std::size_t i = 0; i < total; ++i) column[i] = values[i * inner + j];
    const SampleSummary s = summarize(std::span(column).first(used), u.plan.confidence, u.plan.quantiles);
    push(means, s.mean), push(sds, s.sd);
    for (const Estimate& q : s.quantiles) push(quantiles, q);
    if (!u.plan.sensitivity) continue;
    const SobolIndices indices = sobol_indices(inputs, column, u.plan.size, u.plan.confidence);
    for (const Estimate& e : indices.first) push(firsts, e);
    for (const Estimate& e : indices.total) push(totals, e);
  }
  mean.values = std::move(means), sd.values = std::move(sds), quantile.values = std::move(quantiles);
  out.push_back(std::move(mean)), out.push_back(std::move(sd)), out.push_back(std::move(quantile));
  if (u.plan.sensitivity) {
    first.values = std::move(firsts), total_index.values = std::move(totals);
    out.push_back(std::move(first)), out.push_back(std::move(total_index));
  }
}

const Variable* find_variable(const Dataset& d, const std::string& name) {
  const auto it = std::ranges::find(d.variables, name, &Variable::name);
  return it == d.variables.end() ? nullptr : &*it;
}

// A certification's probability of passing each rule of its standard (and all of them), from
// the samples' measure at its maximum and each sample's bat.
void add_pass_probabilities(const UncertaintyStudy& u, Dataset& d) {
  const Study& study = u.study;
  const Standard& standard = standards()[study.standard];
  const Variable* measure = find_variable(d, to_string(standard.measure));
  if (study.kind != StudyKind::certification || !measure || measure->dims.size() != 1) return;
  const std::vector<double> values = as_numbers(*measure);
  std::vector<std::string> rules;
  std::vector<std::size_t> passes;
  std::size_t count = 0, all = 0;
  for (std::size_t i = 0; i < u.plan.statistics_points(); ++i) {
    if (!std::isfinite(values[i])) continue;  // a failed point
    const std::size_t design = study.sampled_designs ? i : 0;
    const BatDesign& bat = study.design_specs[design];
    const double barrel = largest_outer_diameter(bat);
    const std::vector<RuleCheck> checks =
        rule_checks(standard, values[i], barrel, bat_drop(bat.length, study.design_mass[design].mass), bat.length);
    if (rules.empty())
      for (const RuleCheck& c : checks) rules.push_back(c.rule), passes.push_back(0);
    bool every = true;
    for (std::size_t r = 0; r < checks.size(); ++r) passes[r] += checks[r].pass, every = every && checks[r].pass;
    all += every, ++count;
  }
  if (count == 0) return;
  rules.push_back("all");
  passes.push_back(all);
  std::vector<double> probability;
  for (const std::size_t p : passes) push(probability, proportion(p, count, u.plan.confidence));
  d.coordinates.push_back(Coordinate{"rule", "", "rule of the standard (value <= limit), and all of them", {}, rules});
  d.variables.push_back(Variable{"pass_probability", "1",
                                 "probability that the bat passes the rule (" + standard.name + ")",
                                 {"rule", "bound"}, std::move(probability), {}, {}});
}

}  // namespace

void add_uncertainty_statistics(const UncertaintyStudy& u, Dataset& d) {
  d.coordinates.push_back(Coordinate{"bound", "", "the estimate and its confidence interval", {},
                                     {"estimate", "lower", "upper"}});
  d.coordinates.push_back(Coordinate{"quantile", "1", "probability level of the quantile", u.plan.quantiles, {}});
  std::vector<std::string> inputs;
  for (const Axis& drawn : u.study.sampled) inputs.push_back(dataset_name(drawn.name));
  if (u.plan.sensitivity)
    d.coordinates.push_back(Coordinate{"input", "", "uncertain input (the variable of its samples)", {}, inputs});
  std::vector<Variable> statistics;
  for (const Variable& v : d.variables) {
    const bool drawn = std::ranges::count(inputs, v.name) > 0;
    // Flags are not quantities: a certification's verdict is pass_probability, with its own interval.
    if (v.dims.empty() || v.dims.front() != sample_axis || drawn || v.name == "status" || v.name == "certified" ||
        std::holds_alternative<std::vector<std::string>>(v.values))
      continue;
    add_output_statistics(u, v, statistics);
  }
  for (Variable& v : statistics) d.variables.push_back(std::move(v));
  add_pass_probabilities(u, d);
  d.text_attributes.push_back({"uncertainty_method", to_string(u.plan.method)});
  d.number_attributes.push_back({"uncertainty_size", static_cast<double>(u.plan.size)});
  d.number_attributes.push_back({"uncertainty_seed", static_cast<double>(u.plan.seed)});
  d.number_attributes.push_back({"uncertainty_confidence", u.plan.confidence});
  d.number_attributes.push_back({"uncertainty_statistics_samples", static_cast<double>(u.plan.statistics_points())});
}

void run_uncertainty_study(const UncertaintyStudy& u, RunOptions options) {
  options.finish = [&u](Dataset& d) { add_uncertainty_statistics(u, d); };
  run_study(u.study, options);
}

}  // namespace sweetspot
