// glTF animations (common/scene_io/gltf_animation.h) against values computed by hand from the glTF
// 2.0 specification (§3.11 and Appendix C): a node hierarchy with step, linear (slerp) and
// cubic-spline channels moving a mesh, a spot light and a camera, the scene file's transform on
// top, and malformed channels refused naming the file and field.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.h"
#include "common/scene_io/scene_load.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

// The binary buffer: key times 0, 1, 2 (accessor 0); translations (0,0,0), (0,2,0), (0,4,0) (1);
// rotations identity, 90 and 180 degrees about +y, glTF's x, y, z, w (2); key times 0, 2 (3); a
// cubic spline of scale from 1 to 3 with out-tangent 1 at the first key (4); one triangle (5).
std::vector<float> animationBuffer() {
  const float h = float(std::sqrt(0.5));
  return {0, 1, 2,                                               //
          0, 0, 0, 0, 2, 0, 0, 4, 0,                             //
          0, 0, 0, 1, 0, h, 0, h, 0, 1, 0, 0,                    //
          0, 2,                                                  //
          0, 0, 0, 1, 1, 1, 1, 1, 1, 0, 0, 0, 3, 3, 3, 0, 0, 0,  //
          0, 0, 0, 1, 0, 0, 0, 1, 0};
}

// Node 0 turns (linear) and steps up (step) carrying node 1, which sits at x = 1 and grows
// (cubic spline) and holds the triangle; node 2 is a camera rising linearly; node 3 a spot light
// at y = 3 turning with node 0's rotation. `channels` replaces the animation's channels.
std::string animatedGltf(const std::string& channels = "", const std::string& node0 = "") {
  const std::vector<float> data = animationBuffer();
  const std::string bin = testTempDir() + "animated.bin";
  std::ofstream(bin, std::ios::binary)
      .write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size() * 4));
  const std::string defaultChannels = R"(
      {"sampler":0,"target":{"node":0,"path":"translation"}},
      {"sampler":1,"target":{"node":0,"path":"rotation"}},
      {"sampler":2,"target":{"node":1,"path":"scale"}},
      {"sampler":3,"target":{"node":2,"path":"translation"}},
      {"sampler":1,"target":{"node":3,"path":"rotation"}},
      {"sampler":0,"target":{"node":1,"path":"weights"}})";
  return writeTemp("animated.gltf", R"({"asset":{"version":"2.0"},"scene":0,
  "scenes":[{"nodes":[0,2,3]}],
  "nodes":[{"name":"turner","children":[1])" +
                                        node0 + R"(},
           {"name":"grower","translation":[1,0,0],"mesh":0},
           {"name":"cam","camera":0},
           {"name":"lamp","translation":[0,3,0],"extensions":{"KHR_lights_punctual":{"light":0}}}],
  "cameras":[{"type":"perspective","perspective":{"yfov":0.8,"znear":0.1}}],
  "extensions":{"KHR_lights_punctual":{"lights":[{"type":"spot","intensity":683,"spot":{}}]}},
  "meshes":[{"primitives":[{"attributes":{"POSITION":5}}]}],
  "animations":[{"name":"move","channels":[)" +
                                        (channels.empty() ? defaultChannels : channels) + R"(],
    "samplers":[{"input":0,"output":1,"interpolation":"STEP"},
                {"input":0,"output":2},
                {"input":3,"output":4,"interpolation":"CUBICSPLINE"},
                {"input":0,"output":1,"interpolation":"LINEAR"}]}],
  "buffers":[{"byteLength":212,"uri":"animated.bin"}],
  "bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":12},
                 {"buffer":0,"byteOffset":12,"byteLength":36},
                 {"buffer":0,"byteOffset":48,"byteLength":48},
                 {"buffer":0,"byteOffset":96,"byteLength":8},
                 {"buffer":0,"byteOffset":104,"byteLength":72},
                 {"buffer":0,"byteOffset":176,"byteLength":36}],
  "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"SCALAR","min":[0],"max":[2]},
               {"bufferView":1,"componentType":5126,"count":3,"type":"VEC3"},
               {"bufferView":2,"componentType":5126,"count":3,"type":"VEC4"},
               {"bufferView":3,"componentType":5126,"count":2,"type":"SCALAR","min":[0],"max":[2]},
               {"bufferView":4,"componentType":5126,"count":6,"type":"VEC3"},
               {"bufferView":5,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}]})");
}

