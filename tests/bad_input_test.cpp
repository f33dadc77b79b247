// Bad input files (tests/data/bad/, each under 1 KB): one line naming the file and the field,
// exit code 2, within 5 s — never a crash, a hang, exit 0 with garbage or an internal error.
#include <algorithm>
#include <chrono>

#include <gtest/gtest.h>

#include "tests/cli.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

struct Case {
  const char* file;
  const char* says;  // part of the one line
};

class BadInput : public testing::TestWithParam<Case> {};

TEST_P(BadInput, IsOneLineAndExitTwo) {
  const Case& c = GetParam();
  const std::string file = sourcePath(std::string("tests/data/bad/") + c.file);
  const auto start = std::chrono::steady_clock::now();
  const CommandResult r =
      voxgi("render " + file + " --backend cpu --image 16 --resolution 16 --out " + testTempDir() +
            "out.exr");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_NE(r.output.find(c.file), std::string::npos) << "names the file: " << r.output;
  EXPECT_NE(r.output.find(c.says), std::string::npos) << r.output;
  EXPECT_LT(seconds, 5.0);
}

INSTANTIATE_TEST_SUITE_P(
    Files, BadInput,
    testing::Values(
        Case{"face_index_7_of_3.ply", "face 0: vertex_indices: vertex index 7 outside [0, 3)"},
        Case{"face_index_negative.ply", "vertex index -1 outside [0, 3)"},
        Case{"header_without_end.ply", "header: no end_header line"},
        Case{"billion_vertices.ply", "header: the declared elements need at least"},
        Case{"truncated_binary.ply", "header: the declared elements need at least 37 bytes"},
        Case{"list_count_255.ply", "face 0: the line has too few values"},
        Case{"points_only.ply", "contains no faces"},
        Case{"stl_named_gltf.gltf", "not a glTF file"},
        Case{"missing_meshes.json", "meshes: missing (this field is required)"},
        Case{"light_without_intensity.json", "lights[0].intensity: missing"},
        Case{"number_beyond_double.json", "malformed JSON"},
        Case{"grid_size_tiny.json", "grid.size: gives voxels of"},
        Case{"grid_size_huge.json", "grid.size: gives voxels of"},
        Case{"mesh_is_a_folder.json", "is a folder, not a mesh file"},
        Case{"camera_at_1e308.json", "camera.position: must lie within 1e+15 of the origin"},
        Case{"light_at_1e39.json", "lights[0].position: must lie within 1e+15"},
        Case{"falloff_1e-45.json", "falloff.constant: must be 0 or at least 1e-30"},
        Case{"mesh_scale_1e-300.json", "grid.size: gives voxels of"},
        Case{"mesh_scale_1e200.json", "lies beyond 1e+15 of the origin"}),
    [](const testing::TestParamInfo<Case>& p) {
      std::string name = p.param.file;
      std::replace_if(
          name.begin(), name.end(), [](char ch) { return !std::isalnum(ch); }, '_');
      return name;
    });

}  // namespace
}  // namespace voxgi::test
