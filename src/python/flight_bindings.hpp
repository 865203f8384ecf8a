#pragma once
// The batted ball's flight for Python: _flight, which the package's flight() calls with its
// arguments checked and in SI (angles in deg, humidity in %).
#include <pybind11/pybind11.h>

namespace sweetspot::python {

void bind_flight(pybind11::module_& m);

}  // namespace sweetspot::python
