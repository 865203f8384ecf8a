#pragma once
// What sweetspot.impact and sweetspot.impacts resolved, as attributes of their results: every
// input that determines the numbers, with the program's defaults filled in, under the names a
// study dataset gives its scene (scene_KEY, study_provenance.cpp), numbers in SI units, flags as
// 0/1 (netCDF has no booleans). Fed back as keyword arguments (sweetspot.scene_of), they make the
// same scene bit for bit.
#include <set>
#include <string>

#include <pybind11/pybind11.h>

#include "scene_args.hpp"

namespace sweetspot::python {

// `per_point`: the point arguments given as arrays, which are coordinates rather than attributes.
pybind11::dict scene_record(const SceneArgs& args, const std::set<std::string>& per_point);

}  // namespace sweetspot::python
