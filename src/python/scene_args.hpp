#pragma once
// The keyword arguments of sweetspot.impact and sweetspot.impacts as a scene, checked as the
// program checks its options (src/app/command_impact.cpp): the same defaults, the same refusals.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "sweetspot/bat/modes.hpp"
#include "sweetspot/impact/scene.hpp"
#include "sweetspot/units/quantity.hpp"

namespace sweetspot::python {

// The arguments that may vary from point to point in sweetspot.impacts (numbers only).
inline const std::vector<std::string>& point_arguments() {
  static const std::vector<std::string> names = {"z",          "ball_speed", "cm_speed",   "center",  "omega",
                                                 "e0",         "ball_mass",  "ball_radius", "k1",     "a",
                                                 "undercut",   "swing_tilt", "pitch_spin",  "friction"};
  return names;
}

// The dimension of a point argument ("z": length, "ball_speed": speed), or nothing (e0, k1, a).
std::optional<Dimension> point_argument_dimension(const std::string& name);

// A length, mass or speed as Python gives it: a number (SI), or a string with its unit ("28 in",
// "136 mph"). Throws InputError "z '31 oz': expected a length (...)" otherwise.
double quantity_argument(const std::string& name, const pybind11::handle& value, Dimension dimension);

// sweetspot._si(name, value, dimension=None): a string with a unit as SI, anything else as it is
// (numbers, arrays, None), for the package's own argument conversion; `dimension` ("length",
// "mass", "speed", "angular speed") defaults to the point argument's.
void bind_quantity_arguments(pybind11::module_& m);

// A real number as Python gives it (int, float, numpy's), or nothing for anything else: a
// string, a bool, a complex number (whose imaginary part would be lost), an array.
std::optional<double> real_number(const pybind11::handle& value);
// real_number, or InputError "density '700': expected a real number".
double number(const std::string& name, const pybind11::handle& value);

// Sets one point argument (an index into point_arguments()) on the scene. No Python involved:
// called with the GIL released.
void set_point_argument(ImpactScene& scene, int which, double value);

// The ball's ranges (ball_tests.hpp) and the swing's omega (>= 0) before any work: InputError
// "ball_mass 1e-300: expected a mass in [0.001, 10] kg" for the first value out of range, unless it
// is given per point (those are checked point by point, before any point runs).
void check_point_ranges(const ImpactScene& scene, const std::set<std::string>& per_point = {});

// The program's --modes: a count, "all" or "auto"; throws InputError for anything else.
int parse_modes(const pybind11::handle& value);

struct SceneArgs {
  ImpactScene scene;
  BeamTheory theory = BeamTheory::timoshenko;
};

// Every keyword argument of sweetspot.impact and sweetspot.impacts: the point arguments (in
// point_arguments()' order), then these.
inline const std::vector<std::string>& scene_arguments() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all = point_arguments();
    for (const char* other : {"ball", "pivot", "modes", "mode_tolerance", "accuracy", "step_accuracy", "integrator",
                              "dt", "tolerance", "window", "theory", "n2000"})
      all.emplace_back(other);
    return all;
  }();
  return names;
}

// `args`: keyword -> value (None: not given); `per_point`: the point arguments given as arrays
// instead, which count as given. Throws InputError for bad values, TypeError for unknown names.
SceneArgs scene_args(const pybind11::dict& args, const std::set<std::string>& per_point = {});

// impact()'s arguments as a tuple in scene_arguments()' order, when every number among them is a
// plain float, int or None and `ball` a str or None: the scene scene_args makes of them after the
// package's checks (which turn those ints into the same floats). Nothing when any is something
// else (a string with a unit, a numpy number, an array, a path): the package checks and converts
// it first, with its messages.
std::optional<SceneArgs> plain_scene_args(const pybind11::tuple& values);

}  // namespace sweetspot::python
