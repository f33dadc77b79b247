// The voxgi command: exit codes, one-line errors and the files it writes.
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <set>
#include <sstream>
#include <vector>
#include <sys/wait.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <openvdb/openvdb.h>

#include "common/io/image_io.h"

#include "tests/cli.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

TEST(Cli, VoxelizeWritesAlignedGrids) {
  const std::string out = testTempDir() + "cornell.vdb";
  const CommandResult r = voxgi("voxelize " + sourcePath("scenes/cornell_box.json") +
                                " --resolution 32 --out " + out + " --backend cpu");
  ASSERT_EQ(r.code, 0) << r.output;
  openvdb::initialize();
  openvdb::io::File file(out);
  file.open();
  std::set<std::string> names;
  for (auto it = file.beginName(); it != file.endName(); ++it) names.insert(it.gridName());
  EXPECT_EQ(names, (std::set<std::string>{"albedo", "normal", "emission", "opacity"}));
  const auto opacity = file.readGrid("opacity");
  // Grid min (-2,-2,-2), size 562, N = 32: voxel (0,0,0)'s centre sits half a voxel inside.
  const openvdb::Vec3d c = opacity->indexToWorld(openvdb::Coord(0, 0, 0));
  EXPECT_NEAR(c.x(), -2.0 + 0.5 * 562.0 / 32.0, 1e-9);
}

// voxgi dump --technique svo writes every octree level as grids that line up with the scene's
// grid: leaves at the voxel size, node level depth - m at 2^m voxels.
TEST(Cli, SvoLevelsDumpAsAlignedGrids) {
  const std::string dir = testTempDir() + "svo";
  const CommandResult r =
      voxgi("dump " + sourcePath("scenes/cornell_box.json") +
            " --technique svo --stage all --resolution 16 --image 16 --out " + dir);
  ASSERT_EQ(r.code, 0) << r.output;
  openvdb::initialize();
  openvdb::io::File build(dir + "/build.vdb");
  build.open();
  const auto opacity = build.readGrid("leaf_sums_opacity");
  EXPECT_GT(opacity->activeVoxelCount(), 0u);
  EXPECT_NE(opacity->metaValue<std::string>("voxgi_svo_weight_scale"), "");
  const auto child = build.readGrid("nodes_child_L3");  // the root tile: tree level 1 of 4
  EXPECT_EQ(child->activeVoxelCount(), 8u);
  openvdb::io::File mip(dir + "/mip.vdb");
  mip.open();
  const double h = 562.0 / 16.0;
  openvdb::io::File propagate(dir + "/propagate.vdb");
  propagate.open();
  for (const auto& [name, level] : {std::pair<std::string, int>{"node_faces_+x_L1", 1},
                                    std::pair<std::string, int>{"node_faces_-z_L2", 2},
                                    std::pair<std::string, int>{"gathered_bricks", 0}}) {
    const auto g = (level == 0 ? propagate : mip).readGrid(name);
    EXPECT_GT(g->activeVoxelCount(), 0u) << name;
    const openvdb::Vec3d c = g->indexToWorld(openvdb::Coord(0, 0, 0));
    EXPECT_NEAR(c.x(), -2.0 + 0.5 * h * double(1 << level), 1e-9) << name;
  }
}

TEST(Cli, BareMeshAndAutoBackend) {
  const std::string out = testTempDir() + "bunny.vdb";
  const CommandResult r = voxgi("voxelize " + sourcePath("scenes/bunny.obj") +
                                " --resolution 16 --out " + out + " --backend auto");
  EXPECT_EQ(r.code, 0) << r.output;
}

