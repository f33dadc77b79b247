// A glTF file's materials, lights and cameras (common/scene_io/gltf_authored.h) against values
// computed by hand from the glTF 2.0 specification and its KHR_lights_punctual,
// KHR_materials_emissive_strength and KHR_materials_specular extensions.
#include <cmath>
#include <filesystem>
#include <numbers>

#include <gtest/gtest.h>

#include "common/error.h"
#include "common/scene_io/gltf_authored.h"
#include "common/scene_io/scene_load.h"
#include "tests/test_scenes.h"

namespace voxgi::test {
namespace {

// One triangle (0,0,0), (1,0,0), (0,1,0) as accessor 0.
constexpr const char* kTriangle = R"(
  "buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
  "bufferViews":[{"buffer":0,"byteLength":36}],
  "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}])";

// Four materials, two meshes using them out of order, a point light two nodes down a hierarchy,
// a spot light turned to point down, a directional light, and two cameras.
std::string authoredGltf() {
  return writeTemp("authored.gltf", std::string(R"({"asset":{"version":"2.0"},"scene":0,
  "scenes":[{"nodes":[0,1,4,5,6,7]}],
  "nodes":[
    {"name":"parent","translation":[10,0,0],"scale":[2,2,2],"children":[2]},
    {"mesh":0},
    {"name":"bulb","translation":[1,2,3],"children":[3]},
    {"name":"bulb child","mesh":1,"extensions":{"KHR_lights_punctual":{"light":0}}},
    {"name":"spot","translation":[0,4,0],"rotation":[-0.70710678118654752,0,0,0.70710678118654752],
     "extensions":{"KHR_lights_punctual":{"light":1}}},
    {"name":"sun","extensions":{"KHR_lights_punctual":{"light":2}}},
    {"name":"Main","translation":[0,1,5],"camera":0},
    {"name":"Side","matrix":[0,0,-1,0, 0,1,0,0, 1,0,0,0, 7,1,0,1],"camera":1}],
  "cameras":[{"type":"perspective","perspective":{"yfov":0.5,"aspectRatio":2,"znear":0.1}},
             {"name":"side camera","type":"perspective","perspective":{"yfov":1.0,"znear":0.1}}],
  "extensions":{"KHR_lights_punctual":{"lights":[
    {"type":"point","color":[1,0.5,0.25],"intensity":683},
    {"type":"spot","intensity":1366,"spot":{"innerConeAngle":0,"outerConeAngle":1.0471975511965976}},
    {"type":"directional","intensity":1366}]}},
  "materials":[
    {"name":"lambert","pbrMetallicRoughness":{"baseColorFactor":[0.8,0.5,0.2,1],"metallicFactor":0,
     "roughnessFactor":0.5},"extensions":{"KHR_materials_specular":{"specularFactor":0}}},
    {"name":"emitter","emissiveFactor":[1,0.5,0.25],
     "extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":17}}},
    {"name":"metal","pbrMetallicRoughness":{"baseColorFactor":[0.9,0.6,0.3,1],"roughnessFactor":0.5}},
    {"pbrMetallicRoughness":{"metallicFactor":0}}],
  "meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":2},
                           {"attributes":{"POSITION":0},"material":0}]},
            {"primitives":[{"attributes":{"POSITION":0},"material":1},
                           {"attributes":{"POSITION":0},"material":3,"mode":5}]}],)") +
                                        kTriangle + "}");
}

const Material& materialNamed(const Scene& s, const std::string& name) {
  for (const Material& m : s.materials)
    if (m.name == name) return m;
  throw std::runtime_error("no material " + name);
}

