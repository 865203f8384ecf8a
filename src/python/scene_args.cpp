#include "scene_args.hpp"

#include <cmath>
#include <cstdio>
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

const std::set<std::string>& known_arguments() {
  static const std::set<std::string> names = {
      "z",  "ball_speed", "cm_speed",    "center", "omega",          "e0",       "ball_mass", "ball_radius",
      "k1", "a",          "pivot",       "modes",  "mode_tolerance", "accuracy", "integrator", "dt",
      "tolerance", "window", "theory", "n2000", "ball", "step_accuracy", "undercut", "swing_tilt", "pitch_spin",
      "friction"};
  return names;
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

// A point argument: a quantity where it has a dimension, else a plain number.
double point_number(const std::string& name, const py::handle& value) {
  const std::optional<Dimension> dimension = point_argument_dimension(name);
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
  if (name == "z" || name == "center" || name == "ball_radius" || name == "undercut") return Dimension::length;
  if (name == "ball_speed" || name == "cm_speed") return Dimension::speed;
  if (name == "omega") return Dimension::angular_speed;
  if (name == "ball_mass") return Dimension::mass;
  return std::nullopt;
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
  } else if (py::isinstance<py::int_>(value) && !py::isinstance<py::bool_>(value)) {
    // Compared as Python ints: 10**20 is no C++ integer, and refused like any other count too large.
    if (value.attr("__ge__")(0).cast<bool>() && value.attr("__le__")(2 * max_slices).cast<bool>())
      return value.cast<int>();
  }
  throw InputError("modes " + py::str(value).cast<std::string>() +
                   ": expected a number of vibrational modes (0, 1, 2, ...), 'all' or 'auto'");
}

SceneArgs scene_args(const py::dict& args, const std::set<std::string>& per_point) {
  SceneArgs out;
  ImpactScene& s = out.scene;
  std::set<std::string> given = per_point;
  for (const auto& [key, value] : args) {
    const std::string name = key.cast<std::string>();
    if (!known_arguments().contains(name)) throw py::type_error("unexpected keyword argument '" + name + "'");
    if (!value.is_none()) given.insert(name);
  }
  auto has = [&](const char* name) { return given.contains(name) && !per_point.contains(name); };
  auto get = [&](const char* name) { return args[name]; };

  // The named ball first: the ball's values given beside it (and per point) override its own.
  if (has("ball")) {
    if (!py::isinstance<py::str>(get("ball")))
      throw InputError("ball " + py::str(get("ball")).cast<std::string>() +
                       ": expected a preset's name or a TOML file with a [ball] table");
    s.ball = load_ball(get("ball").cast<std::string>(), "ball").ball;
  }
  const auto& names = point_arguments();
  for (std::size_t k = 0; k < names.size(); ++k)
    if (has(names[k].c_str()))
      set_point_argument(s, static_cast<int>(k), point_number(names[k], get(names[k].c_str())));
  check_point_ranges(s, per_point);
  if (!given.contains("z")) throw InputError("impact: z is required");
  if (!given.contains("ball_speed")) throw InputError("impact: ball_speed is required");
  const bool cm = given.contains("cm_speed"), center = given.contains("center");
  if (!cm && !center) throw InputError("impact: give the swing as cm_speed or as center");
  if (cm && center) throw InputError("impact: cm_speed excludes center: give the swing as one of them");
  s.swing.about_center = center;

  if (has("theory")) out.theory = parse_beam_theory(text("theory", get("theory"), "\"timoshenko\" or \"euler-bernoulli\""));
  if (has("pivot")) s.pivoted = flag("pivot", get("pivot"));
  if (has("mode_tolerance")) s.mode_tolerance = number("mode_tolerance", get("mode_tolerance"));
  // As a study's keys and --accuracy, --step-accuracy: each in its range, neither beside what it
  // chooses itself.
  if (has("accuracy")) {
    s.accuracy = number("accuracy", get("accuracy"));
    if (!(s.accuracy >= min_accuracy && s.accuracy <= max_accuracy))
      throw InputError("accuracy " + py::repr(get("accuracy")).cast<std::string>() + ": expected " + accuracy_expected);
  }
  if (has("step_accuracy")) {
    s.step_accuracy = number("step_accuracy", get("step_accuracy"));
    if (!(std::isfinite(s.step_accuracy) && s.step_accuracy > 0))
      throw InputError("step_accuracy " + py::repr(get("step_accuracy")).cast<std::string>() + ": expected " +
                       step_accuracy_expected);
  }
  for (const AccuracyExclusion& pair : accuracy_exclusions)
    if (has(pair.given) && has(pair.accuracy))
      throw InputError(std::string("impact: ") + pair.given + " excludes " + pair.accuracy + " (which chooses " +
                       pair.chooses + "): give one of them");
  if (has("tolerance")) s.integrator.tolerance = number("tolerance", get("tolerance"));
  if (has("window")) s.integrator.window = number("window", get("window"));
  // As the program's --n2000: RK4 at 5 us and 18 modes unless integrator, dt or modes say otherwise.
  const bool n2000 = has("n2000") && flag("n2000", get("n2000"));
  if (n2000 && !has("integrator")) s.integrator = with_n2000_settings(s.integrator);
  if (has("integrator"))
    s.integrator.method = parse_method(text("integrator", get("integrator"), "\"exact\", \"rk4\" or \"dopri\""));
  if (has("dt")) s.integrator.dt = number("dt", get("dt"));
  else s.integrator.dt = default_step(s.integrator.method);
  if (!(s.integrator.dt >= finest_step)) {
    char text[160];
    std::snprintf(text, sizeof text, "impact: dt %g: expected a step >= %g s (a finer one could take more than 1e7 "
                  "steps per contact)", s.integrator.dt, finest_step);
    throw InputError(text);
  }
  s.vibrational_modes = has("modes") ? parse_modes(get("modes")) : n2000 ? n2000_modes : auto_modes;
  return out;
}

}  // namespace sweetspot::python
