#pragma once
// An impact's result as Python gets it: a dict under the names of `sweetspot impact --json`.
#include <pybind11/pybind11.h>

#include "sweetspot/bat/bat.hpp"
#include "sweetspot/impact/impact.hpp"

namespace sweetspot::python {

// The value impact()'s Result holds where it makes a value when first read (sweetspot.Result's
// _LATER). Used with the GIL held.
pybind11::handle later_marker();

// The result under the names of `sweetspot impact --json`, in its order; NaN where JSON has null.
// Filled into `into` (empty: impact()'s Result), or a new dict; with `estimates_later`, the error
// estimates (slicing_error, step_error, total_error) are later_marker().
pybind11::dict result_dict(const ImpactResult& r, const Bat& bat, pybind11::dict into = {},
                           bool estimates_later = false);

}  // namespace sweetspot::python
