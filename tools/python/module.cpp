// The extension module voxgi._voxgi. Errors cross into Python as voxgi.InputError (a ValueError:
// bad input, the CLI's exit 2) with the CLI's one-line message, and as RuntimeError otherwise.
#include <pybind11/pybind11.h>

#include "common/error.h"
#include "tools/python/bindings.h"

PYBIND11_MODULE(_voxgi, m) {
  m.doc() = "voxgi's C++ core; use the package voxgi (docs/python.md)";
  pybind11::register_exception<voxgi::InputError>(m, "InputError", PyExc_ValueError);
  voxgi::python::bindRegistry(m);
  voxgi::python::bindRuns(m);
  voxgi::python::bindDumps(m);
  voxgi::python::bindStudies(m);
}
