// CPU voxelize stage: every (triangle, voxel) pair the shared kernel accepts is accumulated with
// integer atomics (order-independent, so bit-identical for any thread count), then resolved. A
// fresh voxelization accumulates into the blocks of 8^3 voxels the surface reaches (BlockSums) and
// resolves those blocks alone: every other voxel resolves to the zeros its buffers start with. The
// dense sums are outputs only where the plan keeps them (Effect::voxel_sums), filled from the
// blocks. In a sequence where a few meshes moved, the frame before's dense sums are updated in
// part instead ([Villegas 2017, §1.2] revoxelizes its dynamic objects alone): the moved meshes'
// contributions of that frame are subtracted, this frame's added, and only the blocks of 8^3
// voxels either touched are resolved again. Integer sums make the update exact, so the buffers are
// the ones voxelizing every triangle gives.
#include <algorithm>
#include <atomic>
#include <bit>
#include <optional>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>

#include "common/error.h"
#include "common/memory.h"
#include "common/parallel.h"
#include "common/voxel_overflow.h"
#include "common/voxelize_update.h"
#include "common/voxel_walk.h"
#include "cpu/stages.h"

namespace voxgi::cpu {
namespace {

using shared::VoxelContribution;
using shared::VoxelTriangle;

// A voxel's sums on adjacent words: weight, albedo (3), normal (3), then with emission its rgb and
// the emitters' weight.
constexpr int kSumWords = 7, kEmissiveSumWords = 11;

// Adds (or, subtracting, takes out) one contribution into a voxel's sums, wherever they lie:
// `word(i)` is the voxel's i-th sum word. Returns the weight sum before the addition.
template <class Word>
uint32_t addContribution(const shared::VoxelContribution& c, bool emissive, bool subtract,
                         Word&& word) {
  const auto add = [&](int i, uint32_t v) {
    // Adding (0 - v) modulo 2^32 takes v out exactly.
    return std::atomic_ref<uint32_t>(word(i)).fetch_add(subtract ? 0u - v : v,
                                                        std::memory_order_relaxed);
  };
  const uint32_t old = add(0, c.weight);
  for (int i = 0; i < 3; ++i) {
    add(1 + i, c.albedo[i]);
    add(4 + i, static_cast<uint32_t>(c.normal[i]));
    if (emissive) add(7 + i, c.emission[i]);
  }
  if (emissive) add(10, c.emitterWeight);
  return old;
}

// Set by the first contribution that takes a voxel past kMaxWeightSum: the sums of that voxel are
// lost, the stage fails, so the remaining triangles are skipped.
struct Overflow {
  std::atomic<bool> flag{false};
  // Adds alone raise a sum, so the check fires exactly when the final sum passes the bound.
  void check(uint32_t old, uint32_t weight) {
    if (uint64_t(old) + weight > shared::kMaxWeightSum) flag.store(true, std::memory_order_relaxed);
  }
};

// A fresh voxelization's sums, held only in the blocks of 8^3 voxels the surface reaches (a small
// mesh's surface touches few of a grid's blocks), a voxel's sums on adjacent words: the dense sums
// cost clearing and writing 28-44 bytes a voxel of the whole grid, where the blocks' cost what the
// surface covers. A first walk marks the blocks, which take their places in index order; the
// second adds the contributions.
struct BlockSums {
  static constexpr int kShift = 3, kVoxels = 1 << (3 * kShift);
  int side, words;
  std::vector<uint32_t> place;  // per block of the grid: 1 + its index in `low`, or 0
  std::vector<glm::ivec3> low;  // the marked blocks' lowest voxels, in index order, once listed
  Words sums;

