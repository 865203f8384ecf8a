// Reading a study file's values: [scene] keys, axes (lists and ranges), the kind and [output].
#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>

#include "study_settings.hpp"
#include "sweetspot/bat/material_presets.hpp"
#include "sweetspot/impact/standards.hpp"
#include "sweetspot/input_error.hpp"
#include "toml_parse.hpp"
#include "toml_values.hpp"

namespace sweetspot::study_detail {

using detail::describe;
using detail::describe_quantity;
using detail::format_number;
using detail::quote;

void reject(const Where& at, const std::string& value, const std::string& expected) {
  std::string text = at.file->string() + (at.line ? ":" + std::to_string(at.line) : "") + ": key '" + at.key + "'" +
                     (value.empty() ? " is missing" : " = " + value) + ": " + expected;
  std::replace(text.begin(), text.end(), '\n', ' ');
  throw InputError(text);
}

std::string Setting::value_text(std::size_t i) const {
  if (i < labels.size()) return quote(labels[i]);
  if (i < written.size()) return written[i];
  return format_number(values[i]);
}

const Setting* find(const std::vector<Setting>& settings, std::string_view name) {
  const auto it = std::ranges::find_if(settings, [&](const Setting& s) { return s.name == name; });
  return it == settings.end() ? nullptr : &*it;
}

namespace {

// A standard's place in standards().
double standard_index(const Where& at, const std::string& name) {
  const std::vector<Standard>& all = standards();
  const auto it = std::ranges::find(all, name, &Standard::name);
  if (it == all.end()) reject(at, quote(name), "expected \"bbcor\", \"besr\" or \"bpf\"");
  return static_cast<double>(it - all.begin());
}

// A wood preset's place in material_preset_list().
double material_preset_index(const Where& at, const std::string& name) {
  const std::vector<MaterialPreset>& presets = material_preset_list();
  const auto it = std::ranges::find(presets, name, &MaterialPreset::name);
  if (it != presets.end()) return static_cast<double>(it - presets.begin());
  std::string names;
  for (const MaterialPreset& p : presets) names += (names.empty() ? "" : ", ") + quote(p.name);
  reject(at, quote(name), "expected a wood preset: one of " + names);
}

// Bounds that keep a mistyped step (1e-9 for 1e-2) from exhausting memory before any work.
constexpr double max_axis_values = 1e6;

// ---- Reading values ----------------------------------------------------------------------------

// toml++ keeps a table's keys sorted, but axis order is the order written: recover it.
std::vector<std::pair<std::string_view, const toml::node*>> written_order(const toml::table& table) {
  std::vector<std::pair<std::string_view, const toml::node*>> entries;
  for (const auto& [key, node] : table) entries.emplace_back(key.str(), &node);
  const auto position = [](const auto& e) {
    const toml::source_position at = e.second->source().begin;
    return std::pair(at.line, at.column);
  };
  std::ranges::sort(entries, {}, position);
  return entries;
}

}  // namespace

// Unknown keys are errors: a misspelt optional key would otherwise be silently ignored.
void reject_unknown(const Where& at, const toml::table& table, std::initializer_list<std::string_view> known) {
  std::string list;
  for (const std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
  for (const auto& [key, node] : written_order(table))
    if (std::ranges::find(known, key) == known.end())
      reject(at.child(key, *node), describe(*node), "unknown key; expected one of " + list);
}

namespace {

const toml::table* subtable(const Where& at, const toml::table& parent, std::string_view name) {
  const toml::node* node = parent.get(name);
  if (node && !node->is_table())
    reject(at.child(name, *node), describe(*node), "expected a table [" + at.child(name, *node).key + "]");
  return node ? node->as_table() : nullptr;
}

// A scene value as a number (see Axis); `label` keeps the names of bat and theory values,
// `written` the value as the file has it.
struct Value {
  double number = 0;
  std::string label;
  std::string written = {};
};

// A study's angles (wind_direction) are in degrees, as the flight calculator's: a plain number
// is one, and a quantity written with its unit is converted to them, not to SI's radians.
double in_key_units(Dimension dimension, double si) {
  return dimension == Dimension::angle ? si / (std::numbers::pi / 180) : si;
}

std::string key_quantity_hint(Dimension dimension) {
  if (dimension == Dimension::angle) return "(a number in deg, or a string such as \"30 deg\"; units deg, rad)";
  return quantity_hint(dimension);
}

// A value the key takes, with the units it may be written in when it has a dimension.
std::string expected_value(const KeySpec& spec, std::optional<Dimension> dimension) {
  return std::string(spec.expected) + (dimension ? " " + key_quantity_hint(*dimension) : "");
}

Value read_number(const Where& at, const KeySpec& spec, std::optional<Dimension> dimension, const toml::node& node) {
  const auto bad = [&] {
    reject(at, dimension ? describe_quantity(node) : describe(node), "expected " + expected_value(spec, dimension));
  };
  Value v;
  const bool numeric = spec.type == Type::number || spec.type == Type::numbers || spec.type == Type::bat_parameter;
  if (numeric && dimension && node.is_string()) {
    const std::optional<double> x = detail::quantity(node, *dimension);
    if (!x) bad();
    v.number = in_key_units(*dimension, *x);
  } else if (numeric && node.is_number())
    v.number = *detail::number(node);
  else if ((spec.type == Type::integer || spec.type == Type::modes) && node.is_integer())
    v.number = static_cast<double>(node.as_integer()->get());
  else if (spec.type == Type::boolean && node.is_boolean())
    v.number = node.as_boolean()->get();
  else if (spec.type == Type::modes && node.value<std::string_view>() == "all")
    return {all_modes, ""};
  else if (spec.type == Type::modes && node.value<std::string_view>() == "auto")
    return {auto_modes, ""};
  else if ((spec.type == Type::bat || spec.type == Type::theory || spec.type == Type::integrator ||
            spec.type == Type::material || spec.type == Type::reference) &&
           node.is_string())
    v.label = node.as_string()->get();
  else if (spec.type == Type::standard && node.is_string())
    return {standard_index(at, node.as_string()->get()), node.as_string()->get()};
  else if (spec.type == Type::swing && (node.value<std::string_view>() == "given" ||
                                        node.value<std::string_view>() == "equal_effort"))
    return {node.value<std::string_view>() == "equal_effort" ? 1.0 : 0.0, std::string(*node.value<std::string_view>())};
  else if (spec.type == Type::preset && node.value<std::string_view>() == "n2000")
    return {0, "n2000"};
  else
    bad();
  if ((spec.type == Type::bat || spec.type == Type::reference) && v.label.empty()) bad();
  try {
    if (spec.type == Type::theory) v.number = static_cast<double>(parse_beam_theory(v.label));
    if (spec.type == Type::integrator) v.number = static_cast<double>(parse_method(v.label));
  } catch (const InputError&) {
    bad();
  }
  if (spec.type == Type::material) v.number = material_preset_index(at, v.label);
  if (!spec.valid(v.number)) bad();
  return v;
}

Value read_value(const Where& at, const KeySpec& spec, std::optional<Dimension> dimension, const toml::node& node) {
  Value v = read_number(at, spec, dimension, node);
  v.written = dimension ? describe_quantity(node) : describe(node);
  return v;
}

void add(Setting& s, Value v) {
  s.values.push_back(v.number);
  s.written.push_back(std::move(v.written));
  if (s.spec->type == Type::bat || s.spec->type == Type::theory || s.spec->type == Type::material ||
      s.spec->type == Type::reference)
    s.labels.push_back(std::move(v.label));
}

// 15 significant digits: 0.305 + 3 * 0.01 becomes the 0.335 a reader expects.
double tidy(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", x);
  return std::strtod(text, nullptr);
}

// A bound (start, stop or step) of a range: for a key with a dimension, in any of its units.
double range_bound(const Where& at, const toml::table& range, std::string_view name, bool integer,
                   std::optional<Dimension> dimension) {
  const toml::node* node = range.get(name);
  if (!node) reject(at.missing(name), "", "a range needs start, stop and either step or count");
  if (dimension) {
    const std::optional<double> x = detail::quantity(*node, *dimension);
    if (!x || !std::isfinite(*x))
      reject(at.child(name, *node), describe_quantity(*node),
             "expected a finite " + std::string(dimension_name(*dimension)) + " " + key_quantity_hint(*dimension));
    return in_key_units(*dimension, *x);
  }
  if (!(integer ? node->is_integer() : node->is_number()) || !std::isfinite(*detail::number(*node)))
    reject(at.child(name, *node), describe(*node), integer ? "expected an integer" : "expected a finite number");
  return *detail::number(*node);
}

// {start, stop, step}: stop is included when it lands within 1e-9 step of a point.
std::vector<double> stepped_range(const Where& at, const toml::table& range, double start, double stop, bool integer,
                                  std::optional<Dimension> dimension) {
  const double step = range_bound(at, range, "step", integer, dimension);
  const Where where = at.child("step", *range.get("step"));
  if (step == 0 || (stop - start) * step < 0)
    reject(where, format_number(step), "expected a step with the sign of stop - start = " +
                                           format_number(stop - start) + (step == 0 ? ", not 0" : ""));
  const double n = std::floor((stop - start) / step + 1e-9) + 1;
  if (n > max_axis_values)
    reject(where, format_number(step), "gives " + format_number(n) + " values; an axis has at most 1e6");
  std::vector<double> values;
  for (int i = 0; i < n; ++i) values.push_back(tidy(start + i * step));
  if (std::abs(values.back() - stop) <= 1e-9 * std::abs(step)) values.back() = stop;
  return values;
}

// {start, stop, count[, spacing]}: count points, both ends included, evenly spaced in the value
// or (spacing = "log") in its logarithm, as for omega tau over decades.
std::vector<double> counted_range(const Where& at, const toml::table& range, double start, double stop, bool log) {
  const toml::node& node = *range.get("count");
  if (!node.is_integer() || node.as_integer()->get() < 1 || node.as_integer()->get() > max_axis_values)
    reject(at.child("count", node), describe(node), "expected an integer count from 1 to 1e6");
  for (const auto& [name, value] : {std::pair<std::string_view, double>{"start", start}, {"stop", stop}})
    if (log && !(value > 0))
      reject(at.child(name, *range.get(name)), format_number(value), "a log range needs start and stop > 0");
  const auto n = node.as_integer()->get();
  const auto interior = [&](double fraction) {
    return tidy(log ? start * std::pow(stop / start, fraction) : start + fraction * (stop - start));
  };
  std::vector<double> values;
  for (int i = 0; i < n; ++i)
    values.push_back(n == 1 ? start : i + 1 == n ? stop : interior(static_cast<double>(i) / (n - 1)));
  return values;
}

// spacing = "linear" (the default) or "log"; only a range with a count has a spacing.
bool log_spacing(const Where& at, const toml::table& range) {
  const toml::node* node = range.get("spacing");
  if (!node) return false;
  const Where where = at.child("spacing", *node);
  const std::optional<std::string_view> name = node->value<std::string_view>();
  if (!node->is_string() || (name != "linear" && name != "log"))
    reject(where, describe(*node), "expected \"linear\" or \"log\"");
  if (range.contains("step")) reject(where, describe(*node), "a spacing goes with count, not step");
  return name == "log";
}

std::vector<double> read_range(const Where& at, const KeySpec& spec, std::optional<Dimension> dimension,
                               const toml::table& range) {
  reject_unknown(at, range, {"start", "stop", "step", "count", "spacing"});
  const bool integer = spec.type == Type::integer || spec.type == Type::modes;  // slices, modes
  const double start = range_bound(at, range, "start", integer, dimension),
               stop = range_bound(at, range, "stop", integer, dimension);
  if (range.contains("step") == range.contains("count"))
    reject(at, "{...}", "a range needs exactly one of step and count");
  const bool log = log_spacing(at, range);
  const std::vector<double> values = range.contains("step") ? stepped_range(at, range, start, stop, integer, dimension)
                                                            : counted_range(at, range, start, stop, log);
  for (const double x : values)
    if (!spec.valid(x) || (integer && x != std::round(x)))
      reject(at, format_number(x), "the range gives a value that is not " + std::string(spec.expected));
  return values;
}

template <class T>
std::optional<T> first_repeat(std::vector<T> items) {
  std::ranges::sort(items);
  const auto twice = std::ranges::adjacent_find(items);
  return twice == items.end() ? std::nullopt : std::optional(*twice);
}

// The second of two equal values as written, with the first where it was written otherwise
// ("71.12 cm", the same as "28 in"), or nothing.
// Sorted, not pairwise: an axis may hold 1e6 values (a pairwise check of 300 000 took 47 s).
std::optional<std::string> repeated_value(const Setting& s) {
  std::vector<std::size_t> order;  // the values' indices, NaN (equal to nothing) left out
  for (std::size_t i = 0; i < s.values.size(); ++i)
    if (!std::isnan(s.values[i])) order.push_back(i);
  std::ranges::stable_sort(order, {}, [&s](std::size_t i) { return s.values[i]; });
  // Each run of equal values' first two indices: the earliest second one is the first repeat met
  // in the order written, and its run's first the value it repeats.
  std::optional<std::pair<std::size_t, std::size_t>> first;
  for (std::size_t k = 1; k < order.size(); ++k)
    if (s.values[order[k]] == s.values[order[k - 1]] && (k == 1 || s.values[order[k - 2]] != s.values[order[k]]) &&
        (!first || order[k] < first->second))
      first = std::pair(order[k - 1], order[k]);
  if (!first) return std::nullopt;
  const auto [i, j] = *first;
  return s.value_text(j) + (s.value_text(i) == s.value_text(j) ? "" : " (the same as " + s.value_text(i) + ")");
}

// Repeated values would make the axis useless as a coordinate (which point is z = 0.5?).
void reject_duplicates(const Setting& s, const fs::path& dir) {
  if (s.spec->type == Type::bat) {
    std::vector<std::string> paths;
    for (const std::string& label : s.labels) paths.push_back((dir / label).lexically_normal().string());
    if (const auto twice = first_repeat(paths)) reject(s.where, quote(*twice), "names the same bat file twice");
  } else if (!s.labels.empty()) {  // names (a material, a theory) stand for their index in the values
    if (const auto twice = first_repeat(s.labels)) reject(s.where, quote(*twice), "appears twice in the axis; its values must differ");
  } else if (const auto twice = repeated_value(s)) {
    reject(s.where, *twice, "appears twice in the axis; its values must differ");
  }
}

Setting read_axis(const Where& at, const KeySpec& spec, std::optional<Dimension> dimension, const toml::node& node,
                  const fs::path& dir) {
  Setting s{&spec, at, {}, {}};
  const bool numeric = spec.type == Type::number || spec.type == Type::integer || spec.type == Type::modes ||
                       spec.type == Type::bat_parameter;
  if (const toml::array* list = node.as_array()) {
    for (std::size_t i = 0; i < list->size(); ++i)
      add(s, read_value(at.item(i, (*list)[i]), spec, dimension, (*list)[i]));
  } else if (numeric && node.is_table()) {
    s.values = read_range(at, spec, dimension, *node.as_table());
    for (const double x : s.values) s.written.push_back(format_number(x));
  } else {
    reject(at, describe(node),
           "expected a list of values, each " + expected_value(spec, dimension) +
               (numeric ? ", or a range {start, stop, step} or {start, stop, count[, spacing = \"log\"]}" : ""));
  }
  if (s.values.empty()) reject(at, "[]", "an axis needs at least one value");
  reject_duplicates(s, dir);
  return s;
}

// A list-valued [scene] key (probes): one or more distinct values.
Setting read_list(const Where& at, const KeySpec& spec, const toml::node& node) {
  Setting s{&spec, at, {}, {}};
  const toml::array* list = node.as_array();
  if (!list || list->empty()) reject(at, describe(node), "expected " + expected_value(spec, spec.dimension));
  for (std::size_t i = 0; i < list->size(); ++i)
    add(s, read_value(at.item(i, (*list)[i]), spec, spec.dimension, (*list)[i]));
  if (const auto twice = repeated_value(s)) reject(at, *twice, "appears twice in the list; its values must differ");
  return s;
}

// Why a key of the table cannot stand here, or empty when it can.
std::string misplaced(const KeySpec* spec, StudyKind kind, bool axes) {
  if (!spec) return "unknown key";
  if (!(spec->kinds & bit(kind))) return "does not apply to kind " + kind_text(kind);
  if (axes && !spec->axis) return "cannot be an axis";
  return "";
}

}  // namespace

std::vector<Setting> read_settings(const Where& top, const toml::table& doc, std::string_view section,
                                   StudyKind kind) {
  std::vector<Setting> settings;
  const toml::table* table = subtable(top, doc, section);
  if (!table) return settings;
  const bool axes = section == "axes";
  const Where at{top.file, std::string(section), 0};
  for (const auto& [name, node] : written_order(*table)) {
    const KeySpec* spec = find_key(name);
    const Where where = at.child(name, *node);
    if (const std::string why = misplaced(spec, kind, axes); !why.empty())
      reject(where, describe(*node), why + "; expected one of " + key_list(kind, axes) +
                                         (kind == StudyKind::impact ? ", or \"bat.PARAMETER\"" : ""));
    // TOML reads bat.density = ... unquoted as a table bat = {density = ...}.
    if (spec->type == Type::bat && node->is_table())
      reject(where, describe(*node), "a bat parameter is a quoted key: \"bat.density\" = ..., not bat.density = ...");
    const std::optional<Dimension> dimension = key_dimension(*spec, name);
    if (axes)
      settings.push_back(read_axis(where, *spec, dimension, *node, top.file->parent_path()));
    else if (spec->type == Type::numbers)
      settings.push_back(read_list(where, *spec, *node));
    else
      add(settings.emplace_back(Setting{spec, where, {}, {}}), read_value(where, *spec, dimension, *node));
    settings.back().name = std::string(name);
  }
  return settings;
}


// ---- The kind ----------------------------------------------------------------------------------

constexpr StudyKind study_kinds[] = {StudyKind::impact, StudyKind::wall, StudyKind::toy, StudyKind::certification};

StudyKind read_kind(const Where& top, const toml::table& doc) {
  const toml::node* node = doc.get("kind");
  if (!node) return StudyKind::impact;
  if (node->value<std::string_view>() == "uncertainty")  // a study of another kind, drawn: sweetspot/uncertainty
    reject(top.child("kind", *node), describe(*node),
           "an uncertainty study is loaded by load_uncertainty_study (sweetspot run, certify --uncertainty)");
  std::string names;
  for (const StudyKind kind : study_kinds) {
    if (node->value<std::string_view>() == to_string(kind)) return kind;
    names += (names.empty() ? "" : ", ") + kind_text(kind);
  }
  reject(top.child("kind", *node), describe(*node), "expected one of " + names + ", \"uncertainty\"");
}

// ---- Outputs -----------------------------------------------------------------------------------

std::string output_list_text(StudyKind kind) {
  std::string names;
  for (const std::string& n : output_names(kind)) names += (names.empty() ? "" : ", ") + n;
  return names;
}

// Why an output cannot be asked of a study of this kind, or empty when it can.
std::string unavailable(const toml::node& item, StudyKind kind) {
  const std::span<const OutputSpec> specs = output_specs();
  const auto spec = std::ranges::find(specs, item.value_or(std::string_view()), &OutputSpec::name);
  if (!item.is_string() || spec == specs.end()) return "expected one of " + output_list_text(kind);
  if (!(spec->kinds & bit(kind)))
    return "does not apply to kind " + kind_text(kind) + "; expected one of " + output_list_text(kind);
  return "";
}

namespace {

// The rig's measures beyond e_a are defined by the pivot that holds the bat.
bool is_rig_measure(const std::string& name) { return name == "bbcor" || name == "besr" || name == "bpf"; }

bool every_point_pivoted(const Settings& s) {
  const std::vector<double> pivot = s.values("pivot", 0);
  return std::ranges::count(pivot, 0.0) == 0;
}

}  // namespace

std::vector<std::string> read_outputs(const Where& top, const toml::table& doc, const Settings& s, StudyKind kind) {
  const toml::table* table = subtable(top, doc, "output");
  const Where section{top.file, "output", 0};
  if (table) reject_unknown(section, *table, {"variables", "sweet_spot_fraction", "sweet_spot_of"});
  if (!table || !table->contains("variables")) return default_outputs(kind);
  const toml::node& node = *table->get("variables");
  const Where at = section.child("variables", node);
  if (!node.is_array() || node.as_array()->empty())
    reject(at, describe(node), "expected a non-empty list of output names");
  // One mode dimension for the whole dataset: its length must not vary from point to point.
  const bool fixed_modes = !find(s.axes, "modes") && s.values("modes", default_mode_count(s))[0] >= 1;
  std::vector<std::string> outputs;
  for (std::size_t i = 0; i < node.as_array()->size(); ++i) {
    const toml::node& item = (*node.as_array())[i];
    const std::string name = item.value_or(std::string());
    if (const std::string why = unavailable(item, kind); !why.empty()) reject(at.item(i, item), describe(item), why);
    if (std::ranges::count(outputs, name))
      reject(at.item(i, item), describe(item), "appears twice; list each output once");
    if (is_probe_history(name) && !s["probes"])
      reject(at.item(i, item), describe(item), "needs probes = [z, ...] in [scene] (m from the knob)");
    if ((name == "mode_energy" || name == "mode_response") && !fixed_modes)
      reject(at.item(i, item), describe(item),
             "needs a fixed number of modes >= 1 (modes a number in [scene], not \"all\", \"auto\" (the "
             "default) or an axis)");
    if (is_rig_measure(name) && kind == StudyKind::impact && !every_point_pivoted(s))
      reject(at.item(i, item), describe(item),
             "needs a pivoted bat at every point (pivot = true, not an axis with false): its recoil factor is the "
             "rig's m d^2 / I about the pivot");
    const Setting* z = find(s.axes, "z");
    if (name.starts_with("sweet_spot_") && (!z || z->values.size() < 3))
      reject(at.item(i, item), describe(item), "needs a z axis of at least 3 points, to reduce v_f along it");
    outputs.push_back(name);
  }
  // The sweet spot is found from v_f along z, which is then stored too.
  if (std::ranges::any_of(outputs, [](const std::string& o) { return o.starts_with("sweet_spot_"); }) &&
      !std::ranges::count(outputs, "vf"))
    outputs.insert(outputs.begin(), "vf");
  return outputs;
}

std::string read_sweet_spot_of(const Where& top, const toml::table& doc) {
  const toml::table* output = doc.get_as<toml::table>("output");
  const toml::node* node = output ? output->get("sweet_spot_of") : nullptr;
  if (!node) return Study{}.sweet_spot_of;
  const std::optional<std::string> of = node->value<std::string>();
  if (!of || (*of != "vf" && *of != "distance"))
    reject(Where{top.file, "output", 0}.child("sweet_spot_of", *node), describe(*node),
           "expected \"vf\" (the exit speed, the default) or \"distance\" (the flight's carry)");
  return *of;
}

void check_sweet_spot_keys_read(const Where& top, const toml::table& doc, const std::vector<std::string>& outputs) {
  const toml::table* output = doc.get_as<toml::table>("output");
  const auto asked = [&outputs](std::string_view prefix) {
    return std::ranges::any_of(outputs, [prefix](const std::string& o) { return o.starts_with(prefix); });
  };
  // The fraction bounds the width alone; what the sweet spot is of shapes all three.
  const std::pair<const char*, const char*> keys[] = {{"sweet_spot_fraction", "sweet_spot_width"},
                                                      {"sweet_spot_of", "sweet_spot_"}};
  for (const auto& [key, reader] : keys)
    if (const toml::node* node = output ? output->get(key) : nullptr; node && !asked(reader))
      reject(Where{top.file, "output", 0}.child(key, *node), describe(*node),
             std::string("is read by ") + (std::string_view(reader) == "sweet_spot_" ?
                 "the sweet spot's outputs (sweet_spot_z, sweet_spot_vf, sweet_spot_width)" : reader) +
                 " alone, and the study asks none of them: add one to variables, or leave the key out");
}

double read_sweet_spot_fraction(const Where& top, const toml::table& doc) {
  const toml::table* output = doc.get_as<toml::table>("output");
  const toml::node* node = output ? output->get("sweet_spot_fraction") : nullptr;
  if (!node) return Study{}.sweet_spot_fraction;
  const std::optional<double> x = detail::number(*node);
  if (!node->is_number() || !(*x > 0 && *x < 1))
    reject(Where{top.file, "output", 0}.child("sweet_spot_fraction", *node), describe(*node),
           "expected a number in (0, 1): the fraction of the largest v_f that bounds the sweet spot");
  return *x;
}

// ---- The file ----------------------------------------------------------------------------------

std::string read_text(const fs::path& file, std::string_view what) {
  std::error_code ignored;  // a status we cannot get reads as "not found"
  if (!fs::is_regular_file(file, ignored))
    throw InputError(file.string() + ": " + std::string(what) + " not found (or not a regular file)");
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw InputError(file.string() + ": cannot read the " + std::string(what));
  return text.str();
}

toml::table parse_toml(const fs::path& file, const std::string& text) {
  try {
    return detail::parse_toml_text(text, file.string());
  } catch (const toml::parse_error& e) {
    const toml::source_position at = e.source().begin;
    throw InputError(file.string() + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                     ": TOML syntax error: " + std::string(e.description()));
  }
}

}  // namespace sweetspot::study_detail