// voxgi sample writes a point cloud the loader reads back, path traces it and renders it with the
// octree, and refuses a bad gradient with one line.
TEST(Cli, SampleWritesAPointCloudThatRenders) {
  const std::string cloud = testTempDir() + "box.ply";
  CommandResult r = voxgi("sample " + sourcePath("scenes/cornell_box.json") +
                          " --points 20000 --noise 0.5 --density-gradient y:0.5 --out " + cloud);
  ASSERT_EQ(r.code, 0) << r.output;
  r = voxgi(
      "render " + cloud +
      " --technique path --spp 1 --sampler independent --light-sampling area --image 16 --out " +
      testTempDir() + "box.exr");
  EXPECT_EQ(r.code, 0) << r.output;
  // The path tracer's discs at 16 spp are the reference the octree's image is held to.
  const std::string reference = testTempDir() + "box_ref.exr";
  r = voxgi("render " + cloud + " --technique path --spp 16 --image 16 --out " + reference);
  ASSERT_EQ(r.code, 0) << r.output;
  // The octree renders it on either backend (it needs at least 4 leaves a side), lit as the
  // path tracer lights it: the default lights (nothing in a bare cloud emits). Measured at 16^3:
  // energy 1.07-1.09 of the path tracer's per channel, relMSE 0.24 where black scores 0.62. The
  // bounds fail a black or a blank image, one lit twice, or one lit by another light.
  for (const char* backend : {"cpu", "gpu"}) {
    const std::string image = testTempDir() + "svo_" + backend + ".exr";
    r = voxgi("render " + cloud + " --technique svo --backend " + backend +
              " --resolution 16 --image 16 --set propagate.frames=2 --out " + image);
    EXPECT_EQ(r.code, 0) << r.output;
    const std::string json = testTempDir() + "svo_" + backend + ".json";
    r = voxgi("compare " + image + " " + reference + " --json " + json);
    ASSERT_EQ(r.code, 0) << r.output;
    const nlohmann::json m = nlohmann::json::parse(std::ifstream(json));
    for (const double energy : m["energy"]) {
      EXPECT_GT(energy, 0.8) << backend;
      EXPECT_LT(energy, 1.25) << backend;
    }
    EXPECT_LT(m["rel_mse"].get<double>(), 0.5 * m["baselines"]["black"]["rel_mse"].get<double>())
        << backend;
  }
  r = voxgi("render " + cloud + " --technique svo --resolution 2 --image 16 --out " +
            testTempDir() + "svo.exr");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("grid.resolution: the octree's leaves are the grid's voxels"),
            std::string::npos)
      << r.output;
  r = voxgi("sample " + sourcePath("scenes/cornell_box.json") +
            " --points 10 --density-gradient w:2 --out " + cloud);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--density-gradient: expected AXIS:RATIO"), std::string::npos)
      << r.output;
}

TEST(Cli, BadInputExitsTwoWithOneLine) {
  const std::string scene = sourcePath("scenes/cornell_box.json");
  for (const std::string& args : std::vector<std::string>{
           "voxelize " + scene + " --resolution 100 --out x.vdb",
           "voxelize /nonexistent.json --out x.vdb",
           "voxelize " + scene + " --resolution 2048 --out x.vdb --backend cpu",
           "voxelize " + scene + " --mode blurry --out x.vdb",
           "diff " + scene + " --stage nosuchstage",
           "dump " + scene + " --stage mip --out x --set voxel_shadow.kappa=99",
           "dump " + scene + " --stage mip --out x --set no.such.key=1",
           "dump " + scene + " --stage mip --out x --preset nobody2020",
           "render " + scene + " --technique path --sampler halton --out x.exr",
           "render " + scene + " --technique path --light-sampling cosine --out x.exr"}) {
    const CommandResult r = voxgi(args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << args << "\n" << r.output;
  }
  const std::string broken = testTempDir() + "broken.json";
  std::ofstream(broken) << "{\"meshes\": [";
  const CommandResult r = voxgi("voxelize " + broken + " --out x.vdb");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.output.find("broken.json"), std::string::npos) << r.output;
}

TEST(Cli, DiffReportsEveryBufferAsJson) {
  const std::string json = testTempDir() + "report.json", dump = testTempDir() + "dump";
  const CommandResult r =
      voxgi("diff " + sourcePath("scenes/bunny.json") +
            " --stage voxelize --resolution 32 --json " + json + " --dump " + dump);
  ASSERT_EQ(r.code, 0) << r.output;
  std::ifstream in(json);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const char* key : {"\"metric\"", "\"tolerance\"", "\"max_abs_diff\"", "\"differing\"",
                          "\"fraction\"", "\"pass\"", "\"non_ties\""})
    EXPECT_NE(text.find(key), std::string::npos) << key;
  for (const char* f : {"/voxelize_cpu.vdb", "/voxelize_gpu.vdb", "/voxelize_diff.vdb"})
    EXPECT_TRUE(std::filesystem::exists(dump + f)) << f;
}

TEST(Cli, DumpWritesEveryBufferOfTheStage) {
  const std::string dir = testTempDir() + "dumpcmd";
  const CommandResult r = voxgi("dump " + sourcePath("scenes/cornell_box.json") +
                                " --stage voxelize --resolution 16 --backend cpu --out " + dir);
  ASSERT_EQ(r.code, 0) << r.output;
  openvdb::initialize();
  openvdb::io::File file(dir + "/voxelize.vdb");
  file.open();
  size_t grids = 0;
  for (auto it = file.beginName(); it != file.endName(); ++it) ++grids;
  // The Cornell box emits, so every declared buffer exists: 8 buffers, the emission sum's
  // emitting weight (its w) as a grid of its own.
  EXPECT_EQ(grids, 9u);
}

