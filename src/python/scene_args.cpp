#include "scene_args.hpp"

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <array>
#include <optional>
#include <string_view>
#include <tuple>

#include <pybind11/stl.h>

#include "sweetspot/ball/ball_file.hpp"
#include "sweetspot/ball/ball_tests.hpp"
#include "sweetspot/impact/error_estimates.hpp"
#include "sweetspot/impact/n2000_settings.hpp"
#include "sweetspot/input_error.hpp"

namespace py = pybind11;

namespace sweetspot::python {

namespace {

// Indices into scene_arguments(): the point arguments first (0 to 13), then these.
namespace arg {
enum : int {
  z = 0,
  ball_speed = 1,
  cm_speed = 2,
  center = 3,
  ball = 14,
  pivot,
  modes,
  mode_tolerance,
  accuracy,
  step_accuracy,
  integrator,
  dt,
  tolerance,
  window,
  theory,
  n2000,
  count
};
}  // namespace arg

// Each argument's value (a null handle or None where not given), by index into scene_arguments().
using SceneValues = std::array<py::handle, arg::count>;

// The index of an argument's name, or -1.
int argument_index(std::string_view name) {
  const auto& names = scene_arguments();
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return static_cast<int>(k);
  return -1;
}

bool is_numpy(const py::handle& value, const char* type) {
  // A plain Python float, int or str is none of numpy's types: no import asked (most arguments).
  if (PyFloat_CheckExact(value.ptr()) || PyLong_CheckExact(value.ptr()) || PyUnicode_CheckExact(value.ptr()))
    return false;
  return py::isinstance(value, py::module_::import("numpy").attr(type));
}


// True or False (numpy's bools too); 0 and 1 as Python reads them.
bool flag(const std::string& name, const py::handle& value) {
  if (py::isinstance<py::bool_>(value) || is_numpy(value, "bool_")) return value.cast<bool>();
  if (py::isinstance<py::int_>(value)) {
    const int v = value.equal(py::int_(1)) ? 1 : value.equal(py::int_(0)) ? 0 : -1;
    if (v >= 0) return v == 1;
  }
  throw InputError(name + " " + py::repr(value).cast<std::string>() + ": expected True or False");
}

std::string text(const std::string& name, const py::handle& value, const std::string& expected) {
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  throw InputError(name + " " + py::repr(value).cast<std::string>() + ": expected " + expected);
}

// Each point argument's dimension, in point_arguments()' order (none: e0, k1, a, swing_tilt in
// degrees, pitch_spin in rpm, friction).
constexpr std::optional<Dimension> point_dimensions[] = {
    Dimension::length, Dimension::speed, Dimension::speed, Dimension::length, Dimension::angular_speed,
    std::nullopt,      Dimension::mass,  Dimension::length, std::nullopt,     std::nullopt,
    Dimension::length, std::nullopt,     std::nullopt,      std::nullopt};
static_assert(std::size(point_dimensions) == arg::ball, "one per point argument");

// Point argument k: a quantity where it has a dimension, else a plain number.
double point_number(int k, const py::handle& value) {
  const std::string& name = point_arguments()[k];
  const std::optional<Dimension> dimension = point_dimensions[k];
  return dimension ? quantity_argument(name, value, *dimension) : number(name, value);
}

Dimension dimension_named(const std::string& name) {
  for (const Dimension d : {Dimension::length, Dimension::mass, Dimension::speed, Dimension::angular_speed,
                            Dimension::frequency, Dimension::angle, Dimension::temperature, Dimension::pressure})
    if (dimension_name(d) == name) return d;
  throw py::value_error("unknown dimension '" + name + "'");
}

}  // namespace

void check_point_ranges(const ImpactScene& scene, const std::set<std::string>& per_point) {
  char value[32];
  if (const auto outside = ball_out_of_range(scene.ball); outside && !per_point.contains(outside->key)) {
    std::snprintf(value, sizeof value, "%.10g", outside->value);
    throw InputError(outside->key + " " + value + ": " + outside->expected());
  }
  if (!valid_omega(scene.swing.omega) && !per_point.contains("omega")) {
    std::snprintf(value, sizeof value, "%.10g", scene.swing.omega);
    throw InputError(std::string("omega ") + value + ": expected " + omega_expected);
  }
  // The oblique keys as a study's and the program's options take them (a miss is a status).
  const ObliqueImpact& o = scene.oblique;
  const std::tuple<const char*, double, bool, const char*> oblique[] = {
      {"undercut", o.undercut, valid_undercut(o.undercut), undercut_expected},
      {"swing_tilt", o.swing_tilt, valid_swing_tilt(o.swing_tilt), swing_tilt_expected},
      {"pitch_spin", o.pitch_spin, valid_pitch_spin(o.pitch_spin), pitch_spin_expected},
      {"friction", o.friction, valid_friction(o.friction), friction_expected}};
  for (const auto& [name, x, valid, expected] : oblique)
    if (!valid && !per_point.contains(name)) {
      std::snprintf(value, sizeof value, "%.10g", x);
      throw InputError(std::string(name) + " " + value + ": expected " + expected);
    }
}

std::optional<double> real_number(const py::handle& value) {
  // A complex number would lose its imaginary part, a bool read as 0 or 1: neither is a value.
  if (PyComplex_Check(value.ptr()) || is_numpy(value, "complexfloating") || py::isinstance<py::bool_>(value) ||
      is_numpy(value, "bool_") || py::isinstance<py::str>(value))
    return std::nullopt;
  try {
    return value.cast<double>();
  } catch (const py::cast_error&) {
    return std::nullopt;
  }
}

double number(const std::string& name, const py::handle& value) {
  if (const std::optional<double> x = real_number(value)) return *x;
  throw InputError(name + " " + py::repr(value).cast<std::string>() + ": expected a real number");
}

std::optional<Dimension> point_argument_dimension(const std::string& name) {
  const auto& names = point_arguments();
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? std::nullopt : point_dimensions[it - names.begin()];
}

double quantity_argument(const std::string& name, const py::handle& value, Dimension dimension) {
  if (!py::isinstance<py::str>(value)) {
    if (const std::optional<double> x = real_number(value)) return *x;
  } else if (const std::optional<double> si = parse_quantity(value.cast<std::string>(), dimension)) {
    return *si;
  }
  throw InputError(name + " " + py::repr(value).cast<std::string>() + ": expected " + expected_quantity(dimension));
}

void bind_quantity_arguments(py::module_& m) {
  m.def(
      "_si",
      [](const std::string& name, const py::object& value, std::optional<std::string> dimension) -> py::object {
        if (!py::isinstance<py::str>(value)) return value;
        const std::optional<Dimension> d = dimension ? dimension_named(*dimension) : point_argument_dimension(name);
        return d ? py::float_(quantity_argument(name, value, *d)) : value;
      },
      py::arg("name"), py::arg("value"), py::arg("dimension") = py::none());
}

void set_point_argument(ImpactScene& s, int which, double v) {
  switch (which) {
    case 0: s.z = v; break;
    case 1: s.ball_speed = v; break;
    case 2: s.swing.cm_speed = v, s.swing.about_center = false; break;
    case 3: s.swing.center = v, s.swing.about_center = true; break;
    case 4: s.swing.omega = v; break;
    case 5: s.ball.e0 = v; break;
    case 6: s.ball.mass = v; break;
    case 7: s.ball.radius = v; break;
    case 8: s.ball.k1 = v; break;
    case 9: s.ball.a = v; break;
    case 10: s.oblique.undercut = v; break;
    case 11: s.oblique.swing_tilt = v; break;
    case 12: s.oblique.pitch_spin = v; break;
    default: s.oblique.friction = v; break;
  }
}

int parse_modes(const py::handle& value) {
  if (py::isinstance<py::str>(value)) {
    const std::string text = value.cast<std::string>();
    if (text == "all") return all_modes;
    if (text == "auto") return auto_modes;
  } else if (!py::isinstance<py::bool_>(value) &&
             py::isinstance(value, py::module_::import("numbers").attr("Integral"))) {
    // Any integer (numpy's too; not numpy's bool, which is no Integral), compared as a Python int:
    // 10**20 is no C++ integer, and refused like any other count too large.
    const auto count = py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
    if (!count) throw py::error_already_set();
    if (count.attr("__ge__")(0).cast<bool>() && count.attr("__le__")(2 * max_slices).cast<bool>())
      return count.cast<int>();
  }
  throw InputError("modes " + py::repr(value).cast<std::string>() +
                   ": expected a number of vibrational modes (0, 1, 2, ...), 'all' or 'auto'");
}

namespace {

// The scene of the arguments' values; `per_point` names those given as arrays instead.
SceneArgs scene_from(const SceneValues& values, const std::set<std::string>& per_point) {
  std::array<bool, arg::count> varies{};
  for (const std::string& name : per_point)
    if (const int k = argument_index(name); k >= 0) varies[k] = true;
  SceneArgs out;
  ImpactScene& s = out.scene;
  const auto given = [&](int k) { return varies[k] || (values[k] && !values[k].is_none()); };
  const auto has = [&](int k) { return given(k) && !varies[k]; };
  const auto get = [&](int k) { return values[k]; };

  // The named ball first: the ball's values given beside it (and per point) override its own.
  if (has(arg::ball)) {
    if (!py::isinstance<py::str>(get(arg::ball)))
      throw InputError("ball " + py::str(get(arg::ball)).cast<std::string>() +
                       ": expected a preset's name or a TOML file with a [ball] table");
    s.ball = load_ball(get(arg::ball).cast<std::string>(), "ball").ball;
  }
  const auto& names = point_arguments();
  for (std::size_t k = 0; k < names.size(); ++k)
    if (has(static_cast<int>(k))) set_point_argument(s, static_cast<int>(k), point_number(static_cast<int>(k), get(static_cast<int>(k))));
  check_point_ranges(s, per_point);
  if (!given(arg::z)) throw InputError("impact: z is required");
  if (!given(arg::ball_speed)) throw InputError("impact: ball_speed is required");
  const bool cm = given(arg::cm_speed), center = given(arg::center);
  if (!cm && !center) throw InputError("impact: give the swing as cm_speed or as center");
  if (cm && center) throw InputError("impact: cm_speed excludes center: give the swing as one of them");
  s.swing.about_center = center;

  if (has(arg::theory)) out.theory = parse_beam_theory(text("theory", get(arg::theory), "\"timoshenko\" or \"euler-bernoulli\""));
  if (has(arg::pivot)) s.pivoted = flag("pivot", get(arg::pivot));
  if (has(arg::mode_tolerance)) s.mode_tolerance = number("mode_tolerance", get(arg::mode_tolerance));
  // As a study's keys and --accuracy, --step-accuracy: each in its range, neither beside what it
  // chooses itself.
  if (has(arg::accuracy)) {
    s.accuracy = number("accuracy", get(arg::accuracy));
    if (!(s.accuracy >= min_accuracy && s.accuracy <= max_accuracy))
      throw InputError("accuracy " + py::repr(get(arg::accuracy)).cast<std::string>() + ": expected " + accuracy_expected);
  }
  if (has(arg::step_accuracy)) {
    s.step_accuracy = number("step_accuracy", get(arg::step_accuracy));
    if (!(std::isfinite(s.step_accuracy) && s.step_accuracy > 0))
      throw InputError("step_accuracy " + py::repr(get(arg::step_accuracy)).cast<std::string>() + ": expected " +
                       step_accuracy_expected);
  }
  // The pairs' indices (-1: no argument here, as "slices"), found once.
  static const auto pairs = [] {
    std::vector<std::pair<int, int>> indices;
    for (const AccuracyExclusion& pair : accuracy_exclusions)
      indices.emplace_back(argument_index(pair.given), argument_index(pair.accuracy));
    return indices;
  }();
  for (std::size_t p = 0; p < pairs.size(); ++p)
    if (const AccuracyExclusion& pair = accuracy_exclusions[p];
        pairs[p].first >= 0 && pairs[p].second >= 0 && has(pairs[p].first) && has(pairs[p].second))
      throw InputError(std::string("impact: ") + pair.given + " excludes " + pair.accuracy + " (which chooses " +
                       pair.chooses + "): give one of them");
  if (has(arg::tolerance)) s.integrator.tolerance = number("tolerance", get(arg::tolerance));
  if (has(arg::window)) s.integrator.window = number("window", get(arg::window));
  // As the program's --n2000: RK4 at 5 us and 18 modes unless integrator, dt or modes say otherwise.
  const bool n2000 = has(arg::n2000) && flag("n2000", get(arg::n2000));
  if (n2000 && !has(arg::integrator)) s.integrator = with_n2000_settings(s.integrator);
  if (has(arg::integrator))
    s.integrator.method = parse_method(text("integrator", get(arg::integrator), "\"exact\", \"rk4\" or \"dopri\""));
  if (has(arg::dt)) s.integrator.dt = number("dt", get(arg::dt));
  else s.integrator.dt = default_step(s.integrator.method);
  if (!valid_step(s.integrator.dt)) {
    char text[200];
    std::snprintf(text, sizeof text, "impact: dt %g: expected a step in [%g, %g] s (a finer one could take more than "
                  "1e7 steps per contact, a coarser one steps over it)", s.integrator.dt, finest_step, coarsest_step);
    throw InputError(text);
  }
  s.vibrational_modes = has(arg::modes) ? parse_modes(get(arg::modes)) : n2000 ? n2000_modes : auto_modes;
  // dopri alone reads a tolerance, and auto alone a mode tolerance: beside another integrator or a
  // fixed set of modes either would be silently ignored.
  if (has(arg::tolerance) && s.integrator.method != Method::dopri)
    throw InputError("impact: tolerance " + py::repr(get(arg::tolerance)).cast<std::string>() +
                     ": expected integrator=\"dopri\" beside it, the one integrator that reads a tolerance (" +
                     to_string(s.integrator.method) + " steps at dt): give integrator=\"dopri\", or step_accuracy");
  if (has(arg::mode_tolerance) && s.vibrational_modes != auto_modes) {
    const std::string fixed = has(arg::modes) ? "modes=" + py::repr(get(arg::modes)).cast<std::string>() : "n2000";
    throw InputError("impact: mode_tolerance " + py::repr(get(arg::mode_tolerance)).cast<std::string>() +
                     ": expected modes=\"auto\" beside it, the one choice of modes that reads a tolerance (" + fixed +
                     " keeps a fixed set): give modes=\"auto\", or no mode_tolerance");
  }
  return out;
}

}  // namespace

SceneArgs scene_args(const py::dict& args, const std::set<std::string>& per_point) {
  SceneValues values;
  for (const auto& [key, value] : args) {
    const std::string name = key.cast<std::string>();
    const int k = argument_index(name);
    if (k < 0) throw py::type_error("unexpected keyword argument '" + name + "'");
    values[k] = value;
  }
  return scene_from(values, per_point);
}

std::optional<SceneArgs> plain_scene_args(const py::tuple& given) {
  if (given.size() != arg::count) throw py::type_error("impact: expected " + std::to_string(arg::count) + " arguments");
  SceneValues values;
  std::array<py::object, arg::count> floats;  // the ints as floats, held while the scene is read
  for (int k = 0; k < arg::count; ++k) {
    PyObject* value = given[k].ptr();
    values[k] = value;
    const bool number = k < arg::ball || (k >= arg::mode_tolerance && k != arg::integrator && k <= arg::window);
    if (value == Py_None || (number ? PyFloat_CheckExact(value) : k != arg::ball || PyUnicode_CheckExact(value)))
      continue;
    if (!number || !PyLong_CheckExact(value)) return std::nullopt;
    const double x = PyLong_AsDouble(value);  // rounded to nearest, as float(value)
    if (x == -1 && PyErr_Occurred()) {  // too large for a double: the package says so
      PyErr_Clear();
      return std::nullopt;
    }
    floats[k] = py::float_(x);
    values[k] = floats[k];
  }
  return scene_from(values, {});
}

}  // namespace sweetspot::python
