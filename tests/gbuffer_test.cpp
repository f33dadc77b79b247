// The CPU gbuffer against a hand-computed camera ray: a wall facing the camera, seen from its back
// too, a second object in front, and the background.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace voxgi::test
