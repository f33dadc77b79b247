// The CPU gbuffer against a hand-computed camera ray: a wall facing the camera, seen from its back
// too, a second object in front, and the background; textured albedo at each pixel's hit.
#include <algorithm>

#include <gtest/gtest.h>

#include "common/camera_geometry.h"
#include "common/texture.h"

#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

Scene wallScene() {
  // A wall at z = 0.25 across the whole unit grid; a small box face at z = 0.5 in front of it.
  Material white;
  white.albedo = glm::vec3(0.7f);
  Scene scene = makeScene(quad(2, 0.25, {-1.0, -1.0}, {2.0, 2.0}), unitGrid(32), white);
  Material red;
  red.albedo = glm::vec3(0.9f, 0.1f, 0.1f);
  red.specular = glm::vec3(0.5f);
  red.shininess = 20.0f;
  scene.materials.push_back(red);
  Mesh front;
  front.name = "front";
  front.material = 1;
  for (const auto& t : quad(2, 0.5, {0.45, 0.45}, {0.55, 0.55})) {
    const auto base = static_cast<unsigned>(front.positions.size());
    front.positions.insert(front.positions.end(), t.begin(), t.end());
    front.triangles.emplace_back(base, base + 1, base + 2);
  }
  scene.meshes.push_back(front);
  scene.camera.position = {0.5, 0.5, 2.0};
  scene.camera.lookAt = {0.5, 0.5, 0.0};
  scene.camera.fovYDeg = 60.0;
  scene.camera.width = scene.camera.height = 64;
  scene.lights.push_back(testLight());  // unlit, its plan would run no gbuffer (EffectPlan::dark)
  return scene;
}

glm::vec4 pixel(const Buffer& b, int x, int y) {
  const size_t e = size_t(y) * size_t(b.extent.x) + size_t(x);
  glm::vec4 r(0.0f);
  for (int c = 0; c < b.components(); ++c) r[c] = b.get<float>(e, c);
  return r;
}

TEST(Gbuffer, PixelsSeeTheNearestSurfaceWithAFacingNormal) {
  const Scene scene = wallScene();
  const BufferSet b = runCpuUntil(scene, Settings{}, "gbuffer");
  const Buffer& id = b.at(BufferId::common_gbuffer_object_id);
  // The centre pixel (32, 32) sees the front face; its ray passes just right of and below the
  // image centre by half a pixel.
  EXPECT_EQ(id.words[32 * 64 + 32], 2u);
  const glm::vec4 p = pixel(b.at(BufferId::common_gbuffer_pixel_position), 32, 32);
  EXPECT_NEAR(p.z, 0.5 * 32, 1e-4);  // voxel units: z = 0.5 of a 32-voxel unit grid
  const double halfPixel = std::tan(3.14159265358979 / 6.0) / 64.0 * 1.5 * 32.0;  // at depth 1.5
  EXPECT_NEAR(p.x, 16.0 + halfPixel, 1e-3);
  EXPECT_NEAR(p.y, 16.0 - halfPixel, 1e-3);
  EXPECT_EQ(pixel(b.at(BufferId::common_gbuffer_pixel_normal), 32, 32),
            glm::vec4(0, 0, 1, 0));  // toward the camera
  EXPECT_EQ(pixel(b.at(BufferId::common_gbuffer_pixel_specular), 32, 32),
            glm::vec4(0.5f, 0.5f, 0.5f, 20.0f));
  // A corner pixel sees the wall: white, facing the camera whatever the quad's winding.
  EXPECT_EQ(id.words[2 * 64 + 2], 1u);
  EXPECT_EQ(pixel(b.at(BufferId::common_gbuffer_pixel_normal), 2, 2), glm::vec4(0, 0, 1, 0));
  EXPECT_EQ(pixel(b.at(BufferId::common_gbuffer_pixel_albedo), 2, 2),
            glm::vec4(0.7f, 0.7f, 0.7f, 0.0f));
  EXPECT_FALSE(b.contains(BufferId::common_gbuffer_pixel_emission));  // nothing emits
}

