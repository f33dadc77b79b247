// CPU voxelize of textured triangles (docs/textures.md): a white texture leaves the sums of the
// untextured material unchanged bit for bit, and a voxel's albedo is the texture's mean over the
// part of the triangle inside it, against the area mean computed here.
#include <gtest/gtest.h>

#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

constexpr VoxelizeMode kModes[] = {VoxelizeMode::conservative, VoxelizeMode::antialiased};

// The plane y = 0.53 across the unit grid of 16 voxels (in voxel layer 8), texture coordinates
// (x, z), with material `m`.
Scene texturedPlane(const Material& m) {
  Scene scene = makeScene(quad(1, 0.53, {0.0, 0.0}, {1.0, 1.0}), unitGrid(16), m);
  Mesh& mesh = scene.meshes[0];
  for (const glm::dvec3& p : mesh.positions) mesh.texcoords.emplace_back(p.x, p.z);
  return scene;
}

// A `size` x `size` texture of `cell`-texel squares, black and white.
DecodedImage checker(int size, int cell) {
  DecodedImage image{size, size, {}};
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const uint8_t v = (x / cell + y / cell) % 2 ? 255 : 0;
      for (int c = 0; c < 3; ++c) image.rgb.push_back(v);
    }
  return image;
}

TEST(VoxelizeTexture, AWhiteTextureLeavesTheSumsOfItsMaterialBitForBit) {
  Material m;
  m.albedo = {0.3f, 0.55f, 0.8f};
  m.emission = {2.0f, 1.0f, 0.5f};
  const Scene plain = texturedPlane(m);
  Scene white = plain;
  DecodedImage image{4, 4, std::vector<uint8_t>(48, 255)};
  const uint32_t t = white.textures.texture("white", shared::kWrapRepeat, shared::kWrapRepeat,
                                            [&] { return image; });
  white.materials[0].albedoTexture = white.materials[0].emissionTexture = t;
  for (VoxelizeMode mode : kModes) {
    const BufferSet a = runCpu(plain, mode), b = runCpu(white, mode);
    for (BufferId id : {BufferId::common_voxelize_weight_sum, BufferId::common_voxelize_albedo_sum,
                        BufferId::common_voxelize_emission_sum, BufferId::common_voxelize_albedo})
      EXPECT_EQ(a.at(id).words, b.at(id).words) << voxelizeModeName(mode);
  }
}

// A voxel's albedo against the checker's mean over the voxel's square of the plane. One texel per
// voxel (cells of 2): each voxel is black or white exactly, sampled at its square's centre
// (conservative mode; the antialiased tent blends neighbouring voxels by design). Not on the
// quad's diagonal, where each of the two triangles' halves is sampled at its own centre, 1/6 voxel
// off the square's, and bilinear filtering at one texel per voxel blends in 1/6 of a neighbour. A
// checker finer than a voxel (16 x 16 texels of 4-texel cells per voxel: mean 1/2): the mip level
// the voxel's footprint picks holds the mean as the nearest 8-bit sRGB code, 0.50289 — within
// 0.003, half a code step there, of 1/2, in both modes.
TEST(VoxelizeTexture, AVoxelsAlbedoIsTheTexturesMeanOverItsPart) {
  struct Case {
    int size, cell;
    VoxelizeMode mode;
    double tolerance;
  };
  for (const Case c : {Case{16, 2, VoxelizeMode::conservative, 1e-6},
                       Case{256, 4, VoxelizeMode::conservative, 3e-3},
                       Case{256, 4, VoxelizeMode::antialiased, 3e-3}}) {
    const VoxelizeMode mode = c.mode;
    Material m;
    m.albedo = glm::vec3(1.0f);
    Scene scene = texturedPlane(m);
    const DecodedImage image = checker(c.size, c.cell);
    scene.materials[0].albedoTexture = scene.textures.texture(
        "checker", shared::kWrapRepeat, shared::kWrapRepeat, [&] { return image; });
    const BufferSet b = runCpu(scene, mode);
    const Buffer& albedo = b.at(BufferId::common_voxelize_albedo);
    // Voxels away from the plane's edges (the antialiased tent reaches one voxel further).
    for (int k = 2; k < 14; ++k)
      for (int i = 2; i < 14; ++i) {
        if (c.size == 16 && i == k) continue;
        // The texels of voxel (i, k) are [i, i + 1) * size / 16 in u and the same in v.
        const int per = c.size / 16;
        double sum = 0.0;
        for (int y = k * per; y < (k + 1) * per; ++y)
          for (int x = i * per; x < (i + 1) * per; ++x) sum += (x / c.cell + y / c.cell) % 2;
        const double mean = sum / (per * per);
        const float got = albedo.get<float>(scene.grid.index({i, 8, k}), 0);
        ASSERT_NEAR(got, mean, c.tolerance)
            << voxelizeModeName(mode) << " " << c.size << " voxel " << i << "," << k;
      }
  }
}

}  // namespace
}  // namespace voxgi::test
