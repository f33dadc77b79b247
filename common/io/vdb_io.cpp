#include "common/io/vdb_io.h"

#include <algorithm>
#include <sstream>

#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>

#include "common/error.h"
#include "common/io/input_file.h"
#include "common/mips.h"
#include "common/io/output_file.h"

namespace voxgi {
namespace {

// Voxel (i,j,k) of a level-`level` grid (voxel size h*2^level) centred in world space.
openvdb::math::Transform::Ptr gridTransform(const GridSpec& grid, int level = 0) {
  const double h = grid.voxelSize() * double(1 << level);
  auto t = openvdb::math::Transform::createLinearTransform(h);
  const glm::dvec3 origin = grid.min + glm::dvec3(0.5 * h);
  t->postTranslate(openvdb::Vec3d(origin.x, origin.y, origin.z));
  return t;
}

// A size^3 block of a buffer: element of (i,j,k) = first + i + rowWidth * (j + size * k).
struct Block {
  size_t first;
  int size;
  size_t rowWidth;
  size_t element(int i, int j, int k) const {
    return first + size_t(i) + rowWidth * (size_t(j) + size_t(size) * size_t(k));
  }
};

// Components [first, first + count) of a buffer's elements.
struct View {
  const Buffer& b;
  int first, count;
  template <class T>
  T get(size_t e, int c) const {
    return b.get<T>(e, first + c);
  }
  bool nonzero(size_t e) const {
    for (int c = 0; c < count; ++c)
      if (b.bitsAt(e, first + c) != 0u) return true;
    return false;
  }
};

// A grid of the view's non-zero elements at the coordinates `places` gives: places(f) calls
// f(coordinate, element) for each element the grid covers.
template <class GridT, class Places, class Convert>
openvdb::GridBase::Ptr makeGrid(const View& v, const Places& places, Convert convert) {
  auto g = GridT::create();
  auto acc = g->getAccessor();
  places([&](openvdb::Coord c, size_t e) {
    if (v.nonzero(e)) acc.setValue(c, convert(v, e));
  });
  return g;
}

// The grids of one block: a scalar or vector grid named `name`; 4-component views give the
// rgb vector grid and the fourth component as `name`_alpha (floats) or `name`_w (integers).
template <class Places>
openvdb::GridPtrVec blockGrids(const View& v, const Places& places, const std::string& name) {
  openvdb::GridPtrVec out;
  const int comps = v.count;
  // Half floats are written as floats, which hold them exactly.
  const bool f32 = v.b.spec->type == ScalarType::f32 || v.b.spec->type == ScalarType::f16;
  if (comps > 4 && comps % 3 == 0) {  // SH volumes: rgb per coefficient, components r0.. g0.. b0..
    const int coefficients = comps / 3;
    for (int i = 0; i < coefficients; ++i) {
      const int r = i, g = coefficients + i, bl = 2 * coefficients + i;
      if (f32)
        out.push_back(makeGrid<openvdb::Vec3SGrid>(v, places, [=](const View& x, size_t e) {
          return openvdb::Vec3s(x.get<float>(e, r), x.get<float>(e, g), x.get<float>(e, bl));
        }));
      else
        out.push_back(makeGrid<openvdb::Vec3IGrid>(v, places, [=](const View& x, size_t e) {
          return openvdb::Vec3i(x.get<int32_t>(e, r), x.get<int32_t>(e, g), x.get<int32_t>(e, bl));
        }));
      out.back()->setName(name + "_c" + std::to_string(i));
    }
    return out;
  }
  if (comps >= 3 && f32)
    out.push_back(makeGrid<openvdb::Vec3SGrid>(v, places, [](const View& x, size_t e) {
      return openvdb::Vec3s(x.get<float>(e, 0), x.get<float>(e, 1), x.get<float>(e, 2));
    }));
  else if (comps >= 3)  // integers keep their bits: u32 is stored bit-cast as int32
    out.push_back(makeGrid<openvdb::Vec3IGrid>(v, places, [](const View& x, size_t e) {
      return openvdb::Vec3i(x.get<int32_t>(e, 0), x.get<int32_t>(e, 1), x.get<int32_t>(e, 2));
    }));
  else if (f32)
    out.push_back(makeGrid<openvdb::FloatGrid>(
        v, places, [](const View& x, size_t e) { return x.get<float>(e, 0); }));
  else
    out.push_back(makeGrid<openvdb::Int32Grid>(
        v, places, [](const View& x, size_t e) { return x.get<int32_t>(e, 0); }));
  out.back()->setName(name);
  if (comps == 4 && f32) {
    out.push_back(makeGrid<openvdb::FloatGrid>(
        v, places, [](const View& x, size_t e) { return x.get<float>(e, 3); }));
    out.back()->setName(name + "_alpha");
  } else if (comps == 4) {
    out.push_back(makeGrid<openvdb::Int32Grid>(
        v, places, [](const View& x, size_t e) { return x.get<int32_t>(e, 3); }));
    out.back()->setName(name + "_w");
  }
  return out;
}

// Every element of a dense block at its (i, j, k).
auto blockPlaces(const Block& block) {
  return [block](const auto& f) {
    for (int k = 0; k < block.size; ++k)
      for (int j = 0; j < block.size; ++j)
        for (int i = 0; i < block.size; ++i) f(openvdb::Coord(i, j, k), block.element(i, j, k));
  };
}

openvdb::GridPtrVec blockGrids(const Buffer& b, const Block& block, const std::string& name) {
  return blockGrids(View{b, 0, b.components()}, blockPlaces(block), name);
}

// A sparse buffer's grids: per component group and pyramid level, the elements `layout` puts
// there (docs/svo.md, "Dumps").
std::vector<std::pair<openvdb::GridPtrVec, int>> sparseGrids(const Buffer& b,
                                                             const SparseLayout& layout,
                                                             const std::string& name) {
  std::vector<std::pair<openvdb::GridPtrVec, int>> out;
  int top = -1;
  for (const int8_t l : layout.level) top = std::max(top, int(l));
  for (int level = 0; level <= top; ++level) {
    const auto places = [&layout, level](const auto& f) {
      for (size_t e = 0; e < layout.level.size(); ++e)
        if (layout.level[e] == level) {
          const glm::ivec3 c = layout.coord[e];
          f(openvdb::Coord(c.x, c.y, c.z), e);
        }
    };
    for (const SparseLayout::Group& g : layout.groups)
      out.emplace_back(
          blockGrids(View{b, g.first, g.count}, places,
                     name + g.suffix + (level > 0 ? "_L" + std::to_string(level) : "")),
          level);
  }
  return out;
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
              const GridSpec& grid, const std::map<std::string, std::string>& metadata,
              const SparseLayouts& sparse) {
  openvdb::initialize();
  openvdb::GridPtrVec grids;
  const int n = grid.resolution;
  static const char* const kFaceNames[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  for (const Buffer* b : buffers) {
    const std::string name(b->spec->name);
    // (grids, pyramid level) per block of the buffer
    std::vector<std::pair<openvdb::GridPtrVec, int>> blocks;
    std::map<std::string, std::string> own;  // the buffer's own metadata (a sparse layout's)
    if (b->spec->shape == BufferShape::sparse) {
      const auto layout = sparse.find(b->spec->id);
      if (layout == sparse.end())
        throw std::logic_error("no layout to write the sparse buffer " + b->spec->qualifiedName() +
                               " as grids");
      blocks = sparseGrids(*b, layout->second, name);
      own = layout->second.metadata;
    } else if (b->spec->shape == BufferShape::volume) {
      blocks.emplace_back(blockGrids(*b, {0, n, size_t(n)}, name), 0);
    } else if (b->spec->shape == BufferShape::series) {
      const size_t volume = size_t(n) * size_t(n) * size_t(n);
      for (int k = 0; k * n < b->extent.z; ++k)
        blocks.emplace_back(
            blockGrids(*b, {size_t(k) * volume, n, size_t(n)}, name + ".step_" + std::to_string(k)),
            0);
    } else if (b->spec->shape != BufferShape::image && b->spec->shape != BufferShape::maps) {
      const int faces = b->spec->shape == BufferShape::mips6 ? 6 : 1;
      for (int level = 1; level <= mipLevelCount(n); ++level) {
        const int s = n >> level;
        for (int f = 0; f < faces; ++f) {
          const std::string face = faces == 6 ? std::string("_") + kFaceNames[f] : "";
          const Block block{mipLevelOffset(n, level, faces) + size_t(f * s), s, size_t(faces * s)};
          blocks.emplace_back(blockGrids(*b, block, name + face + "_L" + std::to_string(level)),
                              level);
        }
      }
    }
    for (auto& [levelGrids, level] : blocks)
      for (const auto& g : levelGrids) {
        g->setTransform(gridTransform(grid, level));
        if (name == "opacity") g->setGridClass(openvdb::GRID_FOG_VOLUME);
        if (name == "normal") g->setVectorType(openvdb::VEC_COVARIANT);
        g->insertMeta("voxgi_stage", openvdb::StringMetadata(b->spec->stageSpec().qualifiedName()));
        g->insertMeta("voxgi_type", openvdb::StringMetadata(scalarTypeName(b->spec->type)));
        g->insertMeta("voxgi_level", openvdb::Int32Metadata(level));
        g->insertMeta("voxgi_grid_min",
                      openvdb::Vec3DMetadata(openvdb::Vec3d(grid.min.x, grid.min.y, grid.min.z)));
        g->insertMeta("voxgi_grid_size", openvdb::DoubleMetadata(grid.size));
        g->insertMeta("voxgi_resolution", openvdb::Int32Metadata(grid.resolution));
        for (const auto& [key, value] : metadata)
          g->insertMeta(key, openvdb::StringMetadata(value));
        for (const auto& [key, value] : own) g->insertMeta(key, openvdb::StringMetadata(value));
        grids.push_back(g);
      }
  }
  // Encoded in memory (OpenVDB's stream format, which io::File reads), then written atomically.
  std::ostringstream bytes(std::ios::binary);
  try {
    openvdb::io::Stream(bytes).write(grids);
  } catch (const openvdb::Exception& e) {
    throw InputError(path, "", std::string("cannot encode VDB: ") + e.what());
  }
  writeFileAtomically(path, bytes.str());
}

BufferSet readVdb(const std::string& path, GridSpec& grid,
                  const std::vector<const BufferSpec*>& specs) {
  requireInputFile(path, "", "VDB file");
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
  // A 4-component buffer comes back from its rgb grid and its `_alpha` or `_w` grid.
  std::vector<std::pair<const BufferSpec*, Buffer>> found;
  for (const auto& g : *grids) {
    const BufferSpec* spec = nullptr;
    int first = 0;  // the component the grid's first value goes to
    for (const BufferSpec* s : specs) {
      const std::string name(s->name);
      if (name == g->getName()) spec = s;
      if (s->components == 4 && (g->getName() == name + "_alpha" || g->getName() == name + "_w"))
        spec = s, first = 3;
    }
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
    auto at =
        std::find_if(found.begin(), found.end(), [&](const auto& f) { return f.first == spec; });
    if (at == found.end()) at = found.insert(found.end(), {spec, Buffer(*spec, glm::ivec3(n))});
    Buffer& b = at->second;
    fillBuffer<openvdb::FloatGrid>(g, b, n,
                                   [=](Buffer& x, size_t e, float v) { x.set(e, first, v); });
    fillBuffer<openvdb::Int32Grid>(g, b, n,
                                   [=](Buffer& x, size_t e, int32_t v) { x.set(e, first, v); });
    fillBuffer<openvdb::Vec3SGrid>(g, b, n, [](Buffer& x, size_t e, const openvdb::Vec3s& v) {
      for (int c = 0; c < 3; ++c) x.set(e, c, v[c]);
    });
    fillBuffer<openvdb::Vec3IGrid>(g, b, n, [](Buffer& x, size_t e, const openvdb::Vec3i& v) {
      for (int c = 0; c < 3; ++c) x.set(e, c, v[c]);
    });
  }
  BufferSet out;
  for (auto& [spec, b] : found) out.put(std::move(b));
  return out;
}

}  // namespace voxgi