TEST(GltfScene, MaterialsMapMetallicRoughnessOntoLambertAndPhong) {
  const Scene s = loadScene(authoredGltf());
  // A dielectric without specular (Blender's Lambertian): its base colour, no lobe.
  const Material& lambert = materialNamed(s, "lambert");
  expectVec(lambert.albedo, {0.8, 0.5, 0.2}, 1e-7);
  EXPECT_FALSE(lambert.glossy());
  // Emission times KHR_materials_emissive_strength (which Assimp 5.2.5 drops). Metallic 1 by
  // default: no diffuse part, a rough (roughness 1) base-coloured lobe.
  const Material& emitter = materialNamed(s, "emitter");
  expectVec(emitter.emission, {17.0, 8.5, 4.25}, 1e-6);
  expectVec(emitter.albedo, glm::dvec3(0.0));
  expectVec(emitter.specular, glm::dvec3(1.0));
  EXPECT_EQ(emitter.shininess, 1.0f);
  // Metal of roughness 0.5: alpha 0.25, Phong exponent 2 / 0.25^2 - 2 = 30.
  const Material& metal = materialNamed(s, "metal");
  expectVec(metal.albedo, glm::dvec3(0.0));
  expectVec(metal.specular, {0.9, 0.6, 0.3}, 1e-7);
  EXPECT_NEAR(metal.shininess, 30.0f, 1e-4f);
  // An unnamed default dielectric: F0 0.04 coats a white base, albedo 0.96.
  const Material& plain = materialNamed(s, "materials[3]");
  expectVec(plain.albedo, glm::dvec3(0.96), 1e-7);
  expectVec(plain.specular, glm::dvec3(0.04), 1e-7);
  // A mesh per primitive, in the order the nodes place them (the parent's child first), each with
  // the material the file gives it.
  ASSERT_EQ(s.meshes.size(), 4u);
  EXPECT_EQ(s.materials[s.meshes[0].material].name, "emitter");
  EXPECT_EQ(s.materials[s.meshes[1].material].name, "materials[3]");
  EXPECT_EQ(s.materials[s.meshes[2].material].name, "metal");
  EXPECT_EQ(s.materials[s.meshes[3].material].name, "lambert");
  EXPECT_EQ(s.meshes[1].triangles.size(), 1u);                  // a strip of 3 vertices
  expectVec(s.meshes[0].positions[1], {12.0 + 2.0, 4.0, 6.0});  // (1, 0, 0) in the bulb's node
}

TEST(GltfScene, LightsInRadiometricUnitsPlacedByTheirNodes) {
  const Scene s = loadScene(authoredGltf());
  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_FALSE(s.defaultLights);
  // 683 cd of colour (1, 0.5, 0.25) is (1, 0.5, 0.25) W/sr; the node is at parent * (1, 2, 3)
  // with the parent's translation 10 and scale 2.
  const Light& point = s.lights[0];
  EXPECT_EQ(point.type, Light::Type::point);
  expectVec(point.intensity, {1.0, 0.5, 0.25}, 1e-6);
  expectVec(point.position, {12.0, 4.0, 6.0});
  // Turned -90 degrees about x, the spot's -z axis points down; the hard edge passing the flux of
  // glTF's fade from 0 to 60 degrees is at acos(1 - (1 - 0.5) / 3).
  const Light& spot = s.lights[1];
  EXPECT_EQ(spot.type, Light::Type::spot);
  expectVec(spot.direction, {0.0, -1.0, 0.0}, 1e-7);
  expectVec(spot.position, {0.0, 4.0, 0.0}, 1e-7);
  EXPECT_NEAR(spot.spotAngleDeg, 2.0 * std::acos(1.0 - 0.5 / 3.0) * 180.0 / std::numbers::pi, 1e-4);
  expectVec(spot.intensity, glm::dvec3(2.0), 1e-6);
  // 1366 lux is an irradiance of 2 W/m^2, travelling along the node's -z.
  const Light& sun = s.lights[2];
  EXPECT_EQ(sun.type, Light::Type::directional);
  expectVec(sun.intensity, glm::dvec3(2.0), 1e-6);
  expectVec(sun.direction, {0.0, 0.0, -1.0});
}

TEST(GltfScene, FirstCameraOrTheOneNamed) {
  const std::string file = authoredGltf();
  const Scene s = loadScene(file);
  expectVec(s.camera.position, {0.0, 1.0, 5.0});
  expectVec(glm::normalize(s.camera.lookAt - s.camera.position), {0.0, 0.0, -1.0});
  expectVec(s.camera.up, {0.0, 1.0, 0.0});
  EXPECT_NEAR(s.camera.fovYDeg, 0.5 * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_EQ(s.camera.width, 256);
  EXPECT_EQ(s.camera.height, 128);  // aspect ratio 2
  // "Side": a matrix whose -z column is (-1, 0, 0) at (7, 1, 0); no aspect ratio: square.
  const Scene side = loadScene(file, {.camera = "Side"});
  expectVec(side.camera.position, {7.0, 1.0, 0.0});
  expectVec(glm::normalize(side.camera.lookAt - side.camera.position), {-1.0, 0.0, 0.0});
  EXPECT_EQ(side.camera.height, side.camera.width);
  try {
    loadScene(file, {.camera = "Top"});
    ADD_FAILURE() << "an unknown camera loaded";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 (file + ": --camera: no camera 'Top' in its mesh files (they have 'Main', 'Side')")
                     .c_str());
  }
}

