// Point clouds in: PLY in every format and value type, the scene file's options, transforms,
// estimated radii and normals, and every malformed file of the input list (docs/svo.md).
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <random>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "common/error.h"
#include "common/scene_io/point_cloud_ply.h"
#include "common/scene_io/point_neighbours.h"
#include "common/scene_io/scene_load.h"
#include "common/surface_sampling.h"
#include "common/texture.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

// A property of a PLY written by these tests: its header name and type and how to write a value.
struct Prop {
  const char* name;
  const char* type;  // "float", "double", "uchar", "ushort", ...
};

// Writes `rows` (a value for every property) as PLY in `format`, returning the path.
std::string writePly(const std::string& name, const std::string& format,
                     const std::vector<Prop>& props, const std::vector<std::vector<double>>& rows,
                     const std::string& extraHeader = "") {
  const std::string path = testTempDir() + name;
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat " << format << " 1.0\nelement vertex " << rows.size() << "\n";
  for (const Prop& p : props) out << "property " << p.type << " " << p.name << "\n";
  out << extraHeader << "end_header\n";
  const bool big = format == "binary_big_endian";
  for (const auto& row : rows) {
    for (size_t i = 0; i < props.size(); ++i) {
      const std::string t = props[i].type;
      if (format == "ascii") {
        out << (i ? " " : "") << row[i];
        continue;
      }
      unsigned char b[8];
      size_t n = 0;
      const auto put = [&](auto v) {
        n = sizeof v;
        std::memcpy(b, &v, n);
      };
      if (t == "float") put(float(row[i]));
      if (t == "double") put(double(row[i]));
      if (t == "uchar") put(uint8_t(row[i]));
      if (t == "ushort") put(uint16_t(row[i]));
      if (t == "int") put(int32_t(row[i]));
      if (big) std::reverse(b, b + n);
      out.write(reinterpret_cast<const char*>(b), std::streamsize(n));
    }
    if (format == "ascii") out << "\n";
  }
  return path;
}

std::string writeText(const std::string& name, const std::string& text) {
  std::ofstream(testTempDir() + name) << text;
  return testTempDir() + name;
}

const std::vector<Prop> kFull = {
    {"x", "double"}, {"y", "float"},   {"z", "int"},       {"nx", "float"},   {"ny", "float"},
    {"nz", "float"}, {"red", "uchar"}, {"green", "uchar"}, {"blue", "uchar"}, {"radius", "float"}};
const std::vector<std::vector<double>> kRows = {{0.5, 1.25, 2, 0, 0, 3, 255, 0, 51, 0.125},
                                                {-1, 0, 7, 1, 1, 0, 10, 20, 30, 0.5}};

TEST(PointCloudPly, AsciiAndBothBinaryOrdersReadTheSameValues) {
  for (const std::string format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    SCOPED_TRACE(format);
    const PlyPoints p = readPlyPoints(writePly("full_" + format + ".ply", format, kFull, kRows));
    ASSERT_EQ(p.positions.size(), 2u);
    EXPECT_EQ(p.positions[0], glm::dvec3(0.5, 1.25, 2));
    EXPECT_EQ(p.positions[1], glm::dvec3(-1, 0, 7));
    EXPECT_EQ(p.normals[0], glm::vec3(0, 0, 1));  // normalised as read
    EXPECT_NEAR(p.normals[1].x, std::sqrt(0.5), 1e-7);
    EXPECT_EQ(p.colors[0], glm::vec3(1.0f, 0.0f, 0.2f));  // uchar / 255
    EXPECT_EQ(p.radii[1], 0.5f);
  }
}

TEST(PointCloudPly, OptionalPropertiesStayEmptyAndUshortColoursScaleBy65535) {
  const PlyPoints p = readPlyPoints(writePly("ushort.ply", "binary_little_endian",
                                             {{"x", "float"},
                                              {"y", "float"},
                                              {"z", "float"},
                                              {"red", "ushort"},
                                              {"green", "ushort"},
                                              {"blue", "ushort"}},
                                             {{1, 2, 3, 65535, 0, 13107}}));
  EXPECT_TRUE(p.normals.empty());
  EXPECT_TRUE(p.radii.empty());
  EXPECT_EQ(p.colors[0], glm::vec3(1.0f, 0.0f, 0.2f));
}