// The triangle's vertex (1, 0, 0) in node 1 is at x = 1 + s(t) in node 0, turned by node 0's
// angle a(t) about +y (x -> (cos a, 0, -sin a) x) and lifted by its step translation.
// t = 1: a = 90 degrees, lift 2 (a key's own time takes its value), s = the spline at half its
// span: (1/2)(1) + 2(1/8)(1) + (1/2)(3) = 2.25, so (0, 2, -3.25).
// t = 0.5: a = 45 degrees (slerp), lift 0 (held), s at a quarter: 0.84375 + 2(0.140625) +
// 0.15625(3) = 1.59375.
TEST(GltfAnimation, NodeChannelsMoveTheMeshDownTheHierarchy) {
  const Scene scene = loadScene(animatedGltf());
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.motion.meshes.size(), 1u);
  expectVec(scene.meshes[0].positions[1], {2.0, 0.0, 0.0},
            1e-6);  // loaded at the nodes' own transforms
  expectVec(sceneAt(scene, 1.0).meshes[0].positions[1], {0.0, 2.0, -3.25}, 1e-6);
  const double x = 1.0 + 1.59375, c = std::sqrt(0.5);
  expectVec(sceneAt(scene, 0.5).meshes[0].positions[1], {x * c, 0.0, -x * c}, 1e-6);
  expectVec(sceneAt(scene, 0.5).meshes[0].positions[0], {c, 0.0, -c},
            1e-6);  // the origin of node 1
  // Before the first key the first values, after the last the last: 180 degrees, lift 4, scale 3.
  expectVec(sceneAt(scene, -1.0).meshes[0].positions[1], {2.0, 0.0, 0.0}, 1e-6);
  expectVec(sceneAt(scene, 9.0).meshes[0].positions[1], {-4.0, 4.0, 0.0}, 1e-6);
}

// The camera rises linearly with its node (0, 2t, 0), looking down -z; the spot light's -z axis
// turns with the rotation keys: (-sin a, 0, -cos a).
TEST(GltfAnimation, CamerasAndLightsFollowTheirNodes) {
  const Scene scene = loadScene(animatedGltf());
  ASSERT_TRUE(scene.motion.camera);
  ASSERT_EQ(scene.motion.lights.size(), 1u);
  const Scene half = sceneAt(scene, 0.5);
  expectVec(half.camera.position, {0.0, 1.0, 0.0}, 1e-6);
  expectVec(glm::normalize(half.camera.lookAt - half.camera.position), {0.0, 0.0, -1.0}, 1e-6);
  expectVec(half.camera.up, {0.0, 1.0, 0.0}, 1e-6);
  expectVec(half.lights[0].position, {0.0, 3.0, 0.0}, 1e-6);
  const double c = std::sqrt(0.5);
  expectVec(half.lights[0].direction, {-c, 0.0, -c}, 1e-6);
  expectVec(sceneAt(scene, 1.0).lights[0].direction, {-1.0, 0.0, 0.0}, 1e-6);
}

// A scene file's transform comes before the file's nodes, and its own keys move the file's
// animated meshes, lights and camera with it.
TEST(GltfAnimation, TheSceneFilesTransformAndKeysComeFirst) {
  animatedGltf();
  const Scene scene = loadScene(writeTemp("animated_entry.json", R"({"meshes": [{
      "file": "animated.gltf", "transform": {"translate": [10, 0, 0]},
      "animation": {"translate": {"times": [0, 1], "values": [[10, 0, 0], [20, 0, 0]]}}}]})"));
  ASSERT_EQ(scene.motion.meshes.size(), 1u);
  expectVec(scene.meshes[0].positions[1], {12.0, 0.0, 0.0}, 1e-6);
  const Scene one = sceneAt(scene, 1.0);
  expectVec(one.meshes[0].positions[1], {20.0, 2.0, -3.25}, 1e-6);
  expectVec(one.camera.position, {20.0, 2.0, 0.0}, 1e-6);
  expectVec(one.lights[0].position, {20.0, 3.0, 0.0}, 1e-6);
}

