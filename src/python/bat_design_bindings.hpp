#pragma once
// The bat-design side of the Python module: bats from knots or named dimensions (as bat files
// give them), what a designer reads of a bat (exact for its designed shape), and its
// certification in the virtual test rig (`sweetspot certify`).
#include <memory>

#include <pybind11/pybind11.h>

#include "bat_handle.hpp"

namespace sweetspot::python {

void bind_bat_design(pybind11::module_& m, pybind11::class_<BatHandle, std::shared_ptr<BatHandle>>& bat);

// A design cut into its slices (or `slices`), checked as a bat file's is; `source` the texts it
// was read from (none for a design made in Python).
std::shared_ptr<BatHandle> make_bat(BatDesign design, std::optional<int> slices, BatSource source = {});

}  // namespace sweetspot::python