TEST(Cli, CompareReportsMetricsNoiseFloorAndAnErrorMap) {
  const std::string dir = testTempDir();
  Image test(16, 8), reference(16, 8), variance(16, 8), small(8, 8);
  for (glm::vec3& p : test.pixels) p = glm::vec3(0.6f);
  for (glm::vec3& p : reference.pixels) p = glm::vec3(0.5f);
  for (glm::vec3& p : variance.pixels) p = glm::vec3(0.0004f);  // standard error 0.02
  writeExr(dir + "t.exr", test);
  writeExr(dir + "r.exr", reference);
  writeExr(dir + "r.variance.exr", variance);
  writeExr(dir + "small.exr", small);
  const CommandResult r =
      voxgi("compare " + dir + "t.exr " + dir + "r.exr --json " + dir + "c.json");
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json c = nlohmann::json::parse(std::ifstream(dir + "c.json"));
  EXPECT_NEAR(c["rmse"].get<double>(), 0.1, 1e-6);
  EXPECT_NEAR(c["noise_floor"]["rmse"].get<double>(), 0.02, 1e-6);
  EXPECT_EQ(c["pixels"].get<int>(), 128);
  // In units of the reference's mean (0.5), beside the trivial answers: black scores
  // 1 / (1 + 0.01), the reference's mean is the reference here.
  EXPECT_NEAR(c["rel_mse"].get<double>(), 0.04 / (1.0 + 0.01), 1e-5);
  EXPECT_NEAR(c["energy"][1].get<double>(), 1.2, 1e-5);
  EXPECT_NEAR(c["baselines"]["black"]["rel_mse"].get<double>(), 1.0 / 1.01, 1e-6);
  EXPECT_EQ(c["baselines"]["black"]["energy"][0].get<double>(), 0.0);
  EXPECT_EQ(c["baselines"]["constant"]["rel_mse"].get<double>(), 0.0);
  EXPECT_NE(r.output.find("black"), std::string::npos) << r.output;
  const CommandResult absolute = voxgi("compare " + dir + "t.exr " + dir +
                                       "r.exr --units absolute" + " --json " + dir + "a.json");
  ASSERT_EQ(absolute.code, 0) << absolute.output;
  const nlohmann::json a = nlohmann::json::parse(std::ifstream(dir + "a.json"));
  EXPECT_NEAR(a["rel_mse"].get<double>(), 0.01 / (0.25 + 0.01), 1e-6);
  EXPECT_EQ(voxgi("compare " + dir + "t.exr " + dir + "r.exr --units metres").code, 2);
  // --skip-emitters reads the reference's emission term (render --terms).
  const CommandResult noTerm = voxgi("compare " + dir + "t.exr " + dir + "r.exr --skip-emitters");
  EXPECT_EQ(noTerm.code, 2) << noTerm.output;
  EXPECT_NE(noTerm.output.find("r.emission.exr: missing"), std::string::npos) << noTerm.output;
  EXPECT_GT(std::filesystem::file_size(dir + "t.error.png"), 0u);
  const CommandResult bad = voxgi("compare " + dir + "small.exr " + dir + "r.exr");
  EXPECT_EQ(bad.code, 2) << bad.output;
  EXPECT_NE(bad.output.find("small.exr: size: 8x8"), std::string::npos) << bad.output;
  // A reference with a NaN and an empty mask are bad input; a NaN under test is reported.
  Image withNan = reference, empty(16, 8);
  withNan.at(3, 2).g = std::numeric_limits<float>::quiet_NaN();
  writeExr(dir + "nan.exr", withNan);
  writeExr(dir + "empty.exr", empty);
  const CommandResult nanReference = voxgi("compare " + dir + "t.exr " + dir + "nan.exr");
  EXPECT_EQ(nanReference.code, 2) << nanReference.output;
  EXPECT_NE(nanReference.output.find("nan.exr: pixel (3, 2): not finite"), std::string::npos)
      << nanReference.output;
  const CommandResult emptyMask =
      voxgi("compare " + dir + "t.exr " + dir + "r.exr --mask " + dir + "empty.exr");
  EXPECT_EQ(emptyMask.code, 2) << emptyMask.output;
  const CommandResult nanTest = voxgi("compare " + dir + "nan.exr " + dir + "r.exr");
  EXPECT_EQ(nanTest.code, 0) << nanTest.output;
  EXPECT_NE(nanTest.output.find("non-finite pixels in " + dir + "nan.exr: 1"), std::string::npos)
      << nanTest.output;
}

