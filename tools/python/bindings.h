// The parts of the extension voxgi._voxgi (tools/python/module.cpp): each adds its functions to
// the module. The package voxgi (tools/python/voxgi/__init__.py) is the API users call, with its
// docstrings; these are its primitives.
#pragma once

#include <pybind11/pybind11.h>

namespace voxgi::python {

void bindRegistry(pybind11::module_& m);  // techniques, stages, buffers, settings, presets
void bindRuns(pybind11::module_& m);      // scenes, plans, runs, diffs, checks, path tracing
void bindDumps(pybind11::module_& m);     // reading dumps (.vdb, .exr)

}  // namespace voxgi::python