// Every malformed point cloud of the issue's list: one error naming the file and the element or
// vertex, before anything large is allocated.
TEST(PointCloudPly, MalformedFilesAreOneErrorNamingTheFileAndVertex) {
  const std::vector<Prop> xyz = {{"x", "float"}, {"y", "float"}, {"z", "float"}};
  const std::vector<Prop> withNormals = {{"x", "float"},  {"y", "float"},  {"z", "float"},
                                         {"nx", "float"}, {"ny", "float"}, {"nz", "float"}};
  const double nan = std::nan("");
  const struct {
    std::string file, says;
  } cases[] = {
      {writePly("nan.ply", "binary_little_endian", xyz, {{0, 0, 0}, {1, nan, 0}}),
       "vertex 1: x, y, z: NaN or infinite"},
      {writePly("beyond_float.ply", "ascii", xyz, {{0, 0, 0}, {1, 1, 0}, {0, 0, 1e39}}),
       "vertex 2: z: '1e+39' is not a valid value of its type"},
      {writePly("nan_ascii.ply", "ascii", xyz, {{0, 0, 0}, {nan, 1, 0}}),
       "vertex 1: x, y, z: NaN or infinite"},
      {writePly("zero_normal.ply", "binary_big_endian", withNormals, {{0, 0, 0, 0, 0, 0}}),
       "vertex 0: nx, ny, nz: the zero vector"},
      {writePly("partial_normal.ply", "ascii",
                {{"x", "float"}, {"y", "float"}, {"z", "float"}, {"nx", "float"}}, {{0, 0, 0, 1}}),
       "element vertex: only some of nx, ny, nz"},
      {writePly("float_colour.ply", "ascii",
                {{"x", "float"},
                 {"y", "float"},
                 {"z", "float"},
                 {"red", "float"},
                 {"green", "float"},
                 {"blue", "float"}},
                {{0, 0, 0, 0.5, 2, 0}}),
       "vertex 0: green: a float colour must be in [0, 1]"},
      {writePly("int_colour.ply", "ascii",
                {{"x", "float"},
                 {"y", "float"},
                 {"z", "float"},
                 {"red", "int"},
                 {"green", "int"},
                 {"blue", "int"}},
                {{0, 0, 0, 1, 2, 0}}),
       "red: a colour is uchar, ushort, float or double"},
      {writePly("negative_radius.ply", "binary_little_endian",
                {{"x", "float"}, {"y", "float"}, {"z", "float"}, {"radius", "float"}},
                {{0, 0, 0, 1}, {0, 0, 0, -1}}),
       "vertex 1: radius: must be a positive finite number"},
      {writeText("list.ply",
                 "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                 "property float z\nproperty list uchar int extra\nend_header\n0 0 0 2 1 2\n"),
       "no list property (extra)"},
      {writeText("few_values.ply",
                 "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\n"
                 "property float z\nend_header\n0.000 0 0\n1 1\n"),
       "vertex 1: the line has too few values"},
      {writePly("no_z.ply", "ascii", {{"x", "float"}, {"y", "float"}}, {{0, 0}}),
       "element vertex: no property z"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file);
    try {
      readPlyPoints(c.file);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.file), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
  }
}

// Counts that do not match the file's size: too few bytes (refused by the header check before
// any allocation, even for a billion declared points), and bytes left over.
TEST(PointCloudPly, CountsThatDoNotMatchTheFileSizeAreRefused) {
  const std::string dir = testTempDir();
  std::ofstream(dir + "billion.ply", std::ios::binary)
      << "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\nproperty float x\n"
         "property float y\nproperty float z\nend_header\n"
      << std::string(24, '\0');
  std::ofstream(dir + "extra.ply", std::ios::binary)
      << "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty float x\n"
         "property float y\nproperty float z\nend_header\n"
      << std::string(25, '\0');
  std::ofstream(dir + "extra_ascii.ply")
      << "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\n"
         "property float y\nproperty float z\nend_header\n0 0 0\n1 1 1\n";
  const struct {
    std::string file, says;
  } cases[] = {
      {dir + "billion.ply", "header: the declared elements need at least 12000000000"},
      {dir + "extra.ply", "element vertex: 2 vertices of 12 bytes take 24 bytes, the file has 25"},
      {dir + "extra_ascii.ply", "body: data after the last vertex"}};
  for (const auto& c : cases) {
    try {
      readPlyPoints(c.file);
      ADD_FAILURE() << c.file;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
  }
}

TEST(PointCloudScene, TransformColoursAndMaterialFromTheSceneFile) {
  writePly("cloud.ply", "ascii", kFull, kRows);
  const Scene s = loadScene(writeText("clouds.json", R"({
    "materials": {"stone": {"albedo": [0.3, 0.3, 0.3]}},
    "point_clouds": [
      {"file": "cloud.ply", "material": "stone",
       "transform": {"translate": [1, 0, 0], "scale": [2, 1, 1]}},
      {"file": "cloud.ply", "colors": "linear"},
      {"file": "cloud.ply", "colors": "ignore"}],
    "camera": {"position": [0, 0, 10], "look_at": [0, 0, 0]}})"));
  ASSERT_EQ(s.pointClouds.size(), 3u);
  const PointCloud& a = s.pointClouds[0];
  EXPECT_EQ(s.materials[a.material].name, "stone");
  EXPECT_EQ(a.positions[0], glm::dvec3(2.0, 1.25, 2.0));  // scaled in x, then moved
  // The normal (1, 1, 0)/sqrt 2 under scale (2, 1, 1): the inverse transpose, (1/2, 1, 0).
  EXPECT_NEAR(a.normals[1].x, 0.5 / std::sqrt(1.25), 1e-6);
  EXPECT_NEAR(a.radii[0], 0.125 * std::cbrt(2.0), 1e-7);                   // the mean scale
  EXPECT_NEAR(a.colors[0].z, std::pow((0.2 + 0.055) / 1.055, 2.4), 1e-6);  // sRGB decoded
  EXPECT_EQ(s.pointClouds[1].colors[0], glm::vec3(1.0f, 0.0f, 0.2f));
  EXPECT_TRUE(s.pointClouds[2].colors.empty());
  EXPECT_EQ(s.pointCount(), 6u);
  // The grid covers every point with its disc.
  const auto [lo, hi] = s.bounds();
  EXPECT_LE(s.grid.min.x, lo.x);
  EXPECT_GE(s.grid.min.z + s.grid.size, hi.z);
}

TEST(PointCloudScene, FieldsAreCheckedAndCloudsWithoutNormalsNeedTheEstimateOption) {
  writePly("bare.ply", "ascii", {{"x", "float"}, {"y", "float"}, {"z", "float"}}, {{0, 0, 0}});
  writeText("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const struct {
    std::string json, says;
  } cases[] = {
      {R"({"point_clouds": [{"file": "bare.ply"}]})", "bare.ply: element vertex: no normals"},
      {R"({"point_clouds": [{"file": "bare.ply", "normals": "guess"}]})",
       "point_clouds[0].normals: must be \"file\" or \"estimate\""},
      {R"({"point_clouds": [{"file": "bare.ply", "colors": "cmyk"}]})",
       "point_clouds[0].colors: must be"},
      {R"({"point_clouds": [{"file": "bare.ply", "radius": 1}]})",
       "point_clouds[0]: unknown field 'radius'"},
      {R"({"point_clouds": [{"file": "tri.obj"}]})", "not a point-cloud PLY"},
      {R"({"point_clouds": [{"file": "bare.ply", "normals": "estimate"}]})",
       "needs at least 16 points, the cloud has 1"},
      {R"({"materials": {}})", "meshes: missing"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.json);
    try {
      loadScene(writeText("bad.json", c.json));
      ADD_FAILURE() << "loaded";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
    }
  }
}

// A bare PLY without faces is a point cloud, with the mesh defaults around it.
TEST(PointCloudScene, BarePlyOfPointsLoadsAsACloud) {
  const std::string file = writePly("bare_cloud.ply", "binary_little_endian", kFull, kRows);
  const Scene s = loadScene(file);
  ASSERT_EQ(s.pointClouds.size(), 1u);
  EXPECT_TRUE(s.meshes.empty());
  EXPECT_EQ(s.pointClouds[0].name, file);
}

// A square lattice of spacing h in the plane z = 1: the 8th nearest other point of an interior
// point is at h sqrt 2, so r = sqrt(2/8) h sqrt 2 = h / sqrt 2; the normals are +-z, turned toward
// the viewpoint.
TEST(PointNeighbours, LatticeRadiiAndPlaneNormalsTowardTheViewpoint) {
  PointCloud cloud;
  cloud.name = "lattice";
  const double h = 0.1;
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i) cloud.positions.push_back({i * h, j * h, 1.0});
  estimateRadii(cloud);
  estimateNormals(cloud, glm::dvec3(1.0, 1.0, -5.0));
  for (int j = 2; j < 18; ++j)
    for (int i = 2; i < 18; ++i) {
      const size_t k = size_t(j * 20 + i);
      ASSERT_NEAR(cloud.radii[k], h / std::sqrt(2.0), 1e-6);
      ASSERT_NEAR(cloud.normals[k].z, -1.0f, 1e-6f);
    }
}

// Points on a sphere with the viewpoint at its centre: every estimated normal points inward, and
// a few duplicated points take the median radius instead of 0.
TEST(PointNeighbours, SphereNormalsFaceAnInsideViewpointAndDuplicatesTakeTheMedianRadius) {
  PointCloud cloud;
  cloud.name = "sphere";
  std::mt19937 rng(3);
  std::normal_distribution<double> g;
  for (int i = 0; i < 4000; ++i) {
    glm::dvec3 p(g(rng), g(rng), g(rng));
    cloud.positions.push_back(glm::normalize(p));
  }
  for (int i = 0; i < 9; ++i) cloud.positions.push_back(cloud.positions[0]);
  estimateRadii(cloud);
  estimateNormals(cloud, glm::dvec3(0.0));
  for (size_t i = 0; i < cloud.size(); ++i) {
    ASSERT_GT(cloud.radii[i], 0.0f);
    ASSERT_LT(glm::dot(glm::dvec3(cloud.normals[i]), cloud.positions[i]), -0.98) << i;
  }
}

// Sampling a mesh: every point on its triangle's plane with its normal, colours from the material,
// discs twice the area per point; the same points whatever the thread count; a density gradient
// puts the expected share of points in each half.
TEST(SurfaceSampling, PointsLieOnTheSurfaceWithAreasAndDensityAsAsked) {
  Material m;
  m.albedo = glm::vec3(0.25f, 0.5f, 0.75f);
  Scene scene = makeScene(quad(1, 2.0, {0.0, 0.0}, {4.0, 1.0}), unitGrid(8, 8.0), m);
  SurfaceSampling sampling;
  sampling.points = 20000;
  const PointCloud a = sampleSurfaces(scene, sampling);
  ASSERT_EQ(a.size(), 20000u);
  double discs = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.positions[i].y, 2.0);
    ASSERT_NEAR(std::abs(a.normals[i].y), 1.0f, 1e-6f);
    ASSERT_EQ(a.colors[i], m.albedo);
    discs += 3.14159265358979 * double(a.radii[i]) * a.radii[i];
  }
  EXPECT_NEAR(discs, 2.0 * 4.0, 1e-6 * 8.0);  // twice the quad's area
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const PointCloud b = sampleSurfaces(scene, sampling);
    EXPECT_EQ(a.positions, b.positions);
  }
  // Density from 1 at z = 0 to 3 at z = 4 (the quad spans z in [0, 4]): the upper half holds
  // (2 + 3) / (1 + 2 + 2 + 3) = 5/8 of the points; binomial sigma is 0.0034.
  sampling.gradientAxis = 2;
  sampling.gradientRatio = 3.0;
  sampling.noise = 0.01;
  const PointCloud c = sampleSurfaces(scene, sampling);
  size_t upper = 0;
  double offset2 = 0.0;
  for (size_t i = 0; i < c.size(); ++i) {
    upper += c.positions[i].z > 2.0;
    offset2 += (c.positions[i].y - 2.0) * (c.positions[i].y - 2.0);
  }
  EXPECT_NEAR(double(upper) / double(c.size()), 5.0 / 8.0, 0.02);
  EXPECT_NEAR(std::sqrt(offset2 / double(c.size())), 0.01, 0.0005);  // the noise's sigma
  // The radii follow the density: pi r^2 sums to twice the area still.
  double cDiscs = 0.0;
  for (const float r : c.radii) cDiscs += 3.14159265358979 * double(r) * r;
  EXPECT_NEAR(cDiscs, 8.0, 0.2);
}

