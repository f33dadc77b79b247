#include <fstream>

#include <gtest/gtest.h>

#include "common/effect_plan.h"
#include "common/error.h"
#include "common/scene_io/scene_load.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

// The InputError message of loading `json` (with a valid mesh next to it), or "" if it loads.
std::string errorOf(const std::string& json) {
  writeTemp("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  try {
    loadScene(writeTemp("scene.json", json));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneLoad, CornellBox) {
  const Scene s = loadScene(sourcePath("scenes/cornell_box.json"));
  EXPECT_EQ(s.triangleCount(), 32u);
  EXPECT_TRUE(vct().plan(s, Settings{}).on(Effect::emission));
  EXPECT_TRUE(s.settings.empty());
  // A scene's settings come before --set (the LPV box asks for 16 propagation steps).
  const Scene lpvBox = loadScene(sourcePath("scenes/cornell_box_lpv.json"));
  const Technique& lpv = findTechnique("lpv");
  EXPECT_EQ(lpvBox.settings, std::vector<std::string>{"propagate.steps=16"});
  EXPECT_EQ(resolveSettings(lpv, lpvBox.settings, lpvBox.file, "default", {}).lpv.steps, 16);
  EXPECT_EQ(resolveSettings(lpv, lpvBox.settings, lpvBox.file, "default", {"propagate.steps=3"})
                .lpv.steps,
            3);
  EXPECT_EQ(s.grid.resolution, 64);
  bool red = false;
  for (const Material& m : s.materials)
    if (m.name == "red") red = std::abs(m.albedo.x - 0.63f) < 1e-6f;
  EXPECT_TRUE(red);
  EXPECT_NEAR(s.camera.fovYDeg, 39.3, 1e-9);
}

TEST(SceneLoad, BunnyWithMaterialOverrideAndLight) {
  const Scene s = loadScene(sourcePath("scenes/bunny.json"));
  EXPECT_EQ(s.lights.size(), 1u);
  EXPECT_GT(s.triangleCount(), 3000u);
  EXPECT_EQ(s.materials[s.meshes[0].material].name, "bunny");
}

TEST(SceneLoad, BareMeshFileGetsDefaults) {
  const Scene s = loadScene(sourcePath("scenes/bunny.obj"));
  EXPECT_GT(s.triangleCount(), 3000u);
  const auto [lo, hi] = s.bounds();
  for (int a = 0; a < 3; ++a) {
    EXPECT_LT(s.grid.min[a], lo[a]);
    EXPECT_GT(s.grid.min[a] + s.grid.size, hi[a]);
  }
}

TEST(SceneLoad, GltfAndPlyImport) {
  const std::string ply = writeTemp("tri.ply",
                                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float "
                                    "x\nproperty float y\nproperty float z\n"
                                    "element face 1\nproperty list uchar int "
                                    "vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(loadScene(ply).triangleCount(), 1u);
  // A minimal glTF 2.0 triangle with an embedded buffer (3 float3 positions).
  const std::string gltf =
      writeTemp("tri.gltf", R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],
    "nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
    "buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
    "bufferViews":[{"buffer":0,"byteLength":36}],
    "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}]})");
  EXPECT_EQ(loadScene(gltf).triangleCount(), 1u);
}

TEST(SceneLoad, ErrorsNameTheFileAndTheField) {
  EXPECT_NE(errorOf("{").find("malformed JSON"), std::string::npos);
  EXPECT_NE(errorOf(R"({"meshes": [{"file": "missing.obj"}]})").find("meshes[0].file"),
            std::string::npos);
  EXPECT_NE(
      errorOf(R"({"meshes": [{"file": "tri.obj"}], "colour": 1})").find("unknown field 'colour'"),
      std::string::npos);
  EXPECT_NE(errorOf(R"({"meshes": [{"file": "tri.obj"}], "grid": {"resolution": 100}})")
                .find("grid.resolution"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"meshes": [{"file": "tri.obj", "material": "gold"}]})")
                .find("unknown material 'gold'"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"meshes": [], "materials": {"m": {"albedo": [1, -0.5, 0]}}})")
                .find("materials.m.albedo[1]"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"meshes": [], "lights": [{"type": "area", "intensity": [1,1,1]}]})")
                .find("lights[0].type"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"meshes": [], "grid": {"min": [0,0,0]}})").find("grid"), std::string::npos);
  EXPECT_NE(errorOf(R"({"meshes": [], "camera": {"position": [0,0,0], "look_at": [0,0,0]}})")
                .find("camera.look_at"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"meshes": [], "settings": {"bounce.count": 99}})")
                .find("settings.bounce.count: must be in [0, 8]"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"meshes": [], "settings": {"cones.sett": "equal7"}})")
                .find("settings.cones.sett: unknown parameter"),
            std::string::npos);
  EXPECT_NE(errorOf(R"({"meshes": [], "settings": {"ao.mode": true}})").find("settings.ao.mode"),
            std::string::npos);
  EXPECT_EQ(errorOf(R"({"meshes": [{"file": "tri.obj"}]})"), "");
  EXPECT_THROW(loadScene("/nonexistent/scene.json"), InputError);
  EXPECT_THROW(loadScene(writeTemp("broken.obj", "v 0 0\nf 1 2 3 4 5\n")), InputError);
  writeTemp("negative.mtl", "newmtl dark\nKd -0.5 0.2 0.2\n");
  try {
    loadScene(writeTemp("negative.obj",
                        "mtllib negative.mtl\nusemtl dark\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    FAIL() << "negative albedo accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("material 'dark'.albedo"), std::string::npos) << e.what();
  }
}

TEST(SceneLoad, ErrorsAreOneLine) {
  const std::string e = errorOf(R"({"meshes": [{"file": "tri.obj"}], "grid": {"resolution": 3}})");
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
  EXPECT_NE(e.find("scene.json"), std::string::npos) << e;
}

// Directions are normalised in double whatever their length, so an up vector of length 1e-160 or
// a spot direction of length 1e308 are the unit vectors they point along, not NaN or 0.
TEST(SceneLoad, DirectionsOfAnyLengthNormalise) {
  const std::string dir = testTempDir();
  std::ofstream(dir + "s.json")
      << R"({"meshes": [{"file": ")" << sourcePath("scenes/cornell_box.obj")
      << R"("}], "camera": {"position": [278, 273, -800], "look_at": [278, 273, 0],
             "up": [0, 1e-160, 0]},
             "lights": [{"type": "spot", "position": [278, 500, 278],
                         "direction": [1e308, -1e308, 0], "intensity": [1, 1, 1]}]})";
  const Scene s = loadScene(dir + "s.json");
  EXPECT_EQ(s.camera.up, glm::dvec3(0, 1, 0));
  EXPECT_NEAR(s.lights[0].direction.x, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(s.lights[0].direction.y, -std::sqrt(0.5), 1e-15);
}

}  // namespace
}  // namespace voxgi::test