  BlockSums(int n, bool emissive)
      : side(((n - 1) >> kShift) + 1),
        words(emissive ? kEmissiveSumWords : kSumWords),
        place(size_t(side) * size_t(side) * size_t(side), 0) {}
  size_t blockIndex(const glm::ivec3& voxel) const {
    const glm::ivec3 b = voxel >> kShift;
    return size_t(b.x) + size_t(side) * (size_t(b.y) + size_t(side) * size_t(b.z));
  }
  void mark(size_t block) {
    // A racing store of the same 1 is harmless; the atomic keeps ThreadSanitizer informed.
    std::atomic_ref<uint32_t>(place[block]).store(1, std::memory_order_relaxed);
  }
  bool marked(const glm::ivec3& voxel) const { return place[blockIndex(voxel)] != 0; }
  // The marked blocks' lowest voxels, in index order.
  std::vector<glm::ivec3> markedList() const {
    std::vector<glm::ivec3> out;
    for (int z = 0; z < side; ++z)
      for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x)
          if (marked(glm::ivec3(x, y, z) << kShift)) out.push_back(glm::ivec3(x, y, z) << kShift);
    return out;
  }
  // Gives the marked blocks their places; refuses, before allocating, sums that memory cannot hold.
  void allocate(const StageContext& ctx) {
    low = markedList();
    for (size_t b = 0; b < low.size(); ++b) place[blockIndex(low[b])] = uint32_t(b + 1);
    const uint64_t count = uint64_t(low.size()) * kVoxels * uint64_t(words);
    requireMemory(count * sizeof(uint32_t),
                  "the voxelize sums of " + std::to_string(low.size()) + " blocks of 8^3 voxels",
                  ctx.scene.file, "grid.resolution");
    sums.resize(count);
  }
  // The first sum word of a voxel in a marked block.
  uint32_t* at(const glm::ivec3& voxel) {
    const size_t local = size_t(voxel.x & 7) | size_t(voxel.y & 7) << 3 | size_t(voxel.z & 7) << 6;
    return &sums[((place[blockIndex(voxel)] - 1) * size_t(kVoxels) + local) * size_t(words)];
  }
};

// Adds contributions into the dense sums (the frame before's, updated in part), marking the
// blocks they reach.
struct DenseAccumulator {
  const GridSpec& grid;
  Buffer& weight;
  Buffer& albedo;
  Buffer& normal;
  Buffer* emission;  // null when the scene emits nothing
  BlockSums& touched;
  Overflow& overflow;
  bool subtract = false;

  void operator()(const glm::ivec3& voxel, const VoxelContribution& c) {
    const size_t e = grid.index(voxel);
    touched.mark(touched.blockIndex(voxel));
    const uint32_t old = addContribution(c, emission != nullptr, subtract, [&](int i) -> uint32_t& {
      if (i == 0) return weight.words[e];
      if (i < 4) return albedo.words[3 * e + size_t(i - 1)];
      if (i < 7) return normal.words[3 * e + size_t(i - 4)];
      return emission->words[4 * e + size_t(i - 7)];
    });
    if (!subtract) overflow.check(old, c.weight);
  }
};

// Whether a voxel that no contribution reached resolves to +0 in every output (all of its sums 0),
// the bits a fresh buffer holds: so for a scale that is not negative or NaN.
bool resolvesToZero(bool antialiased, bool emissive, float emissionScale) {
  const auto zero = [](float x) { return std::bit_cast<uint32_t>(x) == 0u; };
  const glm::vec3 blank = shared::resolveAverage(glm::uvec3(0u), 0u);
  const glm::vec3 normal = shared::resolveNormal(glm::ivec3(0), 0u);
  const glm::vec3 emission = shared::resolveEmission(glm::uvec3(0u), 0u, emissionScale);
  bool all = zero(shared::resolveOpacity(0u, antialiased));
  for (int c = 0; c < 3; ++c)
    all = all && zero(blank[c]) && zero(normal[c]) && (!emissive || zero(emission[c]));
  return all;
}

// The sums and resolved volumes of the stage, allocated or taken from the frame before.
struct VoxelBuffers {
  Buffer weight, albedoSum, normalSum, emissionSum, opacity, albedo, normal, emission;
};

// One run of the stage, in its steps: the buffers (taken from the frame before for an update in
// part, else fresh), the contributions accumulated (into the frame before's dense sums, or into
// the blocks the surface reaches), the overflow check, and each voxel resolved from its sums.
class Voxelization {
 public:
  explicit Voxelization(const StageContext& ctx)
      : ctx_(ctx),
        grid_(ctx.scene.grid),
        n_(grid_.resolution),
        antialiased_(ctx.settings.voxelizeMode == VoxelizeMode::antialiased),
        emissive_(ctx.plan.on(Effect::emission)),  // emissionScale may be 0 under plan.mode=full
        emitterMean_(ctx.settings.voxelizeEmission == VoxelizeEmission::emitters),
        // The dense sums are outputs only where the plan keeps them (voxel_sums): compared,
        // written, read by a later stage or updated in part in the next frame. Otherwise the sums
        // live in BlockSums.
        keepSums_(ctx.plan.on(Effect::voxel_sums)),
        // The update starts from the frame before's dense sums, which the stash holds only when
        // the plan kept them.
        moved_(movedTriangles(ctx, emissive_)),
        blocks_(n_, emissive_),
        textures_{ctx.scene.textures} {}

  void run(BufferSet& buffers) {
    v_ = moved_ ? previousBuffers() : freshBuffers();
    if (moved_)
      accumulateUpdate();
    else
      accumulateFresh();
    if (overflow_.flag)
      throw InputError(ctx_.scene.file, "meshes",
                       "more than 32768 voxel faces of surface fall into one voxel (fixed-point "
                       "overflow); lower grid.resolution or remove overlapping copies");
    resolveVolumes();
    for (Buffer* b : {&v_.weight, &v_.albedoSum, &v_.normalSum, &v_.emissionSum, &v_.opacity,
                      &v_.albedo, &v_.normal, &v_.emission})
      if (b->spec != nullptr) buffers.put(std::move(*b));
  }