TEST(GltfScene, SceneFileMovesOrReplacesTheFilesLightsAndCamera) {
  authoredGltf();
  const auto load = [](const std::string& extra, const SceneLoadOptions& options = {}) {
    return loadScene(writeTemp("with_gltf.json", R"({"meshes": [{"file": "authored.gltf",
      "transform": {"translate": [0, 0, -100]}}])" + extra +
                                                     "}"),
                     options);
  };
  const Scene moved = load("");
  ASSERT_EQ(moved.lights.size(), 3u);
  expectVec(moved.lights[0].position, {12.0, 4.0, -94.0});
  expectVec(moved.camera.position, {0.0, 1.0, -95.0});
  const std::string camera =
      R"(, "camera": {"position": [0, 0, 9], "look_at": [0, 0, 0]}, "lights": [])";
  const Scene replaced = load(camera);
  EXPECT_TRUE(replaced.lights.empty());
  expectVec(replaced.camera.position, {0.0, 0.0, 9.0});
  EXPECT_FALSE(replaced.unlit());  // the emitter lights it
  // --camera picks a file's camera over the scene file's.
  expectVec(load(camera, {.camera = "Side"}).camera.position, {7.0, 1.0, -100.0});
}

TEST(GltfScene, BareModelWithoutLightGetsTheDefaultLights) {
  const std::string gltf =
      writeTemp("bare.gltf", std::string(R"({"asset":{"version":"2.0"},"scenes":[{"nodes":[0]}],
    "nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)") +
                                 kTriangle + "}");
  for (const std::string& file : {gltf, sourcePath("scenes/bunny.obj")}) {
    const Scene s = loadScene(file);
    EXPECT_FALSE(s.unlit()) << file;
    ASSERT_EQ(s.lights.size(), 2u) << file;
    EXPECT_TRUE(s.defaultLights);
    // The key light falls on the side the camera sees, from above.
    const glm::dvec3 view = s.camera.lookAt - s.camera.position;
    EXPECT_GT(glm::dot(s.lights[0].direction, view), 0.0);
    EXPECT_LT(glm::dot(s.lights[0].direction, s.camera.up), 0.0);
    EXPECT_TRUE(s.lights[0].castsShadows);
  }
  // A material default in Assimp's sense (no material) is voxgi's default, albedo 0.8.
  expectVec(loadScene(gltf).materials.at(0).albedo, glm::dvec3(0.8), 1e-7);
}

TEST(GltfScene, ASceneFileWithoutLightIsUnlitAndStaysSo) {
  writeTemp("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const Scene s = loadScene(writeTemp("dark.json", R"({"meshes": [{"file": "tri.obj"}]})"));
  EXPECT_TRUE(s.unlit());
  EXPECT_TRUE(s.lights.empty());
  EXPECT_FALSE(s.defaultLights);
}

TEST(GltfScene, BadFieldsAreNamed) {
  const auto errorOf = [](const std::string& json) {
    try {
      loadScene(writeTemp("bad.gltf", json));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(
      errorOf(R"({"asset":{"version":"1.0"},"buffers":{}})").find("glTF 1.0 is not supported"),
      std::string::npos);
  EXPECT_NE(errorOf(R"({"buffers":{}})").find("asset.version: glTF 1.0 is not supported"),
            std::string::npos);
  const std::string head =
      R"({"asset":{"version":"2.0"},"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)" +
      std::string(kTriangle) + ",";
  EXPECT_NE(errorOf(head + R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0,"children":[0]}]})")
                .find("nodes[0]: is reached twice"),
            std::string::npos);
  EXPECT_NE(errorOf(head + R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0,
      "extensions":{"KHR_lights_punctual":{"light":0}}}],
      "extensions":{"KHR_lights_punctual":{"lights":[{"type":"area"}]}}})")
                .find("extensions.KHR_lights_punctual.lights[0].type: must be point, spot or "
                      "directional, got 'area'"),
            std::string::npos);
  EXPECT_NE(errorOf(head + R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0,"camera":3}]})")
                .find("nodes[0].camera: must name one of 0"),
            std::string::npos);
  EXPECT_NE(errorOf(head + R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
      "materials":[{"emissiveFactor":[2,0,0]}]})")
                .find("materials[0].emissiveFactor[0]: must be in [0, 1], got 2"),
            std::string::npos);
  // A file's lights and cameras meet the scene format's bounds, as a scene file's do.
  const std::string lit = head + R"("scenes":[{"nodes":[0,1]}],"nodes":[{"mesh":0},
      {"translation":[0,0,T],"extensions":{"KHR_lights_punctual":{"light":0}}}],
      "extensions":{"KHR_lights_punctual":{"lights":[{"type":"point","intensity":I}]}}})";
  const auto with = [&](const std::string& t, const std::string& i) {
    std::string json = lit;
    json.replace(json.find("T]"), 1, t);
    json.replace(json.find(":I}"), 2, ":" + i);
    return json;
  };
  EXPECT_EQ(errorOf(with("1", "683e12")), "");
  EXPECT_NE(errorOf(with("1", "684e12"))
                .find("extensions.KHR_lights_punctual.lights[0]: color x intensity / 683 must be "
                      "at most 1e12"),
            std::string::npos);
  EXPECT_NE(errorOf(with("2e15", "1"))
                .find("extensions.KHR_lights_punctual.lights[0]: its node places it beyond 1e15"),
            std::string::npos);
  EXPECT_NE(errorOf(head + R"("scenes":[{"nodes":[0,1]}],"nodes":[{"mesh":0},
      {"translation":[0,0,-2e15],"camera":0}],
      "cameras":[{"type":"perspective","perspective":{"yfov":0.5}}]})")
                .find("cameras[0]: its node places it beyond 1e15"),
            std::string::npos);
}