// voxgi ledger: the emitters' VPLs of the thesis's form land in the volume and every step's flux
// is in the JSON; a technique without a propagation volume is one line and exit 2.
TEST(Cli, LedgerAccountsForAVolumesLight) {
  const std::string dir = testTempDir(), scene = sourcePath("scenes/cornell_box_lpv.json");
  const CommandResult r = voxgi("ledger " + scene + " --technique holpv --resolution 16" +
                                " --preset martin2012 --backend cpu --json " + dir + "l.json");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("read by shading"), std::string::npos) << r.output;
  const nlohmann::json l = nlohmann::json::parse(std::ifstream(dir + "l.json"));
  EXPECT_EQ(l["steps"].size(), 16u);  // the scene's propagate.steps
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(l["injected"][c].get<double>(), l["emitted"][c].get<double>(),
                1e-5 * l["emitted"][c].get<double>());
  const CommandResult vct = voxgi("ledger " + scene + " --technique vct");
  EXPECT_EQ(vct.code, 2) << vct.output;
  EXPECT_EQ(std::count(vct.output.begin(), vct.output.end(), '\n'), 1) << vct.output;
}

TEST(Cli, PlanSaysWhatRunsAndWhy) {
  // The box's light is two emissive triangles: area lights with a shadow cone each by default.
  const CommandResult r = voxgi("plan " + sourcePath("scenes/cornell_box.json"));
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* line :
       {"out  bounce", "bounce.count=0", "in     emission volume",
        "2 emissive triangle(s) as area lights", "out    specular cone       no glossy material",
        "in     shadow cones        2 of 2 light(s) cast shadows"})
    EXPECT_NE(r.output.find(line), std::string::npos) << line << "\n" << r.output;
  const CommandResult other = voxgi("plan " + sourcePath("scenes/cornell_box.json") +
                                    " --set bounce.count=1 --set ao.mode=on"
                                    " --set emitters.mode=voxels");
  for (const char* line : {"in   bounce", "bounce.count=1", "in     ambient occlusion   ao.mode=on",
                           "out    shadow cones        no analytic or area lights"})
    EXPECT_NE(other.output.find(line), std::string::npos) << line << "\n" << other.output;
}

// The mean of an image's channels.
double imageMean(const Image& image) {
  double sum = 0.0;
  for (const glm::vec3& p : image.pixels) sum += double(p.x) + double(p.y) + double(p.z);
  return sum / (3.0 * double(image.pixels.size()));
}

// A Blender 3.4 export (tests/data/scenes/README.md) renders through its own camera (4:3) and
// lights, with no default light; --camera names one the file has, or the error lists them.
TEST(Cli, GltfRendersWithItsCameraAndLights) {
  const std::string glb = sourcePath("tests/data/scenes/blender_room.glb");
  const std::string out = testTempDir() + "blender_room.exr";
  const CommandResult r = voxgi("render " + glb +
                                " --technique vct --backend cpu --resolution 16"
                                " --image 64 --out " +
                                out);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(r.output.find("default"), std::string::npos) << r.output;
  const Image image = readExr(out);
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 48);
  EXPECT_GT(imageMean(image), 0.01);
  EXPECT_EQ(voxgi("plan " + glb + " --camera Cam").code, 0);
  const CommandResult wrong = voxgi("plan " + glb + " --camera Nope");
  EXPECT_EQ(wrong.code, 2);
  EXPECT_EQ(wrong.output,
            "voxgi: " + glb + ": --camera: no camera 'Nope' in its mesh files (they have 'Cam')\n");
}

// A bare model with no light renders lit by the default lights and says so, after the run.
TEST(Cli, BareModelIsLitByTheDefaultLights) {
  const std::string out = testTempDir() + "bunny_lit.exr";
  const CommandResult r =
      voxgi("render " + sourcePath("scenes/bunny.obj") +
            " --technique vct --backend cpu --resolution 16 --image 64 --out " + out);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("default key and fill lights"), std::string::npos) << r.output;
  EXPECT_GT(imageMean(readExr(out)), 0.01);
  const CommandResult plan = voxgi("plan " + sourcePath("scenes/bunny.obj"));
  EXPECT_NE(plan.output.find("  lights: "), std::string::npos) << plan.output;
}

// Every OBJ, PLY, glTF and GLB file of Debian's assimp-testmodels (Assimp's own corpus of real
// model files) renders lit, or is refused with exit 2 and one line naming the file.
TEST(Cli, AssimpTestModelsRenderLitOrAreRefused) {
  const std::filesystem::path root = "/usr/share/assimp/models";
  if (!std::filesystem::is_directory(root))
    GTEST_SKIP() << root << " is absent: apt-get install assimp-testmodels";
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (entry.is_regular_file() &&
        (ext == ".obj" || ext == ".ply" || ext == ".gltf" || ext == ".glb"))
      files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  EXPECT_GE(files.size(), 80u);
  const std::string out = testTempDir() + "assimp_model.exr";
  int rendered = 0;
  for (const std::string& file : files) {
    const std::string quoted = "'" + file + "'";  // some names have spaces
    const CommandResult r = voxgi("render " + quoted +
                                  " --technique vct --backend cpu"
                                  " --resolution 16 --image 32 --out " +
                                  out);
    if (r.code == 0) {
      ++rendered;
      EXPECT_GT(imageMean(readExr(out)), 0.0) << file << "\n" << r.output;
    } else {
      EXPECT_EQ(r.code, 2) << file << "\n" << r.output;
      EXPECT_EQ(r.output.rfind("voxgi: " + file + ":", 0), 0u) << r.output;
      EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    }
  }
  EXPECT_GT(rendered, 0);
}

