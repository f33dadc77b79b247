#include "tools/python/arrays.h"

#include <cstring>
#include <memory>

#include "common/error.h"

namespace voxgi::python {
namespace {

std::string shapeText(const std::vector<py::ssize_t>& shape) {
  std::string text = "(";
  for (size_t i = 0; i < shape.size(); ++i) text += (i ? ", " : "") + std::to_string(shape[i]);
  return text + (shape.size() == 1 ? ",)" : ")");
}

}  // namespace

std::vector<py::ssize_t> arrayShape(const Buffer& b) {
  const py::ssize_t c = b.components(), x = b.extent.x, y = b.extent.y, z = b.extent.z;
  switch (b.spec->shape) {
    case BufferShape::volume:
      return {z, y, x, c};
    case BufferShape::series:
      return {x == 0 ? 0 : z / x, x, y, x, c};
    case BufferShape::image:
      return {y, x, c};
    case BufferShape::maps:
      return {x == 0 ? 0 : y / x, x, x, c};
    case BufferShape::mips:
    case BufferShape::mips6:
    case BufferShape::sparse:
      return {x * y * z, c};
  }
  return {};
}

py::dtype arrayDtype(ScalarType type) {
  switch (type) {
    case ScalarType::u32:
      return py::dtype::of<uint32_t>();
    case ScalarType::i32:
      return py::dtype::of<int32_t>();
    case ScalarType::f32:
      return py::dtype::of<float>();
    case ScalarType::f16:
      return py::dtype("float16");  // numpy's IEEE half, two a word as the buffer holds them
  }
  return py::dtype::of<float>();
}

std::string describeArray(const std::vector<py::ssize_t>& shape, ScalarType type) {
  return shapeText(shape) + " " + std::string(py::str(arrayDtype(type)));
}

py::array bufferArray(const Buffer& b, py::handle owner) {
  const std::vector<py::ssize_t> shape = arrayShape(b);
  std::vector<py::ssize_t> strides(shape.size());
  py::ssize_t stride = b.halves() ? 2 : 4;
  for (size_t i = shape.size(); i-- > 0;) {
    strides[i] = stride;
    stride *= shape[i];
  }
  // The words belong to the run: the array shares them and keeps the run alive, read-only so that
  // what a run produced stays what it produced.
  py::array array(arrayDtype(b.spec->type), shape, strides, b.words.data(), owner);
  py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

Buffer arrayBuffer(const BufferSpec& spec, glm::ivec3 extent, const py::array& array,
                   const std::string& source) {
  Buffer b(spec, extent);
  const std::vector<py::ssize_t> want = arrayShape(b);
  const std::vector<py::ssize_t> got(array.shape(), array.shape() + array.ndim());
  const py::dtype word = arrayDtype(spec.type);
  if (array.dtype().kind() != word.kind() || array.dtype().itemsize() != word.itemsize() ||
      got != want)
    throw InputError(source, spec.qualifiedName(),
                     "the array is " + shapeText(got) + " " + std::string(py::str(array.dtype())) +
                         ", the buffer " + describeArray(want, spec.type) +
                         " (docs/python.md, \"Arrays\")");
  // The dtype matches the buffer's (checked above), so a C-ordered copy holds its words.
  const py::array words = py::array::ensure(array, py::array::c_style);
  std::memcpy(b.words.data(), words.data(), b.words.size() * sizeof(uint32_t));
  return b;
}

py::array imageArray(Image image) {
  auto* owned = new Image(std::move(image));
  py::capsule free(owned, [](void* p) { delete static_cast<Image*>(p); });
  return py::array_t<float>({py::ssize_t(owned->height), py::ssize_t(owned->width), py::ssize_t(3)},
                            reinterpret_cast<const float*>(owned->pixels.data()), free);
}

Image arrayImage(const py::array& array, const std::string& source) {
  if (array.ndim() != 3 || array.shape(2) != 3 || array.shape(0) < 1 || array.shape(1) < 1 ||
      (array.dtype().kind() != 'f' && array.dtype().kind() != 'u' && array.dtype().kind() != 'i'))
    throw InputError(source, "",
                     "an image is a (height, width, 3) array of real numbers, this one is " +
                         shapeText({array.shape(), array.shape() + array.ndim()}) + " " +
                         std::string(py::str(array.dtype())));
  const auto values = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
  Image image(int(array.shape(1)), int(array.shape(0)));
  std::memcpy(image.pixels.data(), values.data(), image.pixels.size() * sizeof(glm::vec3));
  return image;
}

}  // namespace voxgi::python