TEST(GltfScene, MetallicRoughnessConservesEnergy) {
  for (float metallic : {0.0f, 0.3f, 1.0f})
    for (float base : {0.0f, 0.5f, 1.0f})
      for (float f0 : {0.0f, 0.04f, 1.0f}) {
        const Material m =
            metallicRoughnessMaterial(glm::vec3(base), metallic, 0.5f, glm::vec3(f0));
        EXPECT_LE(m.albedo.x + m.specular.x, 1.0f + 1e-6f) << metallic << " " << base << " " << f0;
      }
  EXPECT_EQ(metallicRoughnessMaterial(glm::vec3(1), 1, 0, glm::vec3(0.04f)).shininess, 1e6f);
}

// The glTF Asset Generator's Mesh_PrimitiveMode cases (in Debian's assimp-testmodels): the same
// unit square facing +z as a strip, a fan and triangles, each with and without indices. Every
// triangle mode must give its area, 1, with every triangle wound towards +z; points and lines have
// no triangles, so the file is refused.
TEST(GltfScene, AssetGeneratorPrimitiveModes) {
  const std::filesystem::path dir =
      "/usr/share/assimp/models/glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode";
  if (!std::filesystem::is_directory(dir))
    GTEST_SKIP() << dir << " is absent: apt-get install assimp-testmodels";
  // Modes by file: 00-03 and 07-10 points and lines; 04/11 strip, 05/12 fan, 06/13-15 triangles.
  for (int i = 0; i <= 15; ++i) {
    const std::string file = (dir / ("Mesh_PrimitiveMode_" + std::string(i < 10 ? "0" : "") +
                                     std::to_string(i) + ".gltf"))
                                 .string();
    const bool triangles = (i >= 4 && i <= 6) || i >= 11;
    if (!triangles) {
      EXPECT_THROW(loadScene(file), InputError) << file;
      continue;
    }
    const Scene s = loadScene(file);
    double area = 0.0;
    for (const Mesh& m : s.meshes)
      for (const glm::uvec3& t : m.triangles) {
        const glm::dvec3 n =
            glm::cross(m.positions[t.y] - m.positions[t.x], m.positions[t.z] - m.positions[t.x]);
        EXPECT_GT(n.z, 0.0) << file;
        area += 0.5 * glm::length(n);
      }
    EXPECT_NEAR(area, 1.0, 1e-6) << file;
  }
}

// An OBJ's emission (MTL Ke) makes it its own light: no default lights.
TEST(GltfScene, ObjEmissionIsALight) {
  writeTemp("glow.mtl", "newmtl glow\nKd 0.5 0.5 0.5\nKe 2 1 0.5\n");
  const Scene s = loadScene(
      writeTemp("glow.obj", "mtllib glow.mtl\nusemtl glow\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  expectVec(materialNamed(s, "glow").emission, {2.0, 1.0, 0.5}, 1e-7);
  EXPECT_FALSE(s.unlit());
  EXPECT_TRUE(s.lights.empty());
  EXPECT_FALSE(s.defaultLights);
}

}  // namespace
}  // namespace voxgi::test
