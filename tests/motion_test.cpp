// Motion in a scene (common/scene_motion.h, docs/motion.md): keyframes against hand-computed
// values for each interpolation, a scene file's animated mesh, light and camera at given times,
// and keyframe fields that are refused with the field named.
#include <fstream>

#include <gtest/gtest.h>

#include "common/error.h"
#include "common/scene_io/scene_load.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

Keyframes keys(Interpolation i, std::vector<double> times, std::vector<glm::dvec3> values) {
  return {i, std::move(times), std::move(values)};
}

TEST(Keyframes, StepLinearAndClampedOutsideTheKeys) {
  const Keyframes step = keys(Interpolation::step, {1.0, 3.0}, {{0, 0, 0}, {4, 8, -2}});
  const Keyframes linear = keys(Interpolation::linear, {1.0, 3.0}, {{0, 0, 0}, {4, 8, -2}});
  EXPECT_EQ(step.at(2.9), glm::dvec3(0.0));
  EXPECT_EQ(step.at(3.0), glm::dvec3(4, 8, -2));
  EXPECT_EQ(linear.at(1.5), glm::dvec3(1, 2, -0.5));
  EXPECT_EQ(linear.at(0.0), glm::dvec3(0.0));        // before the first key: its value
  EXPECT_EQ(linear.at(10.0), glm::dvec3(4, 8, -2));  // after the last: the last
  const Keyframes one = keys(Interpolation::linear, {2.0}, {{1, 2, 3}});
  EXPECT_EQ(one.at(0.0), glm::dvec3(1, 2, 3));
  EXPECT_EQ(one.at(5.0), glm::dvec3(1, 2, 3));
}

// glTF's cubic spline: keys 0 at t = 0 and 1 at t = 2, out-tangent 3 at the first and in-tangent
// -1 at the second. At s = 1/2 (t = 1) the Hermite basis is (1/2, 1/8, 1/2, -1/8) with the
// tangents scaled by the spacing 2: 0/2 + 2 * 3/8 + 1/2 + 2 * (-1) * (-1/8) = 1.5.
TEST(Keyframes, CubicSplineIsGltfsHermiteSpline) {
  const Keyframes k = keys(Interpolation::cubic_spline, {0.0, 2.0},
                           {{9, 9, 9}, {0, 0, 0}, {3, 0, 0}, {-1, 0, 0}, {1, 0, 0}, {9, 9, 9}});
  EXPECT_DOUBLE_EQ(k.at(1.0).x, 1.5);
  EXPECT_DOUBLE_EQ(k.at(0.0).x, 0.0);
  EXPECT_DOUBLE_EQ(k.at(2.0).x, 1.0);
  EXPECT_DOUBLE_EQ(k.at(1.0).y, 0.0);
}

TEST(Keyframes, FrameTimesAreFramesOverFps) {
  EXPECT_DOUBLE_EQ(frameSeconds(24, 24.0), 1.0);
  EXPECT_DOUBLE_EQ(frameSeconds(1, 24.0), 1.0 / 24.0);
}

std::string writeScene(const std::string& body) {
  const std::string file = testTempDir() + "motion.json";
  std::ofstream(file) << R"({"meshes": [{"file": ")" << sourcePath("scenes/bunny.obj")
                      << R"(", "transform": {"translate": [1, 0, 0]},
      "animation": {"translate": {"times": [0, 2], "values": [[1, 0, 0], [1, 4, 0]]},
                    "rotate_deg": {"times": [0, 1], "values": [[0, 0, 0], [0, 360, 0]]}}}],
    "grid": {"min": [-5, -5, -5], "size": 20},)"
                      << body << "}";
  return file;
}

