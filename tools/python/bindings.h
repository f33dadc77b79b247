// The parts of the extension voxgi._voxgi (tools/python/module.cpp): each adds its functions to
// the module. The package voxgi (tools/python/voxgi/__init__.py) is the API users call, with its
// docstrings; these are its primitives.
#pragma once

#include <string>

#include <pybind11/pybind11.h>

#include "validation/reference/path_trace.h"

namespace voxgi::python {

namespace py = pybind11;

void bindRegistry(pybind11::module_& m);  // techniques, stages, buffers, settings, presets
void bindRuns(pybind11::module_& m);      // scenes, plans, runs, diffs, checks, path tracing
void bindDumps(pybind11::module_& m);     // reading dumps (.vdb, .exr)
void bindStudies(pybind11::module_& m);   // studies, in one piece or job by job

// The path tracer's options from Python's arguments; throws InputError naming the first bad one.
reference::PathTraceOptions pathOptions(int spp, uint64_t seed, int bounces, int replicas,
                                        const std::string& sampler);

}  // namespace voxgi::python