TEST(Cli, RenderHelpListsEveryParameterWithItsDefault) {
  const CommandResult r = voxgi("render --help");
  EXPECT_EQ(r.code, 0);
  for (const char* key : {"voxel_shadow.kappa = 1", "voxel_shadow.mode = hard",
                          "mip.mode = anisotropic", "kahl2019:", "villegas2017:"})
    EXPECT_NE(r.output.find(key), std::string::npos) << key << "\n" << r.output;
}

// dump --checksums fingerprints each buffer's words with FNV-1a: the same figure as hashing the
// floats of the EXR it writes, and the same at one thread as at four.
TEST(Cli, DumpChecksumsFingerprintTheBuffersWords) {
  const std::string dir = testTempDir() + "checksums";
  const std::string args = "dump " + sourcePath("scenes/cornell_box.json") +
                           " --stage gbuffer --resolution 16 --image 48 --backend cpu --checksums";
  const CommandResult four = voxgi("--threads 4 " + args + " --out " + dir);
  ASSERT_EQ(four.code, 0) << four.output;
  const CommandResult one = voxgi("--threads 1 " + args);
  ASSERT_EQ(one.code, 0) << one.output;
  const auto checksumLines = [](const std::string& output) {
    std::istringstream in(output);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
      if (line.rfind("checksum ", 0) == 0) lines.push_back(line);
    return lines;
  };
  EXPECT_EQ(checksumLines(four.output), checksumLines(one.output));
  ASSERT_EQ(checksumLines(one.output).size(), 7u) << one.output;

  const Image albedo = readExr(dir + "/gbuffer.pixel_albedo.exr");
  uint64_t h = 0xcbf29ce484222325ull;
  for (const glm::vec3& p : albedo.pixels)
    for (int c = 0; c < 3; ++c) {
      unsigned char bytes[4];
      std::memcpy(bytes, &p[c], 4);  // little-endian, as the words are hashed
      for (const unsigned char b : bytes) h = (h ^ b) * 0x100000001b3ull;
    }
  std::ostringstream expected;
  expected << "checksum gbuffer.pixel_albedo " << albedo.pixels.size() * 3 << " " << std::hex
           << std::setw(16) << std::setfill('0') << h;
  const std::vector<std::string> lines = checksumLines(one.output);
  EXPECT_NE(std::find(lines.begin(), lines.end(), expected.str()), lines.end())
      << expected.str() << "\n"
      << one.output;
  EXPECT_EQ(voxgi(args.substr(0, args.find(" --checksums"))).code, 2);  // neither --out nor it
}

TEST(Cli, DumpWritesPyramidsAsVdbAndImagesAsExr) {
  const std::string dir = testTempDir();
  const std::string scene = sourcePath("scenes/bunny.json");
  const CommandResult mip =
      voxgi("dump " + scene + " --stage mip --resolution 16 --backend cpu --out " + dir);
  ASSERT_EQ(mip.code, 0) << mip.output;
  openvdb::initialize();
  openvdb::io::File file(dir + "/mip.vdb");
  file.open();
  std::set<std::string> names;
  for (auto it = file.beginName(); it != file.endName(); ++it) names.insert(*it);
  EXPECT_TRUE(names.count("radiance_mips6_+x_L1") && names.count("radiance_mips6_-z_L4") &&
              names.count("radiance_mips6_+y_L2_alpha"))
      << names.size();
  const CommandResult g =
      voxgi("dump " + scene + " --stage gbuffer --resolution 16 --backend cpu --out " + dir);
  ASSERT_EQ(g.code, 0) << g.output;
  EXPECT_TRUE(std::filesystem::exists(dir + "/gbuffer.pixel_normal.exr"));
}

