// Buffers and images as NumPy arrays (docs/python.md, "Arrays"). A buffer's array is a view of its
// words, no copy: the last axis holds its components, the others follow its shape (x fastest, so
// a volume is indexed [k, j, i, c]):
//   volume  (N, N, N, C)        series  (steps, N, N, N, C)     image  (height, width, C)
//   maps    (maps, R, R, C)     mips, mips6, sparse  (elements, C), levels by common/mips.h
// with the dtype of its words (uint32, int32, float32).
#pragma once

#include <string>
#include <vector>

#include <pybind11/numpy.h>

#include "common/buffer.h"
#include "common/image.h"

namespace voxgi::python {

namespace py = pybind11;

std::vector<py::ssize_t> arrayShape(const Buffer& b);
py::dtype arrayDtype(ScalarType type);
// "(64, 64, 64, 4) float32", for messages.
std::string describeArray(const std::vector<py::ssize_t>& shape, ScalarType type);

// A read-only view of b's words; `owner` (the Python object holding b) lives as long as the view.
py::array bufferArray(const Buffer& b, py::handle owner);

// A buffer of `spec` and `extent` holding a copy of `array`, which must have the dtype and shape
// such a buffer's array has; throws InputError naming `source` otherwise.
Buffer arrayBuffer(const BufferSpec& spec, glm::ivec3 extent, const py::array& array,
                   const std::string& source);

// An image as a (height, width, 3) float32 array that owns it (no copy).
py::array imageArray(Image image);
// A (height, width, 3) array of real numbers as an image; throws InputError naming `source`.
Image arrayImage(const py::array& array, const std::string& source);

}  // namespace voxgi::python
