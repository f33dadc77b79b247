// Bad input files (tests/data/bad/, each under 1 KB): one line naming the file and the field,
// exit code 2 — never a crash, a hang, exit 0 with garbage or an internal error. A refusal reads
// at most the file's header or its few hundred bytes, milliseconds of work; the runs are limited
// to kCpuSeconds of CPU time, so that one that loops over what a header claims (a billion
// vertices) is killed and fails, however loaded the machine (a wall-clock bound would fail on a
// slow or busy one, and a hang that does not spin meets ctest's timeout).
#include <algorithm>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "tests/cli.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

constexpr int kCpuSeconds = 30;  // some thousand times a refusal's work, under ASan too

struct Case {
  const char* file;
  const char* says;  // part of the one line
};

// Runs `command` and checks the one line: exit 2, names `file`, says `says`, printable only.
void expectOneLine(const std::string& command, const std::string& file, const std::string& says) {
  const CommandResult r = voxgiWithin(kCpuSeconds, command);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_NE(r.output.find(file), std::string::npos) << "names the file: " << r.output;
  EXPECT_NE(r.output.find(says), std::string::npos) << r.output;
  EXPECT_TRUE(std::all_of(r.output.begin(), r.output.end() - 1,
                          [](char ch) { return ch >= 0x20 && ch < 0x7f; }))
      << "printable: " << r.output;
}

std::string testName(const testing::TestParamInfo<Case>& p) {
  std::string name = p.param.file;
  std::replace_if(
      name.begin(), name.end(), [](char ch) { return !std::isalnum(ch); }, '_');
  return name;
}

// Scenes and meshes, rendered.
class BadInput : public testing::TestWithParam<Case> {};

TEST_P(BadInput, IsOneLineAndExitTwo) {
  const Case& c = GetParam();
  const std::string file = sourcePath(std::string("tests/data/bad/") + c.file);
  expectOneLine("render " + file + " --backend cpu --image 16 --resolution 16 --out " +
                    testTempDir() + "out.exr",
                c.file, c.says);
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
        Case{"points_only.ply", "element vertex: no normals (nx ny nz)"},
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
        Case{"mesh_scale_1e200.json", "lies beyond 1e+15 of the origin"},
        Case{"bytes_in_header.ply", "unknown format '\\xff\\xfeascii'"},
        Case{"two_face_elements.ply", "element face: a second face or tristrips element"},
        Case{"two_vertex_elements.ply", "element vertex: a second vertex element"},
        Case{"tristrips_index_9_of_3.ply", "vertex index 9 outside [0, 3)"},
        Case{"nul_in_property_name.ply", "header line 6: a control character in the header"},
        Case{"vertex_without_x.ply", "element vertex: no property x"},
        Case{"element_without_properties.ply", "element edge: declares no properties"},
        Case{"unknown_element.ply", "element 'colours': voxgi reads vertex, face"},
        Case{"texcoord_without_indices.ply", "texcoord: 6 values for a face of 0 vertices"},
        Case{"obj_info_between_properties.ply", "obj_info between the properties of element"},
        Case{"cloud_nan_position.ply", "vertex 1: x, y, z: NaN or infinite"},
        Case{"cloud_bytes_left_over.ply", "element vertex: 3 vertices of 24 bytes take 72 bytes"},
        Case{"cloud_with_vct.json", "point_clouds: vct renders triangle meshes"}),
    testName);

// Images (references, masks and compare's inputs), compared.
class BadImage : public testing::TestWithParam<Case> {};

TEST_P(BadImage, IsOneLineAndExitTwo) {
  const Case& c = GetParam();
  const std::string file = sourcePath(std::string("tests/data/bad/") + c.file);
  expectOneLine("compare " + file + " " + file + " --error-png " + testTempDir() + "e.png", c.file,
                c.says);
}