// The plan decides what dump writes: a stage it skips is refused (naming why), and --stage all
// writes each stage it runs under the stage's own name with the stage's own buffers; render's
// image is compose's colour.
TEST(Cli, DumpAndRenderFollowThePlan) {
  const std::string dir = testTempDir(), scene = sourcePath("scenes/bunny.json");
  const std::string common = " --resolution 16 --image 32 --backend cpu";
  const CommandResult skipped = voxgi("dump " + scene + " --stage bounce --out " + dir + common);
  EXPECT_EQ(skipped.code, 2) << skipped.output;
  EXPECT_EQ(std::count(skipped.output.begin(), skipped.output.end(), '\n'), 1) << skipped.output;
  EXPECT_NE(skipped.output.find("the plan skips vct/bounce (bounce.count=0"), std::string::npos)
      << skipped.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "bounce.vdb"));

  const CommandResult all = voxgi("dump " + scene + " --stage all --out " + dir + common);
  ASSERT_EQ(all.code, 0) << all.output;
  for (const char* file : {"voxelize.vdb", "light_voxels.vdb", "mip.vdb", "gbuffer.object_id.exr",
                           "trace_cones.indirect_diffuse.exr", "compose.color.exr"})
    EXPECT_TRUE(std::filesystem::exists(dir + file)) << file << "\n" << all.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "bounce.vdb"));
  openvdb::initialize();
  openvdb::io::File file(dir + "light_voxels.vdb");
  file.open();
  const auto radiance = file.readGrid("radiance");
  EXPECT_EQ(radiance->metaValue<std::string>("voxgi_stage"), "vct/light_voxels");

  const CommandResult render =
      voxgi("render " + scene + " --technique vct --out " + dir + "render.exr" + common);
  ASSERT_EQ(render.code, 0) << render.output;
  const Image rendered = readExr(dir + "render.exr"), composed = readExr(dir + "compose.color.exr");
  EXPECT_EQ(rendered.pixels, composed.pixels);

  const CommandResult qualified =
      voxgi("dump " + scene + " --stage vct/trace_cones --out " + dir + "q" + common);
  EXPECT_EQ(qualified.code, 0) << qualified.output;
  const CommandResult unknown = voxgi("dump " + scene + " --stage lpv/propagate --out " + dir);
  EXPECT_EQ(unknown.code, 2) << unknown.output;
  EXPECT_NE(unknown.output.find("no stage 'lpv/propagate' in vct"), std::string::npos)
      << unknown.output;
}

// Every output is checked before the work starts, and a bad one is one line and exit 2 that leaves
// nothing behind: a device, a missing folder, a symbolic link.
TEST(Cli, OutputsAreCheckedBeforeTheWork) {
  const std::string dir = testTempDir(), scene = sourcePath("scenes/cornell_box.json");
  const std::string small = " --resolution 16 --image 16 --backend cpu";
  for (const std::string& out : {std::string("--out /dev/null"), "--out " + dir + "no/x.exr",
                                 "--out " + dir + "x.exr --png " + dir + "no/x.png"}) {
    const CommandResult r = voxgi("render " + scene + small + " " + out);
    EXPECT_EQ(r.code, 2) << out << "\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  }
  EXPECT_FALSE(std::filesystem::exists(dir + "x.exr"))
      << "the EXR is not written before --png fails";
  std::filesystem::create_symlink("/dev/null", dir + "link.vdb");
  const CommandResult link = voxgi("voxelize " + scene + small + " --out " + dir + "link.vdb");
  EXPECT_EQ(link.code, 2) << link.output;
  EXPECT_NE(link.output.find("symbolic link"), std::string::npos) << link.output;
  const CommandResult json =
      voxgi("diff " + scene + " --stage voxelize --resolution 16 --json " + dir + "no/r.json");
  EXPECT_EQ(json.code, 2) << json.output;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find(".voxgi-"), std::string::npos) << e.path();
}

// render --frames: one image per frame, named by the --out pattern, the bunny turning between them
// (docs/motion.md); a bad range or a name without a frame field is one line, exit 2, nothing
// written.
TEST(Cli, RenderFramesWritesOneImagePerFrame) {
  const std::string dir = testTempDir(), scene = sourcePath("scenes/bunny_turning.json");
  const std::string small = " --resolution 16 --image 32 --backend cpu";
  const CommandResult r =
      voxgi("render " + scene + small + " --frames 0:12:6 --out " + dir + "f_%03d.exr");
  ASSERT_EQ(r.code, 0) << r.output;
  const Image a = readExr(dir + "f_000.exr"), b = readExr(dir + "f_006.exr"),
              c = readExr(dir + "f_012.exr");
  EXPECT_NE(a.pixels, b.pixels);  // a quarter turn apart
  EXPECT_NE(b.pixels, c.pixels);
  EXPECT_FALSE(std::filesystem::exists(dir + "f_003.exr"));
  // A single image of an animated scene is its frame 0.
  ASSERT_EQ(voxgi("render " + scene + small + " --out " + dir + "one.exr").code, 0);
  EXPECT_EQ(readExr(dir + "one.exr").pixels, a.pixels);
  for (const std::string& bad :
       {" --frames 3:1 --out " + dir + "g_%03d.exr", " --frames 0:2 --out " + dir + "g.exr",
        " --frames 0:x --out " + dir + "g_%03d.exr",
        " --frames 0:1 --out " + dir + "g_%03d_%d.exr"}) {
    const CommandResult e = voxgi("render " + scene + small + bad);
    EXPECT_EQ(e.code, 2) << bad << "\n" << e.output;
    EXPECT_EQ(std::count(e.output.begin(), e.output.end(), '\n'), 1) << e.output;
  }
  for (const auto& e : std::filesystem::directory_iterator(dir))
    EXPECT_FALSE(e.path().filename().string().starts_with("g")) << e.path();
}

