#include "common/vdb_io.h"

#include <openvdb/openvdb.h>

#include "common/error.h"

namespace voxgi {
namespace {

openvdb::math::Transform::Ptr gridTransform(const GridSpec& grid) {
  const double h = grid.voxelSize();
  auto t = openvdb::math::Transform::createLinearTransform(h);
  const glm::dvec3 origin = grid.min + glm::dvec3(0.5 * h);
  t->postTranslate(openvdb::Vec3d(origin.x, origin.y, origin.z));
  return t;
}

template <class GridT, class Convert>
openvdb::GridBase::Ptr makeGrid(const Buffer& b, const GridSpec& grid, Convert convert) {
  auto g = GridT::create();
  auto acc = g->getAccessor();
  const int n = grid.resolution;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const size_t e = grid.index({i, j, k});
        bool nonzero = false;
        for (int c = 0; c < b.components(); ++c)
          nonzero |= b.words[e * size_t(b.components()) + size_t(c)] != 0u;
        if (nonzero) acc.setValue(openvdb::Coord(i, j, k), convert(b, e));
      }
  return g;
}

template <class GridT, class Store>
void fillBuffer(const openvdb::GridBase::Ptr& base, Buffer& b, int n, Store store) {
  const auto g = openvdb::gridPtrCast<GridT>(base);
  if (!g) return;
  for (auto it = g->cbeginValueOn(); it; ++it) {
    const openvdb::Coord c = it.getCoord();
    if (c.x() < 0 || c.y() < 0 || c.z() < 0 || c.x() >= n || c.y() >= n || c.z() >= n) continue;
    const size_t e = size_t(c.x()) + size_t(n) * (size_t(c.y()) + size_t(n) * size_t(c.z()));
    store(b, e, *it);
  }
}

}  // namespace

void writeVdb(const std::string& path, const std::vector<const Buffer*>& buffers,
              const GridSpec& grid, const std::map<std::string, std::string>& metadata) {
  openvdb::initialize();
  openvdb::GridPtrVec grids;
  for (const Buffer* b : buffers) {
    openvdb::GridBase::Ptr g;
    const bool vec = b->components() == 3;
    if (b->spec->type == ScalarType::f32) {
      if (vec)
        g = makeGrid<openvdb::Vec3SGrid>(*b, grid, [](const Buffer& x, size_t e) {
          return openvdb::Vec3s(x.get<float>(e, 0), x.get<float>(e, 1), x.get<float>(e, 2));
        });
      else
        g = makeGrid<openvdb::FloatGrid>(
            *b, grid, [](const Buffer& x, size_t e) { return x.get<float>(e, 0); });
    } else {  // integers keep their bits: u32 is stored bit-cast as int32
      if (vec)
        g = makeGrid<openvdb::Vec3IGrid>(*b, grid, [](const Buffer& x, size_t e) {
          return openvdb::Vec3i(x.get<int32_t>(e, 0), x.get<int32_t>(e, 1), x.get<int32_t>(e, 2));
        });
      else
        g = makeGrid<openvdb::Int32Grid>(
            *b, grid, [](const Buffer& x, size_t e) { return x.get<int32_t>(e, 0); });
    }
    g->setName(std::string(b->spec->name));
    g->setTransform(gridTransform(grid));
    if (b->spec->name == "opacity") g->setGridClass(openvdb::GRID_FOG_VOLUME);
    if (b->spec->name == "normal") g->setVectorType(openvdb::VEC_COVARIANT);
    g->insertMeta("voxgi_stage", openvdb::StringMetadata(std::string(b->spec->stage)));
    g->insertMeta("voxgi_type", openvdb::StringMetadata(scalarTypeName(b->spec->type)));
    g->insertMeta("voxgi_grid_min",
                  openvdb::Vec3DMetadata(openvdb::Vec3d(grid.min.x, grid.min.y, grid.min.z)));
    g->insertMeta("voxgi_grid_size", openvdb::DoubleMetadata(grid.size));
    g->insertMeta("voxgi_resolution", openvdb::Int32Metadata(grid.resolution));
    for (const auto& [key, value] : metadata) g->insertMeta(key, openvdb::StringMetadata(value));
    grids.push_back(g);
  }
  try {
    openvdb::io::File file(path);
    file.write(grids);
    file.close();
  } catch (const openvdb::Exception& e) {
    throw InputError(path, "", std::string("cannot write: ") + e.what());
  }
}

BufferSet readVdb(const std::string& path, GridSpec& grid,
                  const std::vector<const BufferSpec*>& specs) {
  openvdb::initialize();
  openvdb::GridPtrVecPtr grids;
  try {
    openvdb::io::File file(path);
    file.open();
    grids = file.getGrids();
    file.close();
  } catch (const openvdb::Exception& e) {
    throw InputError(path, "", std::string("cannot read: ") + e.what());
  }
  BufferSet out;
  for (const auto& g : *grids) {
    const BufferSpec* spec = nullptr;
    for (const BufferSpec* s : specs)
      if (s->name == g->getName()) spec = s;
    if (spec == nullptr) continue;
    const auto res = g->getMetadata<openvdb::Int32Metadata>("voxgi_resolution");
    const auto min = g->getMetadata<openvdb::Vec3DMetadata>("voxgi_grid_min");
    const auto size = g->getMetadata<openvdb::DoubleMetadata>("voxgi_grid_size");
    if (!res || !min || !size)
      throw InputError(path, "grid '" + g->getName() + "'", "missing voxgi grid metadata");
    if (res->value() < 1 || res->value() > kMaxResolution)
      throw InputError(path, "grid '" + g->getName() + "'.voxgi_resolution", "out of range");
    grid.resolution = res->value();
    grid.min = {min->value().x(), min->value().y(), min->value().z()};
    grid.size = size->value();
    const int n = grid.resolution;
    Buffer b(*spec, glm::ivec3(n));
    fillBuffer<openvdb::FloatGrid>(g, b, n, [](Buffer& x, size_t e, float v) { x.set(e, 0, v); });
    fillBuffer<openvdb::Int32Grid>(g, b, n, [](Buffer& x, size_t e, int32_t v) { x.set(e, 0, v); });
    fillBuffer<openvdb::Vec3SGrid>(g, b, n, [](Buffer& x, size_t e, const openvdb::Vec3s& v) {
      for (int c = 0; c < 3; ++c) x.set(e, c, v[c]);
    });
    fillBuffer<openvdb::Vec3IGrid>(g, b, n, [](Buffer& x, size_t e, const openvdb::Vec3i& v) {
      for (int c = 0; c < 3; ++c) x.set(e, c, v[c]);
    });
    out.emplace(g->getName(), std::move(b));
  }
  return out;
}

}  // namespace voxgi
