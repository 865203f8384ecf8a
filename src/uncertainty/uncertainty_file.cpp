// Reading an uncertainty study's [uncertain] and [sampling] tables, and its draw.
#include <algorithm>
#include <cmath>
#include <string>

#include "study/study_settings.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/study/study_memory.hpp"
#include "sweetspot/uncertainty/uncertainty_study.hpp"
#include "toml_values.hpp"

namespace sweetspot {

using namespace study_detail;
using detail::describe;
using detail::format_number;
using detail::quote;

namespace {

constexpr double max_points = 1e9;  // as any study's grid
constexpr std::size_t min_sensitivity_size = 64;

// The entries of a table in the order written (toml++ keeps them sorted).
std::vector<std::pair<std::string, const toml::node*>> in_written_order(const toml::table& table) {
  std::vector<std::pair<std::string, const toml::node*>> entries;
  for (const auto& [key, node] : table) entries.emplace_back(std::string(key.str()), &node);
  std::ranges::sort(entries, {}, [](const auto& e) {
    const toml::source_position at = e.second->source().begin;
    return std::pair(at.line, at.column);
  });
  return entries;
}

const toml::table& table_at(const Where& top, const toml::table& doc, std::string_view name, bool required) {
  static const toml::table empty;
  const toml::node* node = doc.get(name);
  if (!node) {
    if (required)
      reject(Where{top.file, std::string(name), 0}, "", "an uncertainty study needs a table [" + std::string(name) + "]");
    return empty;
  }
  if (!node->is_table()) reject(top.child(name, *node), describe(*node), "expected a table [" + std::string(name) + "]");
  return *node->as_table();
}

double number_at(const Where& at, const toml::table& table, std::string_view name, bool (*valid)(double),
                 const std::string& expected) {
  const toml::node* node = table.get(name);
  if (!node) reject(at.missing(name), "", expected);
  const std::optional<double> x = detail::number(*node);
  if (!x || !valid(*x)) reject(at.child(name, *node), describe(*node), expected);
  return *x;
}

bool finite(double x) { return std::isfinite(x); }
bool positive(double x) { return std::isfinite(x) && x > 0; }
bool open_unit(double x) { return x > 0 && x < 1; }

InputDistribution read_distribution(const Where& at, const std::string& key, const toml::node& node) {
  if (!node.is_table())
    reject(at, describe(node), "expected a distribution, e.g. { distribution = \"normal\", mean = 40, sd = 0.5 }");
  const toml::table& t = *node.as_table();
  InputDistribution d;
  d.key = key;
  d.line = at.line;
  const toml::node* shape = t.get("distribution");
  const std::string kinds = "\"normal\", \"truncated_normal\", \"uniform\" or \"lognormal\"";
  if (!shape) reject(at.missing("distribution"), "", "expected " + kinds);
  const Where shape_at = at.child("distribution", *shape);
  const std::string name = shape->value<std::string>().value_or("");
  const char* sd_expected = "expected a standard deviation > 0 (a fixed value belongs in [scene])";
  if (name == "normal" || name == "truncated_normal") {
    d.shape = name == "normal" ? Shape::normal : Shape::truncated_normal;
    d.mean = number_at(at, t, "mean", finite, "expected a finite mean");
    d.sd = number_at(at, t, "sd", positive, sd_expected);
  } else if (name == "lognormal") {
    d.shape = Shape::lognormal;
    d.mean = number_at(at, t, "mean", positive, "expected a mean > 0 (a log-normal variable is positive)");
    d.sd = number_at(at, t, "sd", positive, sd_expected);
    // Its logarithm's spread, log(1 + (sd/mean)^2), must be finite and above 0 for OpenTURNS.
    const double variation = d.sd / d.mean;
    if (!(variation >= 1e-100 && variation <= 1e100))
      reject(at.child("sd", *t.get("sd")), format_number(d.sd),
             "expected sd / mean from 1e-100 to 1e100 (the log-normal's parameters are its logarithm's)");
  } else if (name == "uniform") {
    d.shape = Shape::uniform;
  } else {
    reject(shape_at, describe(*shape), "expected " + kinds);
  }
  if (d.shape == Shape::truncated_normal || d.shape == Shape::uniform) {
    d.lower = number_at(at, t, "lower", finite, "expected a finite lower bound");
    d.upper = number_at(at, t, "upper", finite, "expected a finite upper bound");
    if (!(d.lower < d.upper))
      reject(at.child("upper", *t.get("upper")), format_number(d.upper),
             "expected an upper bound above the lower bound " + format_number(d.lower));
    if (!std::isfinite(d.upper - d.lower))
      reject(at.child("upper", *t.get("upper")), format_number(d.upper),
             "expected bounds whose difference is a finite number");
  }
  // Far wider than its window a truncated normal is the uniform one, and OpenTURNS's draw from it
  // no longer stays inside the window (sd 1e15 on [0.4, 0.6] drew 0.36).
  if (d.shape == Shape::truncated_normal && !(d.sd <= 1e6 * (d.upper - d.lower)))
    reject(at.child("sd", *t.get("sd")), format_number(d.sd),
           "expected sd at most 1e6 times upper - lower (wider, the distribution is \"uniform\" on them)");
  if (d.shape == Shape::truncated_normal && (d.mean < d.lower || d.mean > d.upper))
    reject(at.child("mean", *t.get("mean")), format_number(d.mean),
           "expected a mean within the bounds [" + format_number(d.lower) + ", " + format_number(d.upper) + "]");
  switch (d.shape) {
    case Shape::normal:
    case Shape::lognormal:
      reject_unknown(at, t, {"distribution", "mean", "sd"});
      break;
    case Shape::truncated_normal:
      reject_unknown(at, t, {"distribution", "mean", "sd", "lower", "upper"});
      break;
    case Shape::uniform:
      reject_unknown(at, t, {"distribution", "lower", "upper"});
      break;
  }
  return d;
}

std::vector<InputDistribution> read_inputs(const Where& top, const toml::table& doc) {
  const toml::table& table = table_at(top, doc, "uncertain", true);
  const Where at = top.child("uncertain", table);
  std::vector<InputDistribution> inputs;
  for (const auto& [key, node] : in_written_order(table)) inputs.push_back(read_distribution(at.child(key, *node), key, *node));
  if (inputs.empty()) reject(at, "{}", "expected at least one key with its distribution");
  return inputs;
}

SamplingMethod read_method(const Where& at, const toml::table& t) {
  const toml::node* node = t.get("method");
  if (!node) return SamplingMethod::latin_hypercube;
  for (const SamplingMethod m : {SamplingMethod::monte_carlo, SamplingMethod::latin_hypercube, SamplingMethod::low_discrepancy})
    if (node->value<std::string>() == std::string(to_string(m))) return m;
  reject(at.child("method", *node), describe(*node), "expected \"monte_carlo\", \"latin_hypercube\" or \"low_discrepancy\"");
}

std::size_t index_of(const Where& at, const std::vector<InputDistribution>& inputs, const toml::node& node) {
  const std::string key = node.value<std::string>().value_or("");
  const auto it = std::ranges::find(inputs, key, &InputDistribution::key);
  if (it == inputs.end()) reject(at, describe(node), "expected a key of [uncertain]");
  return static_cast<std::size_t>(it - inputs.begin());
}

std::vector<InputCorrelation> read_correlations(const Where& at, const toml::table& t,
                                                const std::vector<InputDistribution>& inputs) {
  std::vector<InputCorrelation> correlations;
  const toml::node* node = t.get("correlation");
  if (!node) return correlations;
  const Where list_at = at.child("correlation", *node);
  const char* expected = "expected a list of [\"KEY\", \"KEY\", CORRELATION] with two keys of [uncertain] and a "
                         "correlation in (-1, 1)";
  if (!node->is_array()) reject(list_at, describe(*node), expected);
  const toml::array& list = *node->as_array();
  for (std::size_t i = 0; i < list.size(); ++i) {
    const Where item = list_at.item(i, list[i]);
    const toml::array* triple = list[i].as_array();
    if (!triple || triple->size() != 3) reject(item, describe(list[i]), expected);
    const std::optional<double> r = detail::number((*triple)[2]);
    if (!r || !(*r > -1 && *r < 1)) reject(item, describe(list[i]), expected);
    const InputCorrelation c{index_of(item, inputs, (*triple)[0]), index_of(item, inputs, (*triple)[1]), *r};
    if (c.first == c.second) reject(item, describe(list[i]), expected);
    // A pair given twice (in either order) would have the later silently overrule the earlier.
    for (const InputCorrelation& earlier : correlations)
      if (std::minmax(earlier.first, earlier.second) == std::minmax(c.first, c.second))
        reject(item, describe(list[i]), "expected each pair of keys once: this pair's correlation is given before");
    correlations.push_back(c);
  }
  return correlations;
}

// How many outputs the study asks (each at least one value per point); the study's [output]
// checks them later, after the draw.
double output_count(const toml::table& doc) {
  const toml::node* output = doc.get("output");
  const toml::node* variables = output && output->is_table() ? output->as_table()->get("variables") : nullptr;
  return variables && variables->is_array() ? static_cast<double>(variables->as_array()->size()) : 1;
}

SamplingPlan read_plan(const Where& top, const toml::table& doc, const std::vector<InputDistribution>& inputs) {
  const toml::table& t = table_at(top, doc, "sampling", true);
  const Where at = top.child("sampling", t);
  reject_unknown(at, t, {"method", "size", "seed", "sensitivity", "confidence", "quantiles", "correlation"});
  SamplingPlan plan;
  plan.method = read_method(at, t);
  const double size = number_at(at, t, "size", [](double x) { return x >= 2 && x == std::floor(x) && x <= 1e15; },
                                "expected a whole number of samples >= 2");
  plan.size = static_cast<std::size_t>(size);
  if (const toml::node* seed = t.get("seed")) {
    // OpenTURNS's generator takes 32 bits: a larger seed would alias a smaller one.
    const std::optional<std::int64_t> s = seed->value_exact<std::int64_t>();
    if (!s || *s < 0 || *s > 4294967295)
      reject(at.child("seed", *seed), describe(*seed), "expected a whole number from 0 to 4294967295");
    plan.seed = static_cast<std::uint64_t>(*s);
  }
  if (const toml::node* sensitivity = t.get("sensitivity")) {
    if (!sensitivity->is_boolean()) reject(at.child("sensitivity", *sensitivity), describe(*sensitivity), "expected true or false");
    plan.sensitivity = sensitivity->as_boolean()->get();
    // The Sobol' intervals are asymptotic: at a handful of samples they exclude the index itself
    // (size 2: a first-order index of 1.0 in [0.95, 1.05] for an input whose share is 0.05).
    if (plan.sensitivity && plan.size < min_sensitivity_size)
      reject(at.child("size", *t.get("size")), std::to_string(plan.size),
             "expected at least " + std::to_string(min_sensitivity_size) +
                 " samples with sensitivity = true (the Sobol' indices' intervals are asymptotic)");
  }
  if (t.get("confidence"))
    plan.confidence = number_at(at, t, "confidence", open_unit, "expected a confidence level in (0, 1), e.g. 0.95");
  if (const toml::node* levels = t.get("quantiles")) {
    const Where levels_at = at.child("quantiles", *levels);
    const char* expected = "expected a list of levels in (0, 1), e.g. [0.05, 0.5, 0.95]";
    if (!levels->is_array() || levels->as_array()->empty()) reject(levels_at, describe(*levels), expected);
    plan.quantiles.clear();
    for (const toml::node& level : *levels->as_array()) {
      const std::optional<double> p = detail::number(level);
      if (!p || !open_unit(*p)) reject(levels_at, describe(level), expected);
      if (std::ranges::count(plan.quantiles, *p) > 0)
        reject(levels_at, describe(level), "expected each level once (the dataset's quantile coordinate)");
      plan.quantiles.push_back(*p);
    }
  }
  plan.correlations = read_correlations(at, t, inputs);
  if (plan.method == SamplingMethod::latin_hypercube && !plan.correlations.empty())
    reject(at.child("correlation", *t.get("correlation")), "[...]",
           "OpenTURNS's Latin hypercube draws independent inputs only: use method = \"monte_carlo\" or "
           "\"low_discrepancy\" for correlated ones");
  if (plan.sensitivity && !plan.correlations.empty())
    reject(at.child("sensitivity", *t.get("sensitivity")), "true",
           "Sobol' indices need independent inputs: drop sampling.correlation or the sensitivity");
  // The points and the memory the draw takes (its columns, OpenTURNS's sample and the study's
  // copy) with the outputs asked (each twice: the rows and the dataset), checked before a single
  // value is drawn; the study's own, finer, check of its results follows the draw
  // (check_study_memory).
  const double points = static_cast<double>(plan.size) * (plan.sensitivity ? static_cast<double>(inputs.size()) + 2 : 1);
  if (points > max_points)
    reject(at.child("size", *t.get("size")), format_number(size),
           "makes " + format_number(points) + " points; at most 1e9");
  const double outputs = std::max(1.0, output_count(doc));
  const double bytes = points * (3 * static_cast<double>(inputs.size()) + 2 * outputs) * sizeof(double);
  if (bytes > machine_memory_bytes() / 2)
    reject(at.child("size", *t.get("size")), format_number(size),
           "the samples and their " + format_number(outputs) + " outputs need " + format_number(bytes / 1e9) +
               " GB, more than half the " + format_number(machine_memory_bytes() / 1e9) + " GB this machine has");
  return plan;
}

}  // namespace

UncertaintyStudy load_uncertainty_study(const std::filesystem::path& file) {
  std::string text = read_text(file);
  const toml::table doc = parse_toml(file, text);
  const Where top{&file, "", 0};
  SampledKeys sampled;
  if (const toml::node* model = doc.get("model")) {
    const std::string name = model->value<std::string>().value_or("");
    bool known = false;
    for (const StudyKind k : {StudyKind::impact, StudyKind::wall, StudyKind::toy, StudyKind::certification})
      if (name == to_string(k)) sampled.model = k, known = true;
    if (!known)
      reject(top.child("model", *model), describe(*model),
             "expected the kind each sample computes: \"impact\", \"wall\", \"toy\" or \"certification\"");
  }
  UncertaintyStudy u;
  u.inputs = read_inputs(top, doc);
  u.plan = read_plan(top, doc, u.inputs);
  const std::vector<std::vector<double>> columns = draw_samples(u.inputs, u.plan, file.string());
  sampled.samples = u.plan.points(u.inputs.size());
  for (std::size_t k = 0; k < u.inputs.size(); ++k) {
    sampled.keys.push_back(Axis{u.inputs[k].key, columns[k], {}});
    sampled.lines.push_back(u.inputs[k].line);
  }
  u.study = load_sampled_study(file, std::move(text), sampled);
  return u;
}

}  // namespace sweetspot
