#include "gpu/svo/octree.h"

#include <algorithm>
#include <vector>

#include "common/error.h"
#include "common/memory.h"
#include "gpu/program.h"
#include "shaders/shared/svo/svo_layout.h"

namespace voxgi::gpu::svo {
namespace {

using shared::kNodeWords;
using shared::kSvoNull;
using shared::kTileWords;

// The passes of build.comp.
enum Pass : int {
  kMark = 0,
  kCountLeafTiles = 1,
  kListLeafTiles = 2,
  kReal = 3,
  kBorderNodes = 4,
  kBorderLeaves = 5,
  kCountChildren = 6,
  kAllocate = 7,
  kNeighbours = 8,
  kAccumulate = 9,
};

// Counter slots of the Counters block.
enum Counter : int { kNodeTiles = 0, kLeafTiles = 1, kListed = 2, kPassCount = 3, kOverflow = 4 };

// A storage buffer that grows to the records it must hold, keeping what it has; new node words
// start as kSvoNull with flags 0, other new words as 0.
class Pool {
 public:
  Pool(const Gl& gl, bool nodes, size_t words) : gl_(gl), nodes_(nodes), buffer_(gl, 0) {
    grow(words);
  }
  void grow(size_t words) {
    if (words <= words_ && buffer_.get() != 0) return;
    const size_t capacity = std::max<size_t>({words, words_ + words_ / 2, 64});
    std::vector<uint32_t> init(capacity, 0u);
    if (nodes_)
      for (size_t w = 0; w < capacity; ++w)
        init[w] = w % kNodeWords == shared::kNodeFlags ? 0u : kSvoNull;
    GlBuffer next(gl_, createBuffer(gl_, capacity * 4, init.data()));
    if (words_ > 0)
      gl_.CopyNamedBufferSubData(buffer_.get(), next.get(), 0, 0, GLsizeiptr(words_ * 4));
    buffer_ = std::move(next);
    words_ = capacity;
  }
  GLuint get() const { return buffer_.get(); }
  Words read(size_t words) const {
    Words out(words);
    if (words > 0) gl_.GetNamedBufferSubData(buffer_.get(), 0, GLsizeiptr(words * 4), out.data());
    return out;
  }

 private:
  const Gl& gl_;
  bool nodes_;
  GlBuffer buffer_;
  size_t words_ = 0;
};

class Builder {
 public:
  Builder(const Gl& gl, std::span<const shared::SvoSample> samples, int depth, float scale)
      : gl_(gl),
        program_(gl, {&shaders::svo_build_comp}),
        depth_(depth),
        samples_(gl, createBuffer(gl, samples.size() * sizeof(shared::SvoSample), samples.data())),
        counters_(gl, false, 8),
        nodes_(gl, true, 8 * kNodeWords),
        tiles_(gl, false, kTileWords),
        leafTiles_(gl, false, kTileWords),
        sampleCount_(samples.size()) {
    program_.use();
    program_.set("uDepth", depth);
    program_.set("uScale", scale);
    const size_t tileKeys = size_t(1) << (3 * (depth - 1));
    marks_ = std::make_unique<Pool>(gl, false, std::max<size_t>(1, tileKeys / 4));
    markWords_ = std::max<size_t>(1, tileKeys / 4);
    // The root tile: node tile 0, level 1, key 0, no parent.
    const uint32_t root[kTileWords] = {1u, 0u, kSvoNull, 0u};
    GlBuffer rootBlock(gl, createBuffer(gl, sizeof root, root));
    gl.CopyNamedBufferSubData(rootBlock.get(), tiles_.get(), 0, 0, sizeof root);
    setCounter(kNodeTiles, 1);
  }

