// voxgi.read_dump: every grid a voxgi dump holds (float, int32 and their vec3 forms, which
// python3-openvdb cannot read) as a dense NumPy array with its transform and metadata; an EXR
// dump as its image.
#include <filesystem>

#include <openvdb/openvdb.h>
#include <pybind11/stl.h>

#include "common/error.h"
#include "common/io/image_io.h"
#include "common/io/input_file.h"
#include "tools/python/arrays.h"
#include "tools/python/bindings.h"

namespace voxgi::python {
namespace {

// Dense arrays past this many voxels are refused before allocating: a corrupt or foreign file can
// claim an active box of any size.
constexpr int64_t kMaxDenseVoxels = int64_t(1) << 30;

py::object metadataValue(const openvdb::Metadata& meta) {
  const std::string type = meta.typeName();
  if (type == openvdb::Int32Metadata::staticTypeName())
    return py::int_(static_cast<const openvdb::Int32Metadata&>(meta).value());
  if (type == openvdb::Int64Metadata::staticTypeName())
    return py::int_(static_cast<const openvdb::Int64Metadata&>(meta).value());
  if (type == openvdb::FloatMetadata::staticTypeName())
    return py::float_(static_cast<const openvdb::FloatMetadata&>(meta).value());
  if (type == openvdb::DoubleMetadata::staticTypeName())
    return py::float_(static_cast<const openvdb::DoubleMetadata&>(meta).value());
  if (type == openvdb::BoolMetadata::staticTypeName())
    return py::bool_(static_cast<const openvdb::BoolMetadata&>(meta).value());
  if (type == openvdb::Vec3DMetadata::staticTypeName()) {
    const openvdb::Vec3d v = static_cast<const openvdb::Vec3DMetadata&>(meta).value();
    return py::make_tuple(v.x(), v.y(), v.z());
  }
  if (type == openvdb::Vec3IMetadata::staticTypeName()) {
    const openvdb::Vec3i v = static_cast<const openvdb::Vec3IMetadata&>(meta).value();
    return py::make_tuple(v.x(), v.y(), v.z());
  }
  return py::str(meta.str());
}

// The index box a grid's array covers: the voxgi grid of its level ([0, N >> level)^3, so every
// dump of one scene gives arrays of one shape per level) and whatever is active beyond it.
openvdb::CoordBBox denseBox(const openvdb::GridBase& g) {
  openvdb::CoordBBox box = g.evalActiveVoxelBoundingBox();
  const auto n = g.getMetadata<openvdb::Int32Metadata>("voxgi_resolution");
  const auto level = g.getMetadata<openvdb::Int32Metadata>("voxgi_level");
  if (n && level && n->value() > 0 && level->value() >= 0 && level->value() < 31) {
    const int side = std::max(1, n->value() >> level->value());
    const openvdb::CoordBBox own(openvdb::Coord(0), openvdb::Coord(side - 1));
    if (box.empty())
      box = own;
    else
      box.expand(own);
  }
  return box;
}

// The grid's values over `box` as a (z, y, x[, 3]) array of T, its background where inactive.
template <class GridT, class T, int Components>
py::array denseArray(const GridT& grid, const openvdb::CoordBBox& box) {
  const openvdb::Coord dim = box.empty() ? openvdb::Coord(0) : box.dim();
  std::vector<py::ssize_t> shape{dim.z(), dim.y(), dim.x()};
  if (Components > 1) shape.push_back(Components);
  py::array_t<T> out(shape);
  T* data = out.mutable_data();
  const auto background = grid.background();
  const size_t voxels = size_t(dim.x()) * size_t(dim.y()) * size_t(dim.z());
  const auto put = [&](size_t e, const typename GridT::ValueType& v) {
    if constexpr (Components == 1)
      data[e] = static_cast<T>(v);
    else
      for (int c = 0; c < Components; ++c) data[Components * e + size_t(c)] = static_cast<T>(v[c]);
  };
  for (size_t e = 0; e < voxels; ++e) put(e, background);
  for (auto it = grid.cbeginValueOn(); it; ++it) {
    openvdb::CoordBBox part;
    it.getBoundingBox(part);
    part.intersect(box);
    if (part.empty()) continue;
    for (auto c = part.begin(); c; ++c) {
      const openvdb::Coord p = *c - box.min();
      put(size_t(p.x()) + size_t(dim.x()) * (size_t(p.y()) + size_t(dim.y()) * size_t(p.z())), *it);
    }
  }
  return out;
}

py::dict gridDict(const std::string& path, const openvdb::GridBase::Ptr& g) {
  const openvdb::CoordBBox box = denseBox(*g);
  const openvdb::Coord dim = box.empty() ? openvdb::Coord(0) : box.dim();
  if (int64_t(dim.x()) * dim.y() * dim.z() > kMaxDenseVoxels)
    throw InputError(path, "grid '" + g->getName() + "'",
                     "its active box is too large for a dense array");
  py::array array;
  if (auto f = openvdb::gridPtrCast<openvdb::FloatGrid>(g))
    array = denseArray<openvdb::FloatGrid, float, 1>(*f, box);
  else if (auto i = openvdb::gridPtrCast<openvdb::Int32Grid>(g))
    array = denseArray<openvdb::Int32Grid, int32_t, 1>(*i, box);
  else if (auto v = openvdb::gridPtrCast<openvdb::Vec3SGrid>(g))
    array = denseArray<openvdb::Vec3SGrid, float, 3>(*v, box);
  else if (auto vi = openvdb::gridPtrCast<openvdb::Vec3IGrid>(g))
    array = denseArray<openvdb::Vec3IGrid, int32_t, 3>(*vi, box);
  else if (auto d = openvdb::gridPtrCast<openvdb::DoubleGrid>(g))
    array = denseArray<openvdb::DoubleGrid, double, 1>(*d, box);
  else if (auto b = openvdb::gridPtrCast<openvdb::BoolGrid>(g))
    array = denseArray<openvdb::BoolGrid, bool, 1>(*b, box);
  else
    throw InputError(path, "grid '" + g->getName() + "'",
                     "grid type " + g->type() + " is not one voxgi writes");
  // Index space to world space for column vectors: world = transform @ (i, j, k, 1). OpenVDB's
  // matrices act on row vectors, hence the transpose.
  const openvdb::Mat4d m = g->transform().baseMap()->getAffineMap()->getMat4().transpose();
  py::array_t<double> transform({4, 4});
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) transform.mutable_at(r, c) = m(r, c);
  py::dict meta;
  for (auto it = g->beginMeta(); it != g->endMeta(); ++it)
    meta[py::str(it->first)] = metadataValue(*it->second);
  py::dict out;
  out["array"] = array;
  out["origin"] = py::make_tuple(box.min().x(), box.min().y(), box.min().z());
  out["transform"] = transform;
  out["metadata"] = meta;
  return out;
}

py::object readDump(const std::string& path) {
  requireInputFile(path, "", "dump");
  const std::string ext = std::filesystem::path(path).extension().string();
  if (ext == ".exr") {
    Image image;
    {
      py::gil_scoped_release release;
      image = readExr(path);
    }
    return imageArray(std::move(image));
  }
  if (ext != ".vdb") throw InputError(path, "", "a dump is a .vdb or .exr file");
  openvdb::initialize();
  openvdb::GridPtrVecPtr grids;
  try {
    py::gil_scoped_release release;
    openvdb::io::File file(path);
    file.open();
    grids = file.getGrids();
    file.close();
  } catch (const openvdb::Exception& e) {
    throw InputError(path, "", std::string("cannot read: ") + e.what());
  }
  py::dict out;
  for (const auto& g : *grids) out[py::str(g->getName())] = gridDict(path, g);
  return out;
}

}  // namespace

void bindDumps(py::module_& m) {
  m.def("read_dump", &readDump, py::arg("path"));
}

}  // namespace voxgi::python
