#pragma once
// The keyword arguments of sweetspot.impact and sweetspot.impacts as a scene, checked as the
// program checks its options (src/app/command_impact.cpp): the same defaults, the same refusals.
#include <set>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "sweetspot/bat/modes.hpp"
#include "sweetspot/impact/scene.hpp"

namespace sweetspot::python {

// The arguments that may vary from point to point in sweetspot.impacts (numbers only).
inline const std::vector<std::string>& point_arguments() {
  static const std::vector<std::string> names = {"z",  "ball_speed", "cm_speed",    "center", "omega",
                                                 "e0", "ball_mass",  "ball_radius", "k1",     "a"};
  return names;
}

// Sets one point argument (an index into point_arguments()) on the scene. No Python involved:
// called with the GIL released.
void set_point_argument(ImpactScene& scene, int which, double value);

// The program's --modes: a count, "all" or "auto"; throws InputError for anything else.
int parse_modes(const pybind11::handle& value);

struct SceneArgs {
  ImpactScene scene;
  BeamTheory theory = BeamTheory::timoshenko;
};

// `args`: keyword -> value (None: not given); `per_point`: the point arguments given as arrays
// instead, which count as given. Throws InputError for bad values, TypeError for unknown names.
SceneArgs scene_args(const pybind11::dict& args, const std::set<std::string>& per_point = {});

}  // namespace sweetspot::python