// A camera that moves and then stops: the frames reuse every volume stage, then every stage, and
// say so; `plan --frames` says the same; each frame's file is the one --scratch writes.
TEST(Cli, RenderFramesReusesWhatDidNotChange) {
  const std::string dir = testTempDir();
  const std::string scene =
      writeTemp("camera_moves.json", R"({"meshes": [{"file": ")" + sourcePath("scenes/bunny.obj") +
                                         R"("}],
    "lights": [{"type": "point", "position": [3, 10, 5], "intensity": [40, 40, 40]}],
    "camera": {"position": [0, 6, 26], "look_at": [0, 4, 0],
      "animation": {"position": {"times": [0, 1], "values": [[0, 6, 26], [8, 6, 24]]}}},
    "grid": {"resolution": 16, "min": [-8.5, -2.5, -8.5], "size": 17}})");
  const std::string small = " --image 32 --backend cpu --frames 0:48:24";
  const CommandResult r = voxgi("render " + scene + small + " --out " + dir + "i_%02d.exr");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("i_24.exr; ran 3 of 6 stages (the camera moved)"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("i_48.exr; ran 0 of 6 stages (nothing moved)"), std::string::npos)
      << r.output;
  const CommandResult s =
      voxgi("render " + scene + small + " --scratch --out " + dir + "s_%02d.exr");
  ASSERT_EQ(s.code, 0) << s.output;
  EXPECT_NE(s.output.find("ran 6 of 6 stages (from scratch)"), std::string::npos) << s.output;
  for (const char* f : {"00", "24", "48"})
    EXPECT_EQ(readExr(dir + "i_" + f + ".exr").pixels, readExr(dir + "s_" + f + ".exr").pixels)
        << f;
  const CommandResult p = voxgi("plan " + scene + " --frames 0:48:24");
  ASSERT_EQ(p.code, 0) << p.output;
  EXPECT_NE(p.output.find("frame 24 (1 s): the camera moved\n  reuse  voxelize"), std::string::npos)
      << p.output;
}

// diff --frames: every stage of each frame of the Blender-exported moving block passes on both
// backends, and the JSON holds one report per frame.
TEST(Cli, DiffFramesComparesEveryFrame) {
  const std::string json = testTempDir() + "diff_frames.json";
  const CommandResult r = voxgi("diff " + sourcePath("scenes/cornell_box_moving_block.json") +
                                " --resolution 16 --image 32 --frames 0:48:24 --json " + json);
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* frame : {"frame 0:\n", "frame 24:\n", "frame 48:\n"})
    EXPECT_NE(r.output.find(frame), std::string::npos) << r.output;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(json));
  ASSERT_EQ(j.size(), 3u);
  EXPECT_EQ(j[2]["frame"], 48);
}

// dump --frames: one numbered file per frame and stage, the frames' checksums (the block moved
// between them), frame 0's those of the scene dumped without --frames.
TEST(Cli, DumpFramesWritesANumberedVolumePerFrame) {
  const std::string dir = testTempDir() + "dump_frames";
  const std::string scene = sourcePath("scenes/cornell_box_moving_block.json");
  const CommandResult r = voxgi("dump " + scene + " --stage voxelize --resolution 16 --frames " +
                                "0:48:48 --checksums --out " + dir);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir + "/voxelize_0000.vdb")) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir + "/voxelize_0048.vdb")) << r.output;
  const size_t second = r.output.find("frame 48\n");
  ASSERT_NE(second, std::string::npos) << r.output;
  const auto checksumOf = [](const std::string& text, size_t from) {
    const size_t at = text.find("checksum voxelize.opacity ", from);
    return at == std::string::npos ? std::string() : text.substr(at, text.find('\n', at) - at);
  };
  const std::string first = checksumOf(r.output, 0), last = checksumOf(r.output, second);
  ASSERT_FALSE(first.empty()) << r.output;
  EXPECT_NE(first, last) << "the block moved";
  const CommandResult still =
      voxgi("dump " + scene + " --stage voxelize --resolution 16 --checksums");
  ASSERT_EQ(still.code, 0) << still.output;
  EXPECT_EQ(checksumOf(still.output, 0), first);
}