// A mesh entry's translate and rotate_deg keys move its loaded positions rigidly: at 1 s it has
// turned a whole turn (keys as angles, not quaternions: the same pose, reached by turning) and
// risen by 2; at 2 s risen by 4. A light and the camera keyed likewise.
TEST(SceneMotion, SceneFileKeysMoveMeshLightAndCamera) {
  const Scene scene = loadScene(writeScene(R"(
    "lights": [{"type": "point", "position": [0, 5, 0], "intensity": [1, 1, 1],
                "animation": {"intensity": {"times": [0, 1], "values": [[0, 0, 0], [2, 4, 6]],
                                            "interpolation": "step"}}}],
    "camera": {"position": [0, 0, 10], "look_at": [0, 0, 0],
               "animation": {"position": {"times": [0, 1], "values": [[0, 0, 10], [10, 0, 0]]}}})"));
  ASSERT_EQ(scene.motion.meshes.size(), 1u);
  const Mesh& still = scene.meshes.at(0);
  const Scene at1 = sceneAt(scene, 1.0), at2 = sceneAt(scene, 2.0), half = sceneAt(scene, 0.5);
  for (size_t i = 0; i < still.positions.size(); i += 97) {
    const glm::dvec3 p = still.positions[i];
    EXPECT_NEAR(glm::length(at1.meshes[0].positions[i] - (p + glm::dvec3(0, 2, 0))), 0.0, 1e-9);
    EXPECT_NEAR(glm::length(at2.meshes[0].positions[i] - (p + glm::dvec3(0, 4, 0))), 0.0, 1e-9);
    // Half a turn about y through the entry's origin (1, 0, 0): x - 1 and z flip sign.
    const glm::dvec3 turned(2.0 - p.x, p.y + 1.0, -p.z);
    EXPECT_NEAR(glm::length(half.meshes[0].positions[i] - turned), 0.0, 1e-9);
  }
  EXPECT_EQ(sceneAt(scene, 0.5).lights[0].intensity, glm::vec3(0.0f));
  EXPECT_EQ(at1.lights[0].intensity, glm::vec3(2, 4, 6));
  EXPECT_NEAR(glm::length(half.camera.position - glm::dvec3(5, 0, 5)), 0.0, 1e-12);
  EXPECT_EQ(sceneAt(scene, 0.0).meshes[0].positions, still.positions);
}

TEST(SceneMotion, BadKeyframesAreRefusedNamingTheField) {
  struct Case {
    const char* body;
    const char* field;
  };
  for (const Case c :
       {Case{R"("lights": [{"type": "point", "position": [0, 5, 0], "intensity": [1, 1, 1],
                "animation": {"position": {"times": [1, 1], "values": [[0,0,0], [1,1,1]]}}}])",
             "lights[0].animation.position.times[1]"},
        Case{R"("lights": [{"type": "point", "position": [0, 5, 0], "intensity": [1, 1, 1],
                "animation": {"intensity": {"times": [0], "values": [[-1, 0, 0]]}}}])",
             "lights[0].animation.intensity.values[0][0]"},
        Case{R"("lights": [{"type": "point", "position": [0, 5, 0], "intensity": [1, 1, 1],
                "animation": {"position": {"times": [0, 1], "values": [[0,0,0]],
                                           "interpolation": "cubic_spline"}}}])",
             "lights[0].animation.position.values"},
        Case{R"("lights": [{"type": "point", "position": [0, 5, 0], "intensity": [1, 1, 1],
                "animation": {"position": {"times": [0], "values": [[0,0,0]],
                                           "interpolation": "smooth"}}}])",
             "lights[0].animation.position.interpolation"},
        Case{R"("camera": {"position": [0, 0, 10], "look_at": [0, 0, 0],
               "animation": {"fov_y_deg": {"times": [0], "values": [[1, 1, 1]]}}})",
             "camera.animation"}}) {
    try {
      loadScene(writeScene(c.body));
      ADD_FAILURE() << c.field;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.field), std::string::npos) << e.what();
    }
  }
  // A camera keyed onto its target is refused at the time it gets there.
  const Scene scene =
      loadScene(writeScene(R"("camera": {"position": [0, 0, 10], "look_at": [0, 0, 0],
               "animation": {"position": {"times": [0, 1], "values": [[0, 0, 10], [0, 0, 0]]}}})"));
  EXPECT_NO_THROW(sceneAt(scene, 0.5));
  EXPECT_THROW(sceneAt(scene, 1.0), InputError);
}

}  // namespace
}  // namespace voxgi::test