TEST(Gbuffer, BackgroundPixelsAreZero) {
  Scene scene = wallScene();
  scene.camera.lookAt = {0.5, 0.5, 3.0};  // looking away from everything
  const BufferSet b = runCpuUntil(scene, Settings{}, "gbuffer");
  for (uint32_t w : b.at(BufferId::common_gbuffer_object_id).words) ASSERT_EQ(w, 0u);
  for (uint32_t w : b.at(BufferId::common_gbuffer_pixel_position).words) ASSERT_EQ(w, 0u);
}

// The plane y = 0 of the unit grid (8 voxels), texture coordinates (x, z), seen from (0.5, 1, 0.5)
// straight down through 16 x 16 pixels, with a white material textured by `image`.
Scene texturedFloor(const DecodedImage& image, uint32_t wrap) {
  Scene scene = makeScene(quad(1, 0.0, {0.0, 0.0}, {1.0, 1.0}), unitGrid(8));
  Mesh& mesh = scene.meshes[0];
  for (const glm::dvec3& p : mesh.positions) mesh.texcoords.emplace_back(p.x, p.z);
  scene.materials[0].albedo = glm::vec3(1.0f);
  scene.materials[0].albedoTexture =
      scene.textures.texture("floor", wrap, wrap, [&] { return image; });
  scene.lights.push_back(testLight());
  return withCamera(scene, {0.5, 1.0, 0.5}, {0.5, 0.0, 0.5}, {0.0, 0.0, 1.0}, 40.0, 16);
}

// A 2 x 2 texture whose red rises with u and green with v, clamped: bilinear filtering at the
// pixel's hit is red(u) = a + (b - a) clamp(2u - 1/2, 0, 1), a and b the two codes' values, and
// the same for green. The footprint (0.36 voxel at 8 voxels' depth, 0.09 texel) magnifies.
TEST(Gbuffer, TexturedAlbedoIsTheTextureAtEachPixelsHit) {
  const uint32_t lo = srgbEncode(0.25f), hi = srgbEncode(0.75f);
  const float a = srgbDecodeTable()[lo], b = srgbDecodeTable()[hi];
  DecodedImage image{2, 2, {}};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x)
      for (uint32_t code : {x ? hi : lo, y ? hi : lo, 255u}) image.rgb.push_back(uint8_t(code));
  const Scene scene = texturedFloor(image, shared::kWrapClamp);
  const BufferSet buffers = runCpuUntil(scene, Settings{}, "gbuffer");
  const Buffer& albedo = buffers.at(BufferId::common_gbuffer_pixel_albedo);
  const CameraRays cam = cameraRays(scene);
  const auto ramp = [&](double t) { return a + (b - a) * std::clamp(2.0 * t - 0.5, 0.0, 1.0); };
  for (int y = 0; y < cam.height; ++y)
    for (int x = 0; x < cam.width; ++x) {
      // The pixel centre's ray to the plane, in world units.
      const glm::dvec3 d(cam.pixelDirection(x, y));
      const glm::dvec3 hit = (glm::dvec3(cam.origin) - d * (double(cam.origin.y) / d.y)) / 8.0;
      const glm::vec4 p = pixel(albedo, x, y);
      ASSERT_NEAR(p.x, ramp(hit.x), 1e-5) << x << "," << y;
      ASSERT_NEAR(p.y, ramp(hit.z), 1e-5) << x << "," << y;
      ASSERT_EQ(p.z, 1.0f);
    }
}

// A checker of single texels, 64 x 64, seen from the same camera: a pixel covers 2.9 texels, so
// every pixel reads mip levels whose texels all hold the checker's linear mean 1/2 as its nearest
// sRGB code (0.50289), not a texel of the pattern.
TEST(Gbuffer, ATextureFinerThanAPixelIsReadAtItsMean) {
  DecodedImage image{64, 64, {}};
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      for (int c = 0; c < 3; ++c) image.rgb.push_back((x + y) % 2 ? 255 : 0);
  const Scene scene = texturedFloor(image, shared::kWrapRepeat);
  const BufferSet buffers = runCpuUntil(scene, Settings{}, "gbuffer");
  const Buffer& albedo = buffers.at(BufferId::common_gbuffer_pixel_albedo);
  const float mean = srgbDecodeTable()[srgbEncode(0.5f)];
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) ASSERT_EQ(pixel(albedo, x, y).x, mean) << x << "," << y;
  EXPECT_NEAR(mean, 0.5, 3e-3);
}

}  // namespace
}  // namespace voxgi::test