TEST(GltfAnimation, MalformedChannelsAreRefusedNamingTheField) {
  const auto refused = [](const std::string& file, const std::string& message) {
    try {
      loadScene(file);
      ADD_FAILURE() << "loaded: " << message;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
  };
  refused(animatedGltf(R"({"sampler":0,"target":{"node":7,"path":"translation"}})"),
          "animated.gltf: animations[0].channels[0].target.node: names no node");
  refused(animatedGltf(R"({"sampler":9,"target":{"node":0,"path":"translation"}})"),
          "animations[0].channels[0].sampler: names no sampler");
  refused(animatedGltf(R"({"sampler":0,"target":{"node":0,"path":"translation"}})",
                       R"(,"matrix":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1])"),
          "animations[0].channels[0].target.node: keys node 0, which has a matrix");
  // A rotation sampler's output is VEC4: as a translation it has the wrong size.
  refused(animatedGltf(R"({"sampler":1,"target":{"node":0,"path":"translation"}})"),
          "accessors[2] (animations[0].samplers[1].output): must hold 3 numbers per key");
  // The cubic sampler's six values (three per key) read as linear keys of three times.
  std::string file = animatedGltf();
  std::ifstream in(file);
  std::string text(std::istreambuf_iterator<char>(in), {});
  const std::string cubic = R"("input":3,"output":4,"interpolation":"CUBICSPLINE")";
  text.replace(text.find(cubic), cubic.size(), R"("input":0,"output":4)");
  refused(writeTemp("bad_keys.gltf", text),
          "accessors[4] (animations[0].samplers[2].output): holds 6 values for 3 key times");
}

// The shipped Blender export (scripts/moving_block_cornell_box): the short block keyed at frames 1
// and 48 (linear; Blender samples every frame and writes frame f at f / 24 s) slides 150 mm along
// +x while turning 90 degrees about +y around its bounds' centre c (its origin). At frame f, with
// u = (f - 1) / 47 clamped to [0, 1], a vertex p loaded at frame 1 is at
// c + (150 u, 0, 0) + R_y(90 u degrees) (p - c), R_y(a) (x, y, z) = (x cos a + z sin a, y,
// z cos a - x sin a).
TEST(GltfAnimation, ABlenderExportPlaysWithItsOwnTiming) {
  const Scene scene = loadScene(sourcePath("scenes/cornell_box_moving_block.json"));
  ASSERT_EQ(scene.motion.meshes.size(), 1u);  // the block alone moves
  ASSERT_EQ(scene.motion.meshes[0].meshCount, 1u);
  const std::vector<glm::dvec3>& loaded = scene.meshes[scene.motion.meshes[0].firstMesh].positions;
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::dvec3& p : loaded) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::dvec3 c = 0.5 * (lo + hi);
  for (const int frame : {0, 1, 24, 48, 60}) {
    const double u = std::clamp(frame - 1, 0, 47) / 47.0, a = u * std::numbers::pi / 2.0;
    const Scene at = sceneAt(scene, frameSeconds(frame, 24.0));
    for (size_t v = 0; v < loaded.size(); ++v) {
      const glm::dvec3 d = loaded[v] - c;
      const glm::dvec3 want = c + glm::dvec3(150.0 * u, 0.0, 0.0) +
                              glm::dvec3(d.x * std::cos(a) + d.z * std::sin(a), d.y,
                                         d.z * std::cos(a) - d.x * std::sin(a));
      expectVec(at.meshes[scene.motion.meshes[0].firstMesh].positions[v], want, 1e-3);
    }
  }
  // The file's camera, at the box's published viewpoint looking down +z.
  expectVec(scene.camera.position, {278.0, 273.0, -800.0}, 1e-3);
  expectVec(glm::normalize(scene.camera.lookAt - scene.camera.position), {0.0, 0.0, 1.0}, 1e-6);
}

}  // namespace
}  // namespace voxgi::test