// study --frames against references that are vct's own frames (render --frames): every frame's
// error and flicker 0, while a black frame's error and a held sequence's flicker (the block moved)
// are not; a row per technique and frame; the path tracer and sweeps refused in one line.
TEST(Cli, StudyFramesMeasuresEachFrameAndItsChange) {
  const std::string dir = testTempDir() + "study_frames/";
  std::filesystem::create_directories(dir);
  const std::string scene = sourcePath("scenes/cornell_box_moving_block.json");
  const std::string options = " --image 32 --resolution 16 --frames 0:48:48";
  const CommandResult render = voxgi("render " + scene + options + " --out " + dir + "ref_%d.exr");
  ASSERT_EQ(render.code, 0) << render.output;
  const std::string study = "study " + scene + options + " --reference " + dir +
                            "ref_%d.exr --repeat 1 --csv " + dir + "study.csv";
  const CommandResult r = voxgi(study + " --technique vct,lpv --plot " + dir + "study.png");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir + "study.png"));
  std::ifstream csv(dir + "study.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line,
            "technique,frame,seconds,rebuild_seconds,rmse,rel_mse,mare,ssim,ssim_loss,error,"
            "black_error,flicker,held,noise");
  std::vector<std::vector<std::string>> rows;
  while (std::getline(csv, line)) {
    std::vector<std::string> cells;
    std::istringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
    if (line.back() == ',') cells.emplace_back();
    rows.push_back(cells);
  }
  ASSERT_EQ(rows.size(), 4u);
  for (size_t i = 0; i < 2; ++i) {
    const std::vector<std::string>& vct = rows[i];
    ASSERT_EQ(vct.size(), 14u) << line;
    EXPECT_EQ(vct[0], "vct");
    EXPECT_EQ(vct[1], std::to_string(48 * i));
    EXPECT_EQ(std::stod(vct[9]), 0.0) << "vct's frame against itself";
    EXPECT_GT(std::stod(vct[10]), 0.1) << "a black frame";
    if (i == 0) continue;
    EXPECT_EQ(std::stod(vct[11]), 0.0) << "vct's change against itself";
    EXPECT_GT(std::stod(vct[12]), 0.0) << "the block moved";
    EXPECT_GT(std::stod(rows[2 + i][9]), 0.0) << "lpv against vct";
  }
  EXPECT_EQ(voxgi(study + " --technique path").code, 2);
  EXPECT_EQ(voxgi(study + " --sweep cones.count=6,16").code, 2);
}

// compare --frames on hand-made sequences: the reference brightens from 1 to 2 to 4, the test from
// 1 to 3 and stays. In units of each reference frame's mean (2, then 4): flicker |2 - 1| / 2 = 0.5
// then |0 - 2| / 4 = 0.5, held 1 / 2 then 2 / 4; relMSE per frame (t - r)^2 / (r^2 + 0.01 u^2).
TEST(Cli, CompareFramesMeasuresFlickerAgainstTheReferencesChange) {
  const std::string dir = testTempDir();
  const float reference[] = {1.0f, 2.0f, 4.0f}, test[] = {1.0f, 3.0f, 3.0f};
  for (int f = 0; f < 3; ++f) {
    Image r(8, 8), t(8, 8);
    for (glm::vec3& p : r.pixels) p = glm::vec3(reference[f]);
    for (glm::vec3& p : t.pixels) p = glm::vec3(test[f]);
    writeExr(dir + "ref_" + std::to_string(f) + ".exr", r);
    writeExr(dir + "seq_" + std::to_string(f) + ".exr", t);
  }
  const CommandResult r = voxgi("compare " + dir + "seq_%d.exr " + dir +
                                "ref_%d.exr --frames 0:2 --json " + dir + "frames.json");
  ASSERT_EQ(r.code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(dir + "frames.json"));
  ASSERT_EQ(j["frames"].size(), 3u);
  EXPECT_FALSE(j["frames"][0].contains("flicker"));
  EXPECT_NEAR(j["frames"][1]["flicker"].get<double>(), 0.5, 1e-6);
  EXPECT_NEAR(j["frames"][2]["flicker"].get<double>(), 0.5, 1e-6);
  EXPECT_NEAR(j["frames"][1]["held"].get<double>(), 0.5, 1e-6);
  EXPECT_NEAR(j["frames"][2]["held"].get<double>(), 0.5, 1e-6);
  EXPECT_NEAR(j["frames"][1]["rel_mse"].get<double>(), 1.0 / (4.0 + 0.01 * 4.0), 1e-6);
  EXPECT_TRUE(std::filesystem::exists(dir + "seq_2.error.png"));
  // A missing frame, and options for one image, are refused in one line.
  for (const std::string& bad :
       {std::string(" --frames 0:3"), std::string(" --frames 0:2 --terms")}) {
    const CommandResult e = voxgi("compare " + dir + "seq_%d.exr " + dir + "ref_%d.exr" + bad);
    EXPECT_EQ(e.code, 2) << bad << "\n" << e.output;
    EXPECT_EQ(std::count(e.output.begin(), e.output.end(), '\n'), 1) << e.output;
  }
}

}  // namespace
}  // namespace voxgi::test