 private:
  VoxelBuffers previousBuffers() const {
    BufferSet& stash = ctx_.previous->stash;
    return {stash.take(BufferId::common_voxelize_weight_sum),
            stash.take(BufferId::common_voxelize_albedo_sum),
            stash.take(BufferId::common_voxelize_normal_sum),
            stash.take(BufferId::common_voxelize_emission_sum),
            stash.take(BufferId::common_voxelize_opacity),
            stash.take(BufferId::common_voxelize_albedo),
            stash.take(BufferId::common_voxelize_normal),
            stash.take(BufferId::common_voxelize_emission)};
  }

  VoxelBuffers freshBuffers() const {
    const auto fresh = [&](BufferId id, bool needed) {
      return needed ? Buffer(id, glm::ivec3(n_)) : Buffer();
    };
    return {fresh(BufferId::common_voxelize_weight_sum, keepSums_),
            fresh(BufferId::common_voxelize_albedo_sum, keepSums_),
            fresh(BufferId::common_voxelize_normal_sum, keepSums_),
            fresh(BufferId::common_voxelize_emission_sum, keepSums_ && emissive_),
            fresh(BufferId::common_voxelize_opacity, true),
            fresh(BufferId::common_voxelize_albedo, true),
            fresh(BufferId::common_voxelize_normal, true),
            fresh(BufferId::common_voxelize_emission, emissive_)};
  }

  // The walks of triangles [first, end) of `tris`, each contribution handed to `sink`.
  template <class Sink>
  void walk(const std::vector<VoxelTriangle>& tris, size_t first, size_t end, Sink& sink) {
    parallelFor(tbb::blocked_range<size_t>(first, end, 64), [&](const auto& range) {
      for (size_t i = range.begin(); i != range.end(); ++i) {
        // A million copies of one triangle fail after the first few thousand, not after all.
        if (overflow_.flag.load(std::memory_order_relaxed)) return;
        if (antialiased_)
          antialiasedWalk(tris[i], n_, textures_, sink);
        else
          conservativeWalk(tris[i], n_, textures_, sink);
      }
    });
  }

  // The moved meshes' contributions of the frame before out of its dense sums, this frame's in.
  void accumulateUpdate() {
    DenseAccumulator acc{
        grid_,   v_.weight, v_.albedoSum, v_.normalSum, emissive_ ? &v_.emissionSum : nullptr,
        blocks_, overflow_};
    // Every subtraction before any addition, so that a running sum passes the bound only when
    // the final one does.
    acc.subtract = true;
    for (const auto& [first, end] : moved_->before)
      walk(ctx_.previous->triangles->triangles, first, end, acc);
    acc.subtract = false;
    for (const auto& [first, end] : moved_->now) walk(ctx_.triangles.triangles, first, end, acc);
    blocks_.low = blocks_.markedList();  // resolved again; the sums stay dense
  }

  // Every triangle's contributions into the blocks of 8^3 voxels its candidates reach.
  void accumulateFresh() {
    const std::vector<VoxelTriangle>& tris = ctx_.triangles.triangles;
    // The blocks of the walks' candidate voxels, a superset of those contributions reach (a block
    // marked in vain resolves to the zeros it holds) at a fraction of the contributions' cost: each
    // block is marked once per run of a triangle's candidates in it.
    parallelFor(tbb::blocked_range<size_t>(0, tris.size(), 64), [&](const auto& range) {
      for (size_t i = range.begin(); i != range.end(); ++i) {
        size_t last = SIZE_MAX;
        const auto mark = [&](const glm::ivec3& voxel) {
          const size_t b = blocks_.blockIndex(voxel);
          if (b != last) blocks_.mark(b);
          last = b;
        };
        if (antialiased_)
          antialiasedCandidates(tris[i], n_, mark);
        else
          conservativeCandidates(tris[i], n_, mark);
      }
    });
    blocks_.allocate(ctx_);
    auto add = [&](const glm::ivec3& voxel, const VoxelContribution& c) {
      uint32_t* sums = blocks_.at(voxel);
      overflow_.check(
          addContribution(c, emissive_, false, [sums](int i) -> uint32_t& { return sums[i]; }),
          c.weight);
    };
    walk(tris, 0, tris.size(), add);
  }