INSTANTIATE_TEST_SUITE_P(
    Files, BadImage,
    testing::Values(Case{"exr_without_rgb.exr", "channel R: missing"},
                    Case{"exr_attribute_past_end.exr",
                         "header attribute 8 (comment): declares 2147483647 bytes"},
                    Case{"exr_window_past_file.exr", "Early end of file"},
                    Case{"exr_window_too_wide.exr", "(dataWindow): 20000631x3 is outside"},
                    Case{"exr_chlist_size_mismatch.exr", "its chlist content does not"},
                    Case{"png_size_past_file.png", "16384x16384 cannot be compressed into 268"}),
    testName);

// A million copies of one triangle overflow the fixed-point sums of a voxel (docs/stages/
// voxelize.md); 40000 copies are enough to show the one line and the exit code.
TEST(BadInputGenerated, DuplicateTrianglesOverflowOneVoxel) {
  const std::string file = testTempDir() + "duplicates.obj";
  {
    std::ofstream obj(file);
    obj << "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (int i = 0; i < 40000; ++i) obj << "f 1 2 3\n";
  }
  expectOneLine("render " + file + " --backend cpu --image 16 --resolution 16 --out " +
                    testTempDir() + "out.exr",
                "duplicates.obj", "a triangle is repeated 40000 times");
}

// Copies that differ by a rounding step are not found by the check for repeated triangles; the
// accumulation finds the overflow instead (and stops at it).
TEST(BadInputGenerated, NearDuplicateTrianglesOverflowOneVoxel) {
  const std::string file = testTempDir() + "near_duplicates.obj";
  {
    std::ofstream obj(file);
    obj << "v 0 0 16\nv 16 0 16\nv 0 16 16\nf 1 2 3\n";  // spans the grid: voxels of ~1 unit
    for (int i = 0; i < 36000; ++i) {  // one face of weight per copy: 36000 > 32768
      const double dx = 1e-6 * i;      // each copy covers some voxels near (4, 4, 8) whole
      obj << "v " << 3 + dx << " 3 8\nv " << 9 + dx << " 3 8\nv " << 3 + dx << " 9 8\n";
      obj << "f " << 4 + 3 * i << " " << 5 + 3 * i << " " << 6 + 3 * i << "\n";
    }
  }
  expectOneLine("render " + file + " --backend cpu --image 16 --resolution 16 --out " +
                    testTempDir() + "out.exr",
                "near_duplicates.obj", "fall into one voxel (fixed-point overflow)");
}

// Paths the filesystem refuses, options out of range and meshes with nothing to render: made at
// test time (links, long names), each one line and exit 2.
TEST(BadInputGenerated, PathsOptionsAndEmptyMeshes) {
  const std::string dir = testTempDir();
  const std::string out = " --backend cpu --image 16 --resolution 16 --out " + dir + "out.exr";
  const std::string box = sourcePath("scenes/cornell_box.obj");
  std::filesystem::create_symlink("loop_b.json", dir + "loop_a.json");
  std::filesystem::create_symlink("loop_a.json", dir + "loop_b.json");
  const auto scene = [&](const std::string& name, const std::string& meshFile) {
    std::ofstream(dir + name) << R"({"meshes": [{"file": ")" << meshFile << R"("}]})";
    return dir + name;
  };
  std::ofstream(dir + "flat.obj") << "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n";
  const struct {
    std::string command, file, says;
  } cases[] = {
      {"render " + dir + out, dir, "is a folder"},
      {"render " + dir + "loop_a.json" + out, "loop_a.json", "Too many levels of symbolic links"},
      {"render /dev/null" + out, "/dev/null", "is not a regular file"},
      {"render " + scene("long.json", std::string(300, 'm') + ".obj") + out, "long.json",
       "File name too long"},
      {"render " + scene("nul.json", "tri\\u0000.obj") + out, "nul.json",
       "the file name contains a NUL byte"},
      {"render " + dir + "flat.obj" + out, "flat.obj",
       "every one of its 1 triangles has zero area"},
      {"render " + box + " --backend cpu --resolution 0 --out " + dir + "o.exr", "--resolution",
       "0"},
      {"render " + box + " --backend cpu --image 0 --out " + dir + "o.exr", "--image", "0"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.command);
    expectOneLine(c.command, c.file, c.says);
  }
}

}  // namespace
}  // namespace voxgi::test
