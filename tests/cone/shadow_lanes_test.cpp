// The visibility rays in lanes (cpu/cone/shadow_lanes.h) compute exactly what the shared
// voxelVisibility computes: bit for bit, on every instruction set this CPU runs, for hard and soft
// shadows, on random rays through a random opacity volume whose side is not a power of two (rays
// that start outside it, leave it, stop at their length or at the step limit, and voxels the map
// marks that turn out clear).
#include <bit>
#include <random>

#include <gtest/gtest.h>

#include "cpu/cone/voxel_light_lanes.h"
#include "shaders/shared/morton.h"

namespace voxgi::test {
namespace {

constexpr int kN = 24;
constexpr int kKeySide = 32;  // the power of two the Morton keys span

// The kernel's opacity volume, and its map for the lanes.
struct Opacity {
  std::vector<float> a;
  std::vector<uint32_t> map;
  shared::LightVoxelsParams params{};

  float opacityAt(glm::ivec3 v) const { return a[size_t(v.x + kN * (v.y + kN * v.z))]; }
};

// A quarter of the voxels opaque to some degree, walls of full opacity among them; some clear
// voxels marked in the map as well (the map may over-mark, never under-mark).
Opacity randomOpacity(uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  Opacity o;
  o.a.assign(size_t(kN) * kN * kN, 0.0f);
  o.map.assign(size_t(kKeySide) * kKeySide * kKeySide / 32, 0u);
  for (int z = 0; z < kN; ++z)
    for (int y = 0; y < kN; ++y)
      for (int x = 0; x < kN; ++x) {
        const float u = unit(rng);
        float& a = o.a[size_t(x + kN * (y + kN * z))];
        a = u < 0.2f ? unit(rng) : u < 0.25f ? 1.0f : 0.0f;
        if (a > 0.0f || u > 0.95f) {
          const uint32_t key = shared::mortonEncode(glm::uvec3(x, y, z));
          o.map[key >> 5] |= 1u << (key & 31u);
        }
      }
  return o;
}

TEST(ShadowLanes, BitIdenticalToTheSharedMarch) {
  Opacity o = randomOpacity(7);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  // Points in the grid and a little outside it, any direction, lengths from none to past the grid
  // (the step limit ends those).
  struct Ray {
    glm::vec3 p, n, toLight;
    float distance;
  };
  std::vector<Ray> rays;
  for (int i = 0; i < 3000; ++i) {
    const auto direction = [&] {
      glm::vec3 d;
      do d = glm::vec3(unit(rng), unit(rng), unit(rng)) * 2.0f - 1.0f;
      while (glm::dot(d, d) > 1.0f || glm::dot(d, d) < 1e-4f);
      return glm::normalize(d);
    };
    const glm::vec3 p = glm::vec3(unit(rng), unit(rng), unit(rng)) * float(kN + 4) - 2.0f;
    const glm::vec3 toLight = i % 9 == 0 ? glm::vec3(0.0f, 0.0f, 1.0f) : direction();
    const float distance = i % 5 == 0 ? 1e30f : unit(rng) * 2.5f * float(kN);
    rays.push_back({p, i % 7 == 0 ? glm::vec3(0.0f) : direction(), toLight, distance});
  }
  size_t blocked = 0, partial = 0, open = 0;
  for (const int mode : {shared::kVoxelShadowHard, shared::kVoxelShadowSoft}) {
    o.params.resolution = kN;
    o.params.voxelShadow = mode;
    o.params.shadowKappa = 0.7f;
    o.params.shadowOffset = 1.5f;
    std::vector<cpu::ShadowRay> lanes;
    std::vector<float> expected;
    for (const Ray& r : rays) {
      lanes.push_back({shared::shadowRayOrigin(r.p, r.n, o.params), r.toLight,
                       r.distance - o.params.shadowOffset});
      expected.push_back(shared::voxelVisibility(o, r.p, r.n, r.toLight, r.distance, o.params));
      blocked += expected.back() == 0.0f;
      open += expected.back() == 1.0f;
      partial += expected.back() > 0.0f && expected.back() < 1.0f;
    }
    // The stages' view of their volumes (voxel_light_lanes.h).
    const cpu::ShadowRays<Opacity> view{&o, &o.params};
    const cpu::ShadowVolume volume = view.volume(o.map.data());
    for (const cpu::SimdLevel level : cpu::runnableSimdLevels())
      for (const size_t count : {size_t(0), size_t(1), size_t(5), lanes.size()}) {
        std::vector<float> visibility(count, -1.0f);
        cpu::marchShadowRays(level, volume, std::span(lanes).first(count), visibility);
        for (size_t i = 0; i < count; ++i)
          ASSERT_EQ(std::bit_cast<uint32_t>(visibility[i]), std::bit_cast<uint32_t>(expected[i]))
              << cpu::simdLevelName(level) << " mode " << mode << " ray " << i << ": "
              << visibility[i] << " vs " << expected[i];
      }
  }
  // The rays cover every outcome.
  EXPECT_GT(blocked, rays.size() / 10);
  EXPECT_GT(partial, rays.size() / 10);
  EXPECT_GT(open, rays.size() / 10);
}

}  // namespace
}  // namespace voxgi::test