  // Voxel e's outputs from its sums (kSumWords or kEmissiveSumWords words, BlockSums' order).
  void resolve(size_t e, const uint32_t* s) {
    const uint32_t w = s[0];
    v_.opacity.set(e, 0, shared::resolveOpacity(w, antialiased_));
    const glm::vec3 a = shared::resolveAverage(glm::uvec3(s[1], s[2], s[3]), w);
    const glm::vec3 nm = shared::resolveNormal(glm::ivec3(glm::uvec3(s[4], s[5], s[6])), w);
    for (int c = 0; c < 3; ++c) {
      v_.albedo.set(e, c, a[c]);
      v_.normal.set(e, c, nm[c]);
    }
    if (emissive_) {
      const glm::vec3 em = shared::resolveEmission(
          glm::uvec3(s[7], s[8], s[9]), emitterMean_ ? s[10] : w, ctx_.triangles.emissionScale);
      for (int c = 0; c < 3; ++c) v_.emission.set(e, c, em[c]);
    }
  }

  // The dense sums of voxel e, gathered into BlockSums' order or scattered from it.
  template <class Visit>
  void denseSums(size_t e, Visit&& visit) {
    visit(v_.weight.words[e], 0);
    for (int c = 0; c < 3; ++c) {
      visit(v_.albedoSum.words[3 * e + size_t(c)], 1 + c);
      visit(v_.normalSum.words[3 * e + size_t(c)], 4 + c);
    }
    if (emissive_)
      for (int c = 0; c < 4; ++c) visit(v_.emissionSum.words[4 * e + size_t(c)], 7 + c);
  }

  // `blank`: a voxel without sums resolves to the +0 that fresh buffers hold.
  void resolveVoxel(const glm::ivec3& voxel, bool blank) {
    const size_t e = grid_.index(voxel);
    if (moved_) {
      uint32_t s[kEmissiveSumWords] = {};
      denseSums(e, [&](uint32_t word, int i) { s[i] = word; });
      return resolve(e, s);
    }
    static constexpr uint32_t kZero[kEmissiveSumWords] = {};
    const uint32_t* s = blocks_.marked(voxel) ? blocks_.at(voxel) : kZero;
    // Most voxels of a block the surface reaches are empty, and hold what they resolve to.
    if (blank && std::all_of(s, s + blocks_.words, [](uint32_t w) { return w == 0u; })) return;
    resolve(e, s);
    if (keepSums_) denseSums(e, [&](uint32_t& word, int i) { word = s[i]; });
  }

  // Only the blocks contributions reached are resolved where every other voxel already holds its
  // value: the frame before's outputs (a voxel resolves from its sums alone, and the update leaves
  // the others' sums as they were), or fresh buffers' +0 where that is what a voxel without
  // contributions resolves to (resolvesToZero). Each block by one task, its voxels in index order.
  void resolveVolumes() {
    const bool blank = resolvesToZero(antialiased_, emissive_, ctx_.triangles.emissionScale);
    const int n = n_;
    if (moved_ || blank) {
      const std::vector<glm::ivec3>& low = blocks_.low;
      const int side = 1 << BlockSums::kShift;
      parallelFor(tbb::blocked_range<size_t>(0, low.size(), 8), [&](const auto& range) {
        for (size_t b = range.begin(); b != range.end(); ++b) {
          const glm::ivec3 high = glm::min(low[b] + side, glm::ivec3(n));
          for (int z = low[b].z; z < high.z; ++z)
            for (int y = low[b].y; y < high.y; ++y)
              for (int x = low[b].x; x < high.x; ++x) resolveVoxel({x, y, z}, blank);
        }
      });
      return;
    }
    parallelFor(tbb::blocked_range<size_t>(0, size_t(n) * size_t(n) * size_t(n), 4096),
                [&](const auto& range) {
                  for (size_t e = range.begin(); e != range.end(); ++e)
                    resolveVoxel(glm::ivec3(int(e % size_t(n)), int(e / size_t(n) % size_t(n)),
                                            int(e / (size_t(n) * size_t(n)))),
                                 blank);
                });
  }

  const StageContext& ctx_;
  const GridSpec& grid_;
  const int n_;
  const bool antialiased_, emissive_, emitterMean_, keepSums_;
  const std::optional<MovedTriangles> moved_;
  BlockSums blocks_;
  Overflow overflow_;
  const TextureAccess textures_;
  VoxelBuffers v_;
};

}  // namespace

void common::voxelize(const StageContext& ctx, BufferSet& buffers) {
  checkStageMemory(ctx, StageId::common_voxelize);
  refuseRepeatedTriangles(ctx.triangles, ctx.scene.grid.resolution,
                          ctx.settings.voxelizeMode == VoxelizeMode::antialiased, ctx.scene.file);
  Voxelization(ctx).run(buffers);
}

}  // namespace voxgi::cpu
