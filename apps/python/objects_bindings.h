#pragma once
// The bindings behind touchdown.Pad, Soil, Lander and Scenario (objects_bindings.cpp), added to
// the module touchdown._touchdown.
#include <pybind11/pybind11.h>

namespace touchdown::python {

namespace py = pybind11;

void RegisterObjectBindings(py::module_& m);

}  // namespace touchdown::python