  voxgi::svo::OctreeWords run(const std::string& source) {
    source_ = &source;
    dispatch(kMark, sampleCount_);
    dispatch(kCountLeafTiles, markWords_);
    const uint32_t listed = counter(kListed);
    setCounter(kListed, 0);
    leafList_ = std::make_unique<Pool>(gl_, false, std::max<size_t>(2, size_t(listed) * 2));
    dispatch(kListLeafTiles, markWords_);
    // Level by level: the real nodes of level l, the border tiles of level l that they need
    // (children of level l - 1), then the children of level l's nodes (level l + 1's tiles).
    std::vector<uint32_t> start(size_t(depth_) + 2, 0);
    start[1] = 0;
    start[2] = 1;  // level l's node tiles are [start[l], start[l + 1])
    for (int l = 1; l < depth_; ++l) {
      program_.set("uLevel", l);
      dispatch(kReal, listed);
      if (l >= 2) {
        dispatchNodes(kBorderNodes, l, start[size_t(l)], start[size_t(l) + 1]);
        allocateChildren(l - 1, start[size_t(l) - 1], start[size_t(l)]);
        start[size_t(l) + 1] = counter(kNodeTiles);
      }
      allocateChildren(l, start[size_t(l)], start[size_t(l) + 1]);
      if (l + 1 < depth_) start[size_t(l) + 2] = counter(kNodeTiles);
    }
    program_.set("uLevel", depth_);
    dispatch(kBorderLeaves, listed);
    allocateChildren(depth_ - 1, start[size_t(depth_) - 1], start[size_t(depth_)]);
    const uint32_t nodeTiles = counter(kNodeTiles), leafTiles = counter(kLeafTiles);
    dispatchNodes(kNeighbours, 0, 0, nodeTiles);
    sums_ = std::make_unique<Pool>(gl_, false,
                                   std::max<size_t>(1, size_t(leafTiles) * 8 * shared::kSumWords));
    dispatch(kAccumulate, sampleCount_);
    if (counter(kOverflow) != 0)
      throw InputError(
          source, "grid.resolution",
          "a leaf's opacity passes 2^31 fixed-point units; raise grid.resolution or thin "
          "the point cloud");
    gl_.check("build");
    voxgi::svo::OctreeWords out{nodes_.read(size_t(nodeTiles) * 8 * kNodeWords),
                                tiles_.read(size_t(nodeTiles) * kTileWords),
                                leafTiles_.read(size_t(leafTiles) * kTileWords),
                                sums_->read(size_t(leafTiles) * 8 * shared::kSumWords)};
    voxgi::svo::canonicalize(out, depth_);
    return out;
  }

 private:
  void bind() {
    const GLuint blocks[8] = {samples_.get(),
                              marks_->get(),
                              leafList_ ? leafList_->get() : marks_->get(),
                              counters_.get(),
                              nodes_.get(),
                              tiles_.get(),
                              leafTiles_.get(),
                              sums_ ? sums_->get() : marks_->get()};
    for (GLuint b = 0; b < 8; ++b) gl_.BindBufferBase(GL_SHADER_STORAGE_BUFFER, b, blocks[b]);
  }
  // `count` invocations of `pass`.
  void dispatch(Pass pass, size_t count, uint32_t first = 0) {
    if (count == 0) return;
    bind();
    program_.set("uPass", int(pass));
    program_.set("uFirst", first);
    program_.set("uCount", unsigned(count));
    dispatchLinear(gl_, count);
  }
  // A node pass over the nodes of tiles [firstTile, endTile) of `level`.
  void dispatchNodes(Pass pass, int level, uint32_t firstTile, uint32_t endTile) {
    program_.set("uLevel", level);
    dispatch(pass, size_t(endTile - firstTile) * 8, firstTile * 8);
  }
  // Tiles for the nodes of `level` (tiles [firstTile, endTile)) that need a child and lack one,
  // with the pool grown to hold them first.
  void allocateChildren(int level, uint32_t firstTile, uint32_t endTile) {
    setCounter(kPassCount, 0);
    dispatchNodes(kCountChildren, level, firstTile, endTile);
    const uint32_t needed = counter(kPassCount);
    if (needed == 0) return;
    const bool leaves = level + 1 == depth_;
    const size_t after = size_t(counter(leaves ? kLeafTiles : kNodeTiles)) + needed;
    // The tiles' words (and a leaf tile's sums) on the GPU, then twice on the host: read back
    // and put in the canonical form.
    const size_t words = leaves ? kTileWords + 8 * shared::kSumWords : kTileWords + 8 * kNodeWords;
    requireMemory(
        2 * 4 * after * words,
        "the octree's " + std::to_string(after) + (leaves ? " leaf tiles" : " node tiles"),
        *source_, "grid.resolution");
    if (leaves) {
      leafTiles_.grow(after * kTileWords);
    } else {
      tiles_.grow(after * kTileWords);
      nodes_.grow(after * 8 * kNodeWords);
    }
    dispatchNodes(kAllocate, level, firstTile, endTile);
  }
  uint32_t counter(Counter c) {
    uint32_t v = 0;
    gl_.GetNamedBufferSubData(counters_.get(), GLintptr(c * 4), 4, &v);
    return v;
  }
  void setCounter(Counter c, uint32_t v) {
    GlBuffer value(gl_, createBuffer(gl_, 4, &v));
    gl_.CopyNamedBufferSubData(value.get(), counters_.get(), 0, GLintptr(c * 4), 4);
  }

  const Gl& gl_;
  Program program_;
  int depth_;
  GlBuffer samples_;
  Pool counters_, nodes_, tiles_, leafTiles_;
  std::unique_ptr<Pool> marks_, leafList_, sums_;
  size_t markWords_ = 0;
  size_t sampleCount_;
  const std::string* source_ = nullptr;  // run's, for errors
};

}  // namespace

voxgi::svo::OctreeWords buildOctree(GlContext& context, std::span<const shared::SvoSample> samples,
                                    int depth, float scale, const std::string& source) {
  context.makeCurrent();
  return Builder(context.gl(), samples, depth, scale).run(source);
}

}  // namespace voxgi::gpu::svo
