#include "sweetspot/study/study.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <initializer_list>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "sweetspot/bat/bat_file.hpp"
#include "sweetspot/input_error.hpp"
#include "sweetspot/impact/n2000_settings.hpp"
#include "sweetspot/study/study_memory.hpp"
#include "toml_values.hpp"

namespace sweetspot {

namespace {

namespace fs = std::filesystem;

// Bounds that keep a mistyped step (1e-9 for 1e-2) from exhausting memory before any work.
constexpr double max_axis_values = 1e6;
constexpr double max_points = 1e9;
constexpr int default_modes = ImpactScene{}.vibrational_modes;

// ---- Messages: "file:line: key 'axes.z.step' = 0: expected ..." -------------------------------

using detail::describe;
using detail::format_number;
using detail::quote;

// Where a value sits in the study file; line 0 when it has none to show.
struct Where {
  const fs::path* file;
  std::string key;
  std::size_t line = 0;

  Where child(std::string_view name, const toml::node& node) const {
    return {file, key.empty() ? std::string(name) : key + "." + std::string(name), node.source().begin.line};
  }
  Where item(std::size_t i, const toml::node& node) const {
    return {file, key + "[" + std::to_string(i) + "]", node.source().begin.line};
  }
  // A key that is not there: shown at its table's line, if that has one.
  Where missing(std::string_view name) const { return {file, key + "." + std::string(name), line}; }
};

// `value` empty: the key is missing. Every message is one line, so the program prints it as is.
[[noreturn]] void reject(const Where& at, const std::string& value, const std::string& expected) {
  std::string text = at.file->string() + (at.line ? ":" + std::to_string(at.line) : "") + ": key '" + at.key + "'" +
                     (value.empty() ? " is missing" : " = " + value) + ": " + expected;
  std::replace(text.begin(), text.end(), '\n', ' ');
  throw InputError(text);
}

// ---- The scene keys and outputs of each kind of study ----------------------------------------

// A set of study kinds, one bit each: which kinds a key or an output belongs to.
using KindSet = unsigned;
constexpr KindSet bit(StudyKind kind) { return 1u << static_cast<unsigned>(kind); }
constexpr KindSet impact = bit(StudyKind::impact), wall = bit(StudyKind::wall), toy = bit(StudyKind::toy);
constexpr KindSet ball_kinds = impact | wall;  // the kinds with the nonlinear ball and its integrator
constexpr KindSet every_kind = impact | wall | toy;

std::string kind_text(StudyKind kind) { return quote(to_string(kind)); }

// `numbers`: a list of numbers in [scene] (probes), never an axis; `set` takes each in turn.
enum class Type { number, integer, boolean, bat, theory, modes, integrator, preset, numbers };

// One key of [scene]: how its value is read, the rule validate() in scene.cpp applies to it, how
// it sets a grid point, and the kinds of study it belongs to and must be given in. Every value
// is a number here (see Axis in study.hpp).
struct KeySpec {
  std::string_view name;
  Type type;
  std::string_view expected;
  bool (*valid)(double);
  void (*set)(GridPoint&, double);
  KindSet kinds = impact;
  KindSet required = 0;
  bool axis = true;
};

bool any(double) { return true; }
bool finite(double x) { return std::isfinite(x); }
bool positive(double x) { return std::isfinite(x) && x > 0; }
bool step(double x) { return positive(x) && x >= finest_step; }  // as the commands' --dt
bool on_bat(double x) { return std::isfinite(x) && x >= 0; }  // the bats' lengths: check_on_bats
bool unit_interval(double x) { return x > 0 && x <= 1; }
bool slice_count(double x) { return x >= min_slices && x <= max_slices; }  // as `impact --slices`
bool mode_count(double x) { return x >= 0 && x <= 1e6; }    // "all" and "auto" are not checked

constexpr KeySpec keys[] = {
    {"bat", Type::bat, "a bat file path (relative to the study file)", any,
     [](GridPoint& p, double x) { p.bat = static_cast<std::size_t>(x); }, impact, impact},
    {"theory", Type::theory, "\"timoshenko\" or \"euler-bernoulli\"", any,
     [](GridPoint& p, double x) { p.theory = static_cast<BeamTheory>(x); }},
    {"slices", Type::integer, "an integer slice count from 4 to 4096", slice_count,
     [](GridPoint& p, double x) { p.slices = static_cast<int>(x); }},
    {"z", Type::number, "a finite number >= 0 (m from the knob)", on_bat,
     [](GridPoint& p, double x) { p.scene.z = x; }, impact, impact},
    // The wall takes only speeds > 0: check_wall_speeds.
    {"ball_speed", Type::number, "a finite number (m/s)", finite,
     [](GridPoint& p, double x) { p.scene.ball_speed = x; }, ball_kinds, ball_kinds},
    {"e0", Type::number, "a number in (0, 1]", unit_interval, [](GridPoint& p, double x) { p.scene.ball.e0 = x; },
     ball_kinds},
    {"ball_mass", Type::number, "a finite number > 0 (kg)", positive,
     [](GridPoint& p, double x) { p.scene.ball.mass = x; }, ball_kinds},
    {"ball_radius", Type::number, "a finite number > 0 (m)", positive,
     [](GridPoint& p, double x) { p.scene.ball.radius = x; }, ball_kinds},
    {"k1", Type::number, "a finite number > 0 (N/m^a)", positive, [](GridPoint& p, double x) { p.scene.ball.k1 = x; },
     ball_kinds},
    {"a", Type::number, "a finite number > 0", positive, [](GridPoint& p, double x) { p.scene.ball.a = x; },
     ball_kinds},
    {"center", Type::number, "a finite number (m from the knob)", finite,
     [](GridPoint& p, double x) {
       p.scene.swing.center = x;
       p.scene.swing.about_center = true;
     }},
    {"cm_speed", Type::number, "a finite number (m/s)", finite,
     [](GridPoint& p, double x) {
       p.scene.swing.cm_speed = x;
       p.scene.swing.about_center = false;
     }},
    {"omega", Type::number, "a finite number (rad/s)", finite, [](GridPoint& p, double x) { p.scene.swing.omega = x; }},
    {"pivot", Type::boolean, "true or false", any, [](GridPoint& p, double x) { p.scene.pivoted = x != 0; }},
    {"modes", Type::modes, "a number of vibrational modes >= 0, \"all\" or \"auto\"", mode_count,
     [](GridPoint& p, double x) { p.scene.vibrational_modes = static_cast<int>(x); }},
    {"mode_tolerance", Type::number, "a finite number > 0 (relative vf error allowed the dropped modes)", positive,
     [](GridPoint& p, double x) { p.scene.mode_tolerance = x; }},
    {"accuracy", Type::number, "a finite number > 0 (relative vf error the integration may add)", positive,
     [](GridPoint& p, double x) { p.scene.accuracy = x; }},
    // N2000's settings (RK4 at 5 us, 18 modes) under the keys the study leaves out: load_study.
    {"preset", Type::preset, "\"n2000\" (RK4 at 5 us with 18 vibrational modes)", any, [](GridPoint&, double) {},
     ball_kinds, 0, false},
    {"integrator", Type::integrator, "\"exact\", \"rk4\" or \"dopri\"", any,
     [](GridPoint& p, double x) { p.scene.integrator.method = static_cast<Method>(x); }, ball_kinds, 0, false},
    {"tolerance", Type::number, "a finite number > 0 (relative error per step, dopri)", positive,
     [](GridPoint& p, double x) { p.scene.integrator.tolerance = x; }, ball_kinds},
    {"dt", Type::number, "a finite number >= 5e-9 (s; a finer step could take over 1e7 steps per contact)", step,
     [](GridPoint& p, double x) { p.scene.integrator.dt = x; }, ball_kinds},
    {"window", Type::number, "a finite number > 0 (s)", positive,
     [](GridPoint& p, double x) { p.scene.integrator.window = x; }, ball_kinds},
    // Histories shape the dataset's dimensions (probe, time), so they are never axes.
    {"probes", Type::numbers, "a list of points on the bat, each a finite number >= 0 (m from the knob)", on_bat,
     [](GridPoint& p, double x) { p.scene.history.probes.push_back(x); }, impact, 0, false},
    {"history_window", Type::number, "a finite number > 0 (s of history from first touch)", positive,
     [](GridPoint& p, double x) { p.scene.history.window = x; }, ball_kinds, 0, false},
    {"history_step", Type::number, "a finite number > 0 (s between history samples)", positive,
     [](GridPoint& p, double x) { p.scene.history.step = x; }, ball_kinds, 0, false},
    {"omega_tau", Type::number, "a finite number > 0 (omega tau of the toy model)", positive,
     [](GridPoint& p, double x) { p.omega_tau = x; }, toy, toy},
};

const KeySpec* find_key(std::string_view name) {
  const auto it = std::ranges::find(keys, name, &KeySpec::name);
  return it == std::end(keys) ? nullptr : &*it;
}

std::string key_list(StudyKind kind, bool axes_only) {
  std::string list;
  for (const KeySpec& k : keys)
    if ((k.kinds & bit(kind)) && (k.axis || !axes_only)) list += (list.empty() ? "" : ", ") + std::string(k.name);
  return list;
}

// An output variable (an ImpactResult field), the kinds that give it and those that write it when
// [output] names none. The order here is the order of output_names() and default_outputs().
struct OutputSpec {
  std::string_view name;
  KindSet kinds;
  KindSet by_default;
};

constexpr OutputSpec output_specs[] = {
    {"vf", every_kind, every_kind},
    {"vf_rigid", impact, 0},
    {"vf_van_zandt", impact | toy, toy},
    {"e_eff", ball_kinds, ball_kinds},
    {"contact_time", ball_kinds, ball_kinds},
    {"collision_time", ball_kinds, ball_kinds},
    {"u_max", ball_kinds, 0},
    {"peak_force", ball_kinds, 0},
    {"impulse", ball_kinds, 0},
    {"contacts", impact, 0},
    {"energy_initial", every_kind, 0},
    {"energy_ball", every_kind, toy},
    {"energy_bat_translation", impact | toy, toy},
    {"energy_bat_rotation", impact, 0},
    {"energy_vibration", impact | toy, toy},
    {"energy_ball_dissipated", ball_kinds, 0},
    {"energy_residual", every_kind, 0},
    {"mode_energy", impact, 0},
    {"displacement", impact, 0},
    {"velocity", impact, 0},
    {"acceleration", impact, 0},
    {"vibration_displacement", impact, 0},
    {"vibration_velocity", impact, 0},
    {"vibration_acceleration", impact, 0},
    {"force", ball_kinds, 0},
    {"compression", ball_kinds, 0},
    {"ball_position", ball_kinds, 0},
    {"force_response", impact, 0},
    {"mode_response", impact, 0},
    {"modes_kept", impact, 0},
    {"modes_error", impact, 0},
    {"status", every_kind, every_kind},
};

std::vector<std::string> output_list(StudyKind kind, KindSet OutputSpec::*member) {
  std::vector<std::string> names;
  for (const OutputSpec& o : output_specs)
    if (o.*member & bit(kind)) names.emplace_back(o.name);
  return names;
}

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

// Unknown keys are errors: a misspelt optional key would otherwise be silently ignored.
void reject_unknown(const Where& at, const toml::table& table, std::initializer_list<std::string_view> known) {
  std::string list;
  for (const std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
  for (const auto& [key, node] : written_order(table))
    if (std::ranges::find(known, key) == known.end())
      reject(at.child(key, *node), describe(*node), "unknown key; expected one of " + list);
}

const toml::table* subtable(const Where& at, const toml::table& parent, std::string_view name) {
  const toml::node* node = parent.get(name);
  if (node && !node->is_table())
    reject(at.child(name, *node), describe(*node), "expected a table [" + at.child(name, *node).key + "]");
  return node ? node->as_table() : nullptr;
}

// A scene value as a number (see Axis); `label` keeps the names of bat and theory values.
struct Value {
  double number = 0;
  std::string label;
};

Value read_value(const Where& at, const KeySpec& spec, const toml::node& node) {
  const auto bad = [&] { reject(at, describe(node), "expected " + std::string(spec.expected)); };
  Value v;
  if ((spec.type == Type::number || spec.type == Type::numbers) && node.is_number())
    v.number = *node.value<double>();
  else if ((spec.type == Type::integer || spec.type == Type::modes) && node.is_integer())
    v.number = static_cast<double>(node.as_integer()->get());
  else if (spec.type == Type::boolean && node.is_boolean())
    v.number = node.as_boolean()->get();
  else if (spec.type == Type::modes && node.value<std::string_view>() == "all")
    return {all_modes, ""};
  else if (spec.type == Type::modes && node.value<std::string_view>() == "auto")
    return {auto_modes, ""};
  else if ((spec.type == Type::bat || spec.type == Type::theory || spec.type == Type::integrator) && node.is_string())
    v.label = node.as_string()->get();
  else if (spec.type == Type::preset && node.value<std::string_view>() == "n2000")
    return {0, "n2000"};
  else
    bad();
  if (spec.type == Type::bat && v.label.empty()) bad();
  try {
    if (spec.type == Type::theory) v.number = static_cast<double>(parse_beam_theory(v.label));
    if (spec.type == Type::integrator) v.number = static_cast<double>(parse_method(v.label));
  } catch (const InputError&) {
    bad();
  }
  if (!spec.valid(v.number)) bad();
  return v;
}

// A scene key as the study gives it: the one value in [scene] or the values of its axis.
struct Setting {
  const KeySpec* spec;
  Where where;
  std::vector<double> values;
  std::vector<std::string> labels;  // bat and theory only
};

const Setting* find(const std::vector<Setting>& settings, std::string_view name) {
  const auto it = std::ranges::find_if(settings, [&](const Setting& s) { return s.spec->name == name; });
  return it == settings.end() ? nullptr : &*it;
}

void add(Setting& s, Value v) {
  s.values.push_back(v.number);
  if (s.spec->type == Type::bat || s.spec->type == Type::theory) s.labels.push_back(std::move(v.label));
}

// 15 significant digits: 0.305 + 3 * 0.01 becomes the 0.335 a reader expects.
double tidy(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.15g", x);
  return std::strtod(text, nullptr);
}

double range_bound(const Where& at, const toml::table& range, std::string_view name, bool integer) {
  const toml::node* node = range.get(name);
  if (!node) reject(at.missing(name), "", "a range needs start, stop and either step or count");
  if (!(integer ? node->is_integer() : node->is_number()) || !std::isfinite(*node->value<double>()))
    reject(at.child(name, *node), describe(*node), integer ? "expected an integer" : "expected a finite number");
  return *node->value<double>();
}

// {start, stop, step}: stop is included when it lands within 1e-9 step of a point.
std::vector<double> stepped_range(const Where& at, const toml::table& range, double start, double stop, bool integer) {
  const double step = range_bound(at, range, "step", integer);
  const Where where = at.child("step", *range.get("step"));
  if (step == 0 || (stop - start) * step < 0)
    reject(where, format_number(step),
           "expected a step with the sign of stop - start = " + format_number(stop - start) + ", not 0");
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

std::vector<double> read_range(const Where& at, const KeySpec& spec, const toml::table& range) {
  reject_unknown(at, range, {"start", "stop", "step", "count", "spacing"});
  const bool integer = spec.type != Type::number;  // slices, modes
  const double start = range_bound(at, range, "start", integer), stop = range_bound(at, range, "stop", integer);
  if (range.contains("step") == range.contains("count"))
    reject(at, "{...}", "a range needs exactly one of step and count");
  const bool log = log_spacing(at, range);
  const std::vector<double> values = range.contains("step") ? stepped_range(at, range, start, stop, integer)
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

// Repeated values would make the axis useless as a coordinate (which point is z = 0.5?).
void reject_duplicates(const Setting& s, const fs::path& dir) {
  if (s.spec->type == Type::bat) {
    std::vector<std::string> paths;
    for (const std::string& label : s.labels) paths.push_back((dir / label).lexically_normal().string());
    if (const auto twice = first_repeat(paths)) reject(s.where, quote(*twice), "names the same bat file twice");
  } else if (const auto twice = first_repeat(s.values)) {
    reject(s.where, format_number(*twice), "appears twice in the axis; its values must differ");
  }
}

Setting read_axis(const Where& at, const KeySpec& spec, const toml::node& node, const fs::path& dir) {
  Setting s{&spec, at, {}, {}};
  const bool numeric = spec.type == Type::number || spec.type == Type::integer || spec.type == Type::modes;
  if (const toml::array* list = node.as_array()) {
    for (std::size_t i = 0; i < list->size(); ++i) add(s, read_value(at.item(i, (*list)[i]), spec, (*list)[i]));
  } else if (numeric && node.is_table()) {
    s.values = read_range(at, spec, *node.as_table());
  } else {
    reject(at, describe(node),
           "expected a list of values, each " + std::string(spec.expected) +
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
  if (!list || list->empty()) reject(at, describe(node), "expected " + std::string(spec.expected));
  for (std::size_t i = 0; i < list->size(); ++i) add(s, read_value(at.item(i, (*list)[i]), spec, (*list)[i]));
  if (const auto twice = first_repeat(s.values))
    reject(at, format_number(*twice), "appears twice in the list; its values must differ");
  return s;
}

// Why a key of the table cannot stand here, or empty when it can.
std::string misplaced(const KeySpec* spec, StudyKind kind, bool axes) {
  if (!spec) return "unknown key";
  if (!(spec->kinds & bit(kind))) return "does not apply to kind " + kind_text(kind);
  if (axes && !spec->axis) return "cannot be an axis";
  return "";
}

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
      reject(where, describe(*node), why + "; expected one of " + key_list(kind, axes));
    if (axes)
      settings.push_back(read_axis(where, *spec, *node, top.file->parent_path()));
    else if (spec->type == Type::numbers)
      settings.push_back(read_list(where, *spec, *node));
    else
      add(settings.emplace_back(Setting{spec, where, {}, {}}), read_value(where, *spec, *node));
  }
  return settings;
}

// ---- Checks across keys ------------------------------------------------------------------------

// The settings in force: an axis overrides the same key in [scene].
struct Settings {
  std::vector<Setting> scene, axes;
  const Setting* operator[](std::string_view name) const {
    const Setting* axis = find(axes, name);
    return axis ? axis : find(scene, name);
  }
  std::vector<double> values(std::string_view name, double fallback) const {
    const Setting* s = (*this)[name];
    return s ? s->values : std::vector<double>{fallback};
  }
};

// The mode count a study keeps unless it says: "auto", or N2000's 18 under preset = "n2000".
double default_mode_count(const Settings& s) { return s["preset"] ? n2000_modes : default_modes; }

void check_required(const Settings& s, const Where& top, StudyKind kind) {
  for (const KeySpec& key : keys)
    if ((key.required & bit(kind)) && !s[key.name])
      reject(Where{top.file, "scene", 0}.missing(key.name), "",
             "expected " + std::string(key.expected) + ", in [scene] or as an axis in [axes]");
}

// The wall stands still, so only a ball moving toward it (speed > 0) ever touches it.
void check_wall_speeds(const Settings& s) {
  const Setting& speed = *s["ball_speed"];
  for (const double v : speed.values)
    if (!(v > 0))
      reject(speed.where, format_number(v), "expected a speed > 0 (m/s) toward the wall, which does not move");
}

void check_swing(const Settings& s, const Where& top) {
  const Setting *center = s["center"], *cm_speed = s["cm_speed"], *pivot = s["pivot"];
  if (center && cm_speed)
    reject(center->where, format_number(center->values[0]),
           "expected exactly one of center and cm_speed, but key '" + cm_speed->where.key + "' is also given");
  if (!center && !cm_speed)
    reject(Where{top.file, "scene", 0}.missing("center"), "",
           "give the swing as center (the point at rest, m from the knob) or as cm_speed (m/s)");
  if (cm_speed && pivot && std::ranges::count(pivot->values, 1.0))
    reject(pivot->where, "true", "a pivoted bat is held at its rotation centre: give center, not cm_speed");
}

std::vector<Bat> load_bats(Study& study, const Setting& bat) {
  std::vector<Bat> bats;
  for (const std::string& label : bat.labels) {
    study.bats.push_back((study.file.parent_path() / label).lexically_normal());
    try {
      bats.push_back(load_bat(study.bats.back(), study.bat_sources.emplace_back()));
    } catch (const InputError& e) {
      reject(bat.where, quote(label), e.what());
    }
    // The dataset labels the bat coordinate by name: two bats of one name could not be told apart.
    const auto same = std::ranges::find(study.bat_names, bats.back().name);
    if (same != study.bat_names.end())
      reject(bat.where, quote(label),
             "its bat is named '" + *same + "' like the bat of " + quote(bat.labels[same - study.bat_names.begin()]) +
                 "; give each bat its own name");
    study.bat_names.push_back(bats.back().name);
  }
  study.loaded_bats = bats;
  return bats;
}

std::string bat_text(const std::vector<Bat>& bats, const Setting& bat, std::size_t b) {
  return bats[b].name + " (" + bat.labels[b] + ")";
}

// Points on the bat (z, probes) must be on every bat.
void check_on_bats(const Setting& points, const std::vector<Bat>& bats, const Setting& bat) {
  for (const double x : points.values)
    for (std::size_t b = 0; b < bats.size(); ++b)
      if (!lies_on_bat(x, bats[b].length))
        reject(points.where, format_number(x),
               "must lie on every bat of the study: 0 to " + format_number(bats[b].length) + " m for " +
                   bat_text(bats, bat, b));
}

// Vibrational modes a discretisation has (modes.cpp): Timoshenko has two degrees of freedom per
// slice, Euler-Bernoulli two per slice boundary; two modes are rigid.
int vibrational_modes(int slices, BeamTheory theory) {
  return (theory == BeamTheory::timoshenko ? 2 * slices : 2 * (slices + 1)) - 2;
}

void check_mode_counts(const Settings& s, const Where& top, const std::vector<Bat>& bats, const Setting& bat) {
  const Setting* modes = s["modes"];
  const Where where = modes ? modes->where : Where{top.file, "scene", 0}.missing("modes");
  for (std::size_t b = 0; b < bats.size(); ++b)
    for (const double slices : s.values("slices", bats[b].slices()))
      for (const double theory : s.values("theory", 0))
        for (const double m : s.values("modes", default_mode_count(s))) {
          const int available = vibrational_modes(static_cast<int>(slices), static_cast<BeamTheory>(theory));
          if (m == all_modes || m == auto_modes || m <= available) continue;
          reject(where, format_number(m) + (modes ? "" : s["preset"] ? " (the n2000 preset)" : " (the default)"),
                 bat_text(bats, bat, b) + " in " + format_number(slices) + " slices has " + std::to_string(available) +
                     " vibrational modes (" + to_string(static_cast<BeamTheory>(theory)) +
                     "); expected at most that, or \"all\"");
        }
}

void check_euler_bernoulli_slices(const Settings& s, const Where& top, const std::vector<Bat>& bats,
                                  const Setting& bat) {
  const Setting* slices = s["slices"];
  const Where where = slices ? slices->where : Where{top.file, "scene", 0}.missing("slices");
  for (std::size_t b = 0; b < bats.size(); ++b)
    for (const double n : s.values("slices", bats[b].slices()))
      for (const double theory : s.values("theory", 0))
        if (static_cast<BeamTheory>(theory) == BeamTheory::euler_bernoulli && n > max_euler_bernoulli_slices)
          reject(where, format_number(n) + (slices ? "" : " (" + bat_text(bats, bat, b) + "'s own)"),
                 "at most " + std::to_string(max_euler_bernoulli_slices) +
                     " slices for theory euler-bernoulli (its dense solve loses the lowest frequencies to round-off)");
}

void check_grid_size(const Settings& s, const Where& top) {
  double points = 1;
  for (const Setting& axis : s.axes) points *= static_cast<double>(axis.values.size());
  if (points > max_points)
    reject(Where{top.file, "axes", 0}, "{...}", "the grid has " + format_number(points) + " points; at most 1e9");
}

// Rounded as the time grid rounds (HistoryRequest::steps): 3e-3 / 3e-8 is 1e5, not 1e5 + 1e-11.
void check_history_samples(const Settings& s) {
  const HistoryRequest h{{}, s.values("history_window", HistoryRequest{}.window)[0],
                         s.values("history_step", HistoryRequest{}.step)[0]};
  if (h.steps() > max_history_samples) {
    const Setting* at = s["history_step"] ? s["history_step"] : s["history_window"];
    reject(at->where, format_number(at->values[0]),
           "history_window / history_step = " + format_number(h.steps()) + " samples; at most 1e5");
  }
}

// The fastest mode a point keeps (rad/s): the free bat's, or with `pivot_center` the held bat's,
// whose modes the constraint makes (scene.cpp), never faster than the free ones.
double fastest_kept_mode(const ModalBasis& basis, double modes, const double* pivot_center) {
  if (!pivot_center) return basis.omega(modes == all_modes ? basis.count() - 1 : static_cast<int>(modes) + 1);
  ImpactScene scene;
  scene.vibrational_modes = static_cast<int>(modes);
  scene.pivoted = scene.swing.about_center = true;
  scene.swing.center = *pivot_center;
  scene.z = basis.z.front();  // the held bat's frequencies do not depend on where it is struck
  return scene_geometry(scene, basis).contact.omega.maxCoeff();
}

// RK4 at a fixed step is unstable once omega dt > 2.8 for a kept mode, and `impact` refuses such a
// scene: so does the study, before any work, naming the combination of values that makes it.
// ("auto" keeps modes per point and is left to the point; a stated accuracy keeps the step stable.)
void check_rk4_stability(const Settings& s, const Where& top, const std::vector<Bat>& bats, const Setting& bat) {
  const Setting* integrator = s["integrator"];
  if (!integrator || static_cast<Method>(integrator->values[0]) != Method::rk4 || s["accuracy"]) return;
  const std::vector<double> steps = s.values("dt", default_step(Method::rk4));
  const double dt = *std::ranges::max_element(steps);
  const std::vector<double> pivots = s.values("pivot", 0), centers = s.values("center", 0);
  const bool all_pivoted = std::ranges::count(pivots, 0.0) == 0;
  const Setting* modes_setting = s["modes"];
  const Where where = modes_setting ? modes_setting->where : Where{top.file, "scene", 0}.missing("modes");
  for (std::size_t b = 0; b < bats.size(); ++b)
    for (const double slices : s.values("slices", bats[b].slices()))
      for (const double theory : s.values("theory", 0)) {
        std::optional<ModalBasis> basis;  // solved only when some point keeps a vibrational mode
        for (const double m : s.values("modes", default_modes)) {
          if (m == 0 || m == auto_modes) continue;
          if (!basis) basis = compute_modes(resample(bats[b], static_cast<int>(slices)), static_cast<BeamTheory>(theory));
          double omega = fastest_kept_mode(*basis, m, nullptr), center = 0;
          if (omega * dt <= rk4_stability_limit) continue;
          if (all_pivoted) {  // held, the fastest mode may be slow enough
            omega = 0;
            for (const double c : centers)
              if (const double w = fastest_kept_mode(*basis, m, &c); w > omega) omega = w, center = c;
            if (omega * dt <= rk4_stability_limit) continue;
          }
          const std::string value = m == all_modes ? "\"all\"" : format_number(m);
          reject(where, value + (modes_setting ? "" : " (the default)"),
                 "with integrator = \"rk4\" and dt = " + format_number(dt) + " s, " + bat_text(bats, bat, b) + " in " +
                     format_number(slices) + " slices (" + to_string(static_cast<BeamTheory>(theory)) + ")" +
                     (all_pivoted ? ", pivoted at center = " + format_number(center) + " m," : "") +
                     " keeps a mode of omega = " + format_number(omega) + " rad/s: omega dt = " +
                     format_number(omega * dt) + " > 2.8 is unstable; expected fewer modes, dt <= " +
                     format_number(rk4_stability_limit / omega) + " s, accuracy, or integrator = \"exact\"");
        }
      }
}

// The impact kind's checks across keys: the swing, the bat files, z on every bat, mode counts.
void check_bat_scene(Study& study, const Settings& s, const Where& top) {
  const Setting& bat = *s["bat"];
  check_swing(s, top);
  const std::vector<Bat> bats = load_bats(study, bat);
  check_on_bats(*s["z"], bats, bat);
  if (const Setting* probes = s["probes"]) check_on_bats(*probes, bats, bat);
  check_mode_counts(s, top, bats, bat);
  check_euler_bernoulli_slices(s, top, bats, bat);
  check_history_samples(s);
  check_rk4_stability(s, top, bats, bat);
}

// ---- The kind ----------------------------------------------------------------------------------

constexpr StudyKind study_kinds[] = {StudyKind::impact, StudyKind::wall, StudyKind::toy};

StudyKind read_kind(const Where& top, const toml::table& doc) {
  const toml::node* node = doc.get("kind");
  if (!node) return StudyKind::impact;
  std::string names;
  for (const StudyKind kind : study_kinds) {
    if (node->value<std::string_view>() == to_string(kind)) return kind;
    names += (names.empty() ? "" : ", ") + kind_text(kind);
  }
  reject(top.child("kind", *node), describe(*node), "expected one of " + names);
}

// ---- Outputs -----------------------------------------------------------------------------------

std::string output_list_text(StudyKind kind) {
  std::string names;
  for (const std::string& n : output_names(kind)) names += (names.empty() ? "" : ", ") + n;
  return names;
}

// Why an output cannot be asked of a study of this kind, or empty when it can.
std::string unavailable(const toml::node& item, StudyKind kind) {
  const auto spec = std::ranges::find(output_specs, item.value_or(std::string_view()), &OutputSpec::name);
  if (!item.is_string() || spec == std::end(output_specs)) return "expected one of " + output_list_text(kind);
  if (!(spec->kinds & bit(kind)))
    return "does not apply to kind " + kind_text(kind) + "; expected one of " + output_list_text(kind);
  return "";
}

std::vector<std::string> read_outputs(const Where& top, const toml::table& doc, const Settings& s, StudyKind kind) {
  const toml::table* table = subtable(top, doc, "output");
  const Where section{top.file, "output", 0};
  if (table) reject_unknown(section, *table, {"variables"});
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
    outputs.push_back(name);
  }
  return outputs;
}

// ---- The file ----------------------------------------------------------------------------------

std::string read_text(const fs::path& file) {
  std::error_code ignored;  // a status we cannot get reads as "not found"
  if (!fs::is_regular_file(file, ignored))
    throw InputError(file.string() + ": study file not found (or not a regular file)");
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw InputError(file.string() + ": cannot read the study file");
  return text.str();
}

toml::table parse_toml(const fs::path& file, const std::string& text) {
  try {
    return toml::parse(text, file.string());
  } catch (const toml::parse_error& e) {
    const toml::source_position at = e.source().begin;
    throw InputError(file.string() + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) +
                     ": TOML syntax error: " + std::string(e.description()));
  }
}

Axis make_axis(const Setting& s) {
  Axis axis{std::string(s.spec->name), s.values, s.labels};
  if (s.spec->type == Type::bat)
    for (std::size_t i = 0; i < axis.size(); ++i) axis.values[i] = static_cast<double>(i);
  return axis;
}

}  // namespace

const char* to_string(StudyKind kind) {
  switch (kind) {
    case StudyKind::impact:
      return "impact";
    case StudyKind::wall:
      return "wall";
    case StudyKind::toy:
      return "toy";
  }
  return "?";
}


std::size_t Study::points() const {
  std::size_t n = 1;
  for (const Axis& axis : axes) n *= axis.size();
  return n;
}

Study load_study(const fs::path& file) {
  Study study;
  study.file = file;
  study.text = read_text(file);
  const toml::table doc = parse_toml(file, study.text);
  const Where top{&study.file, "", 0};
  reject_unknown(top, doc, {"title", "kind", "scene", "axes", "output"});
  if (const toml::node* title = doc.get("title")) {
    if (!title->is_string()) reject(top.child("title", *title), describe(*title), "expected a string");
    study.title = title->as_string()->get();
  }
  study.kind = read_kind(top, doc);
  const Settings s{read_settings(top, doc, "scene", study.kind), read_settings(top, doc, "axes", study.kind)};
  check_grid_size(s, top);
  check_required(s, top, study.kind);
  if (has_bat(study.kind)) check_bat_scene(study, s, top);
  if (study.kind == StudyKind::wall) check_wall_speeds(s), check_history_samples(s);
  study.outputs = read_outputs(top, doc, s, study.kind);

  GridPoint base;
  // The library's defaults (exact modal stepping, modes = auto: README, "Numerics"), or N2000's
  // settings under preset = "n2000"; what the study gives overrides either. Each method has its
  // own default step.
  if (s["preset"]) base.scene = with_n2000_settings(base.scene);
  for (const Setting& setting : s.scene)
    for (const double x : setting.values) setting.spec->set(base, x);  // one value, or each of a list
  if (!s["dt"]) base.scene.integrator.dt = default_step(base.scene.integrator.method);
  // The comparisons cost time (Van Zandt records and integrates the force profile): only when asked.
  base.scene.rigid_comparison = std::ranges::count(study.outputs, "vf_rigid") > 0;
  base.scene.van_zandt_comparison = std::ranges::count(study.outputs, "vf_van_zandt") > 0;
  base.scene.histories = std::ranges::any_of(study.outputs, is_history);
  base.scene.force_response = std::ranges::count(study.outputs, "force_response") > 0;
  base.scene.mode_response = std::ranges::count(study.outputs, "mode_response") > 0;
  base.scene.integrator.find_collision_time = std::ranges::count(study.outputs, "collision_time") > 0;
  base.scene.swing.about_center = s["center"] != nullptr;
  study.base = base.scene;
  study.omega_tau = base.omega_tau;
  study.theory = base.theory;
  study.slices = base.slices;
  for (const Setting& axis : s.axes) study.axes.push_back(make_axis(axis));
  check_study_memory(study, machine_memory_bytes());
  return study;
}

GridPoint grid_point(const Study& study, std::size_t index) {
  if (index >= study.points())
    throw std::out_of_range("grid_point: index " + std::to_string(index) + " >= " + std::to_string(study.points()) +
                            " points");
  GridPoint p;
  p.kind = study.kind;
  p.scene = study.base;
  p.omega_tau = study.omega_tau;
  p.slices = study.slices;
  p.theory = study.theory;
  p.coords.resize(study.axes.size());
  for (std::size_t k = study.axes.size(); k-- > 0;) {
    const Axis& axis = study.axes[k];
    const KeySpec* spec = find_key(axis.name);
    if (!spec) throw std::invalid_argument("grid_point: unknown axis '" + axis.name + "'");
    p.coords[k] = index % axis.size();
    index /= axis.size();
    spec->set(p, axis.values[p.coords[k]]);
  }
  return p;
}

namespace {
bool model_axis(const Axis& axis) { return axis.name == "bat" || axis.name == "slices" || axis.name == "theory"; }
}  // namespace

std::size_t models(const Study& study) {
  std::size_t n = 1;
  for (const Axis& axis : study.axes)
    if (model_axis(axis)) n *= axis.size();
  return n;
}

// The task number splits into (model, rest), each row-major over its own axes; the coordinates
// then recompose row-major over all axes.
std::size_t task_point(const Study& study, std::size_t task) {
  const std::size_t points = study.points();
  if (task >= points)
    throw std::out_of_range("task_point: task " + std::to_string(task) + " >= " + std::to_string(points) + " points");
  const std::size_t per_model = points / models(study);
  std::size_t model = task / per_model, rest = task % per_model;
  std::vector<std::size_t> coords(study.axes.size());
  for (std::size_t k = coords.size(); k-- > 0;) {
    std::size_t& part = model_axis(study.axes[k]) ? model : rest;
    coords[k] = part % study.axes[k].size();
    part /= study.axes[k].size();
  }
  std::size_t index = 0;
  for (std::size_t k = 0; k < coords.size(); ++k) index = index * study.axes[k].size() + coords[k];
  return index;
}

std::vector<std::size_t> task_order(const Study& study) {
  std::vector<std::size_t> order(study.points());
  for (std::size_t t = 0; t < order.size(); ++t) order[t] = task_point(study, t);
  return order;
}

bool is_probe_history(std::string_view name) {
  static constexpr std::string_view names[] = {"displacement",           "velocity",           "acceleration",
                                               "vibration_displacement", "vibration_velocity", "vibration_acceleration"};
  return std::ranges::count(names, name) > 0;
}

bool is_history(std::string_view name) {
  return is_probe_history(name) || name == "force" || name == "compression" || name == "ball_position";
}

std::vector<std::string> scene_keys(StudyKind kind) {
  std::vector<std::string> names;
  for (const KeySpec& k : keys)
    if (k.kinds & bit(kind)) names.emplace_back(k.name);
  return names;
}

const std::vector<std::string>& output_names(StudyKind kind) {
  static const std::vector<std::string> names[] = {output_list(StudyKind::impact, &OutputSpec::kinds),
                                                   output_list(StudyKind::wall, &OutputSpec::kinds),
                                                   output_list(StudyKind::toy, &OutputSpec::kinds)};
  return names[static_cast<std::size_t>(kind)];
}

const std::vector<std::string>& default_outputs(StudyKind kind) {
  static const std::vector<std::string> names[] = {output_list(StudyKind::impact, &OutputSpec::by_default),
                                                   output_list(StudyKind::wall, &OutputSpec::by_default),
                                                   output_list(StudyKind::toy, &OutputSpec::by_default)};
  return names[static_cast<std::size_t>(kind)];
}

}  // namespace sweetspot