// A textured quad's points take the texture's colour where they lie: a 64 x 64 texture whose left
// half is one sRGB code and right half another. 20000 points on a unit quad each stand for 1/20000
// of its area, a square 0.0071 wide, 0.45 texel: level 0, bilinear, so a point more than a texel
// (1/64) from the middle reads its half's value exactly (1/32 kept clear here).
TEST(SurfaceSampling, PointsTakeTheirTexturesColour) {
  Material m;
  m.albedo = glm::vec3(1.0f);
  Scene scene = makeScene(quad(1, 0.5, {0.0, 0.0}, {1.0, 1.0}), unitGrid(8), m);
  Mesh& mesh = scene.meshes[0];
  for (const glm::dvec3& p : mesh.positions) mesh.texcoords.emplace_back(p.x, p.z);
  const uint32_t left = srgbEncode(0.2f), right = srgbEncode(0.6f);
  DecodedImage image{64, 64, {}};
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      for (int c = 0; c < 3; ++c) image.rgb.push_back(uint8_t(x < 32 ? left : right));
  scene.materials[0].albedoTexture = scene.textures.texture(
      "halves", shared::kWrapClamp, shared::kWrapClamp, [&] { return image; });
  SurfaceSampling sampling;
  sampling.points = 20000;
  const PointCloud cloud = sampleSurfaces(scene, sampling);
  size_t checked = 0;
  for (size_t i = 0; i < cloud.size(); ++i) {
    const double u = cloud.positions[i].x;
    if (std::abs(u - 0.5) < 1.0 / 32.0) continue;
    ASSERT_EQ(cloud.colors[i], glm::vec3(srgbDecodeTable()[u < 0.5 ? left : right])) << u;
    ++checked;
  }
  EXPECT_GT(checked, 18000u);
}

}  // namespace
}  // namespace voxgi::test
