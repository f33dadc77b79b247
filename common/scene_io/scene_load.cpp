// JSON scene files (docs/scene-format.md). Every field is checked; unknown fields are errors so
// that a typo does not silently fall back to a default.
#include "common/scene_io/scene_load.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/io/input_file.h"
#include "common/io/texture_read.h"
#include "common/scene_io/json_field.h"
#include "common/scene_io/motion_load.h"
#include "common/scene_io/point_cloud_ply.h"
#include "common/settings.h"

namespace voxgi {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// A material's texture (`albedo_texture`, `emission_texture`): a PNG or JPEG file relative to the
// scene file, sampled with `texture_wrap` on both axes (docs/textures.md).
uint32_t materialTexture(const Field& f, Scene& scene, uint32_t wrap) {
  const std::string image =
      (fs::path(scene.file).parent_path() / f.string()).lexically_normal().string();
  return scene.textures.texture(image, wrap, wrap,
                                [&] { return readTexture(image, f.file, f.path); });
}

void readMaterial(const Field& f, Material& m, Scene& scene) {
  f.allowKeys({"albedo", "specular", "shininess", "emission", "albedo_texture", "emission_texture",
               "texture_wrap"});
  if (f.has("albedo")) m.albedo = f.at("albedo").color(0.0, 1.0);
  if (f.has("specular")) m.specular = f.at("specular").color(0.0, 1.0);
  if (f.has("shininess")) m.shininess = static_cast<float>(f.at("shininess").number(0.0, 1e6));
  if (f.has("emission")) m.emission = f.at("emission").color(0.0, 1e9);
  uint32_t wrap = shared::kWrapRepeat;
  if (f.has("texture_wrap")) {
    const std::string w = f.at("texture_wrap").string();
    if (w == "clamp")
      wrap = shared::kWrapClamp;
    else if (w == "mirror")
      wrap = shared::kWrapMirror;
    else if (w != "repeat")
      f.at("texture_wrap").fail("must be \"repeat\", \"clamp\" or \"mirror\"");
  }
  if (f.has("albedo_texture"))
    m.albedoTexture = materialTexture(f.at("albedo_texture"), scene, wrap);
  if (f.has("emission_texture"))
    m.emissionTexture = materialTexture(f.at("emission_texture"), scene, wrap);
}

Light readLight(const Field& f) {
  f.allowKeys({"type", "position", "direction", "intensity", "spot_angle_deg", "falloff",
               "casts_shadows", "animation"});
  Light l;
  const std::string type = f.at("type").string();
  const std::optional<Light::Type> kind = lightType(type);
  if (!kind) f.at("type").fail("must be point, spot or directional, got '" + type + "'");
  l.type = *kind;
  if (l.type != Light::Type::directional) l.position = f.at("position").position();
  if (l.type != Light::Type::point) l.direction = f.at("direction").direction();
  l.intensity = f.at("intensity").color(0.0, kMaxLightIntensity);
  if (f.has("spot_angle_deg"))
    l.spotAngleDeg = static_cast<float>(f.at("spot_angle_deg").number(1e-3, 179.9));
  if (f.has("casts_shadows")) l.castsShadows = f.at("casts_shadows").boolean();
  if (f.has("falloff")) {
    const Field fo = f.at("falloff");
    if (fo.value.is_string()) {
      if (fo.string() != "inverse_square")
        fo.fail("must be \"inverse_square\" or {constant, linear, quadratic}");
    } else {
      fo.allowKeys({"constant", "linear", "quadratic"});
      l.falloff.kind = Falloff::Kind::polynomial;
      // Used in float: 0, or a normal float well above float's denormals (1e-45 would be 0 or
      // denormal there and divide the light by nothing).
      const auto coefficient = [&](const char* key) {
        const Field k = fo.at(key);
        const double v = k.number(0.0, 1e9);
        if (v != 0.0 && v < 1e-30) k.fail("must be 0 or at least 1e-30, got " + Field::fmt(v));
        return static_cast<float>(v);
      };
      l.falloff.constant = coefficient("constant");
      l.falloff.linear = coefficient("linear");
      l.falloff.quadratic = coefficient("quadratic");
      if (l.falloff.constant + l.falloff.linear + l.falloff.quadratic <= 0.0f)
        fo.fail("at least one coefficient must be positive");
    }
  }
  return l;
}

Camera readCamera(const Field& f) {
  f.allowKeys({"position", "look_at", "up", "fov_y_deg", "resolution", "animation"});
  Camera c;
  c.position = f.at("position").position();
  c.lookAt = f.at("look_at").position();
  if (f.has("up")) c.up = f.at("up").direction();
  // Compared in the float precision the camera is rendered in, relative to the distance.
  const glm::dvec3 view = c.lookAt - c.position;
  const double distance = glm::length(view);
  if (!(distance > 1e-6 * std::max({1.0, std::abs(c.position.x), std::abs(c.position.y),
                                    std::abs(c.position.z)})))
    f.at("look_at").fail("must differ from position by more than float precision");
  if (glm::length(glm::cross(view / distance, c.up)) < 1e-6)
    f.at("up").fail("must not be parallel to the viewing direction");
  if (f.has("fov_y_deg")) c.fovYDeg = f.at("fov_y_deg").number(1e-3, 179.0);
  if (f.has("resolution")) {
    const Field r = f.at("resolution");
    if (!r.value.is_array() || r.value.size() != 2) r.fail("must be [width, height]");
    c.width = r.at(0).integer(1, 16384);
    c.height = r.at(1).integer(1, 16384);
  }
  return c;
}

// "settings": {"bounce.count": 1, "mip.mode": "isotropic"}: each value (a number or a string)
// checked now, so a bad one fails at load time naming settings.KEY.
std::vector<std::string> readSettings(const Field& f) {
  if (!f.value.is_object()) f.fail("must be an object of parameter -> value");
  std::vector<std::string> out;
  Settings check;
  for (const auto& [key, v] : f.value.items()) {
    if (!v.is_string() && !v.is_number()) f.at(key).fail("must be a number or a string");
    out.push_back(key + "=" + (v.is_string() ? v.get<std::string>() : v.dump()));
    applySetting(check, out.back(), f.file, "settings.");
  }
  return out;
}

}  // namespace

int readResolution(const std::string& file, const std::string& field, int64_t n) {
  if (n < 1 || n > kMaxResolution || (n & (n - 1)) != 0)
    throw InputError(file, field,
                     "must be a power of two in [1, " + std::to_string(kMaxResolution) + "], got " +
                         std::to_string(n));
  return static_cast<int>(n);
}

namespace {

// A PLY whose header has vertices and no faces is a point cloud (a mesh file otherwise).
bool isPointCloudFile(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".ply") return false;
  return plyIsPointCloud(readPlyHeaderOfFile(path));
}

// The JSON material a mesh or cloud entry names in "material", if it has that field: one of the
// scene's first `named` materials (those of the file's "materials").
std::optional<uint32_t> namedMaterial(const Field& f, const Scene& scene, size_t named) {
  if (!f.has("material")) return std::nullopt;
  const std::string name = f.at("material").string();
  for (size_t k = 0; k < named; ++k)
    if (scene.materials[k].name == name) return static_cast<uint32_t>(k);
  f.at("material").fail("unknown material '" + name + "'");
}

// "point_clouds": [{"file", "material", "transform", "normals", "viewpoint", "colors"}].
PointCloudOptions readPointCloud(const Field& f, Scene& scene, size_t namedMaterials) {
  f.allowKeys({"file", "material", "transform", "normals", "viewpoint", "colors"});
  const Field file = f.at("file");
  const fs::path cloudPath = fs::path(f.file).parent_path() / file.string();
  try {
    requireInputFile(cloudPath.string(), "", "point cloud file");
    if (!isPointCloudFile(cloudPath.string()))
      throw InputError(cloudPath.string(), "", "not a point-cloud PLY (vertices and no faces)");
  } catch (const InputError& e) {
    file.fail(e.what());
  }
  PointCloudOptions options;
  if (f.has("normals")) {
    const std::string n = f.at("normals").string();
    if (n != "file" && n != "estimate") f.at("normals").fail("must be \"file\" or \"estimate\"");
    options.estimateNormals = n == "estimate";
  }
  if (f.has("viewpoint")) options.viewpoint = f.at("viewpoint").position();
  if (f.has("colors")) {
    const std::string c = f.at("colors").string();
    if (c == "srgb")
      options.colors = PointCloudOptions::Colors::srgb;
    else if (c == "linear")
      options.colors = PointCloudOptions::Colors::linear;
    else if (c == "ignore")
      options.colors = PointCloudOptions::Colors::ignore;
    else
      f.at("colors").fail("must be \"srgb\", \"linear\" or \"ignore\"");
  }
  const std::optional<uint32_t> named = namedMaterial(f, scene, namedMaterials);
  const uint32_t material = named ? *named : defaultMaterial(scene);
  const glm::dmat4 transform =
      f.has("transform") ? readTransformFields(f.at("transform")).matrix() : glm::dmat4(1.0);
  importPointCloud(scene, cloudPath.string(), transform, material, options);
  return options;
}

}  // namespace

uint32_t defaultMaterial(Scene& scene) {
  for (size_t k = 0; k < scene.materials.size(); ++k)
    if (scene.materials[k].name == "default") return static_cast<uint32_t>(k);
  scene.materials.push_back(Material{.name = "default"});
  return static_cast<uint32_t>(scene.materials.size() - 1);
}

void checkGrid(const Scene& scene, const std::string& source) {
  const GridSpec& g = scene.grid;
  const double h = g.voxelSize();
  if (!(h >= kMinVoxelSize && h <= kMaxVoxelSize))
    throw InputError(source, "grid.size",
                     "gives voxels of " + Field::fmt(h) +
                         " (size / resolution); they must be in [" + Field::fmt(kMinVoxelSize) +
                         ", " + Field::fmt(kMaxVoxelSize) + "] scene units");
  for (int c = 0; c < 3; ++c)
    if (!(std::abs(g.min[c]) <= 1e15))
      throw InputError(source, "grid.min", "must lie within 1e15 of the origin");
}

void validateGeometry(const Scene& scene) {
  // Materials from mesh files are checked here; JSON ones were checked field by field.
  for (const Material& m : scene.materials)
    for (int c = 0; c < 3; ++c) {
      auto check = [&](float v, float hi, const char* field) {
        if (!(v >= 0.0f && v <= hi))
          throw InputError(scene.file, "material '" + m.name + "'." + field,
                           "must be in [0, " + Field::fmt(hi) + "], got " + Field::fmt(v));
      };
      check(m.albedo[c], 1.0f, "albedo");
      check(m.specular[c], 1.0f, "specular");
      check(m.emission[c], 1e9f, "emission");
    }
  for (const Mesh& m : scene.meshes) {
    // The scene file first, then the mesh (a bare mesh file is the scene file itself).
    const std::string mesh =
        m.name.starts_with(scene.file + ": ") ? m.name.substr(scene.file.size() + 2) : m.name;
    const auto fail = [&](const std::string& what, const std::string& reason) {
      throw InputError(scene.file, mesh + ", " + what, reason);
    };
    for (size_t v = 0; v < m.positions.size(); ++v) {
      const glm::dvec3& p = m.positions[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        fail("vertex " + std::to_string(v), "coordinate is NaN or infinite");
      if (std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) > kMaxCoordinate)
        fail("vertex " + std::to_string(v), "lies beyond " + Field::fmt(kMaxCoordinate) +
                                                " of the origin (after the scene's transform)");
    }
    if (!m.texcoords.empty() && m.texcoords.size() != m.positions.size())
      fail("texture coordinates", std::to_string(m.texcoords.size()) + " for " +
                                      std::to_string(m.positions.size()) + " vertices");
    // Within kMaxTexcoord, interpolated coordinates stay finite and wrap without overflow.
    for (size_t v = 0; v < m.texcoords.size(); ++v)
      if (!(std::abs(m.texcoords[v].x) <= kMaxTexcoord &&
            std::abs(m.texcoords[v].y) <= kMaxTexcoord))
        fail("vertex " + std::to_string(v),
             "texture coordinate is NaN, infinite or beyond " + Field::fmt(kMaxTexcoord));
    for (size_t t = 0; t < m.triangles.size(); ++t)
      for (int c = 0; c < 3; ++c)
        if (m.triangles[t][c] >= m.positions.size())
          fail("triangle " + std::to_string(t), "vertex index out of range");
    if (m.material >= scene.materials.size()) fail("material", "index out of range");
  }
  for (const PointCloud& c : scene.pointClouds) {
    for (size_t v = 0; v < c.size(); ++v)
      if (std::max({std::abs(c.positions[v].x), std::abs(c.positions[v].y),
                    std::abs(c.positions[v].z)}) > kMaxCoordinate)
        throw InputError(c.name, "vertex " + std::to_string(v),
                         "lies beyond " + Field::fmt(kMaxCoordinate) +
                             " of the origin (after the scene's transform)");
    if (c.material >= scene.materials.size())
      throw InputError(c.name, "material", "index out of range");
  }
}

namespace {

// The camera `options` name among `cameras` (the scene's mesh files'); nullopt when it names none
// and there are none to choose from. Throws InputError for a name that is not there.
const FileCamera* chosenCamera(const std::string& file, const std::vector<FileCamera>& cameras,
                               const SceneLoadOptions& options) {
  if (options.camera.empty()) return cameras.empty() ? nullptr : &cameras.front();
  std::string names;
  for (const FileCamera& c : cameras) {
    if (c.name == options.camera) return &c;
    names += (names.empty() ? "" : ", ") + ("'" + c.name + "'");
  }
  throw InputError(file, "--camera",
                   "no camera '" + options.camera + "' in its mesh files (" +
                       (names.empty() ? "they have none" : "they have " + names) + ")");
}

// The mesh files' lights (when the scene takes them) and chosen camera as the scene's, moving
// where an animation keys a node that places them.
void takeFileLightsAndCamera(Scene& scene, const MeshFileExtras& extras, bool lights,
                             const FileCamera* camera) {
  if (lights) {
    scene.lights = extras.lights;
    for (size_t i = 0; i < extras.lightPaths.size(); ++i)
      if (extras.lightPaths[i].keyed())
        scene.motion.lights.push_back({i, {}, {}, {}, extras.lightPaths[i]});
  }
  if (camera) {
    scene.camera = camera->camera;
    if (camera->path.keyed()) scene.motion.camera = CameraMotion{{}, {}, {}, camera->path};
  }
}

// The mesh motions of one file imported with `entry` (a scene file's mesh entry, keyed or not):
// each of its glTF meshes on its node path after the entry's node, the meshes of a file without
// node paths (OBJ, PLY) on the entry's node alone; kept where a node is keyed. A keyed mesh's rest
// transform must be invertible (it is moved from there).
void addMeshMotion(Scene& scene, const std::string& file, const MeshFileExtras& carried,
                   const NodeMotion& entry, size_t firstMesh) {
  std::vector<MeshMotion> motions = carried.meshPaths;
  if (motions.empty() && entry.keyed())
    motions.push_back({firstMesh, scene.meshes.size() - firstMesh, NodePath{{entry}}});
  for (MeshMotion& m : motions) {
    m.path.nodes.front() = entry;
    if (!m.path.keyed()) continue;
    const double det = glm::determinant(m.path.rest());
    if (!std::isfinite(det) || det == 0.0)
      throw InputError(file, "animation",
                       "a moving mesh's transform is singular where it is loaded (a scale of 0)");
    scene.motion.meshes.push_back(std::move(m));
  }
}

// A mesh or point-cloud file on its own: its geometry, materials, lights and camera, a 64^3 grid
// fitted to it, a camera looking at its centre when the file has none, and the default
// lights when nothing in it emits light.
Scene loadBareFile(const std::string& path, const SceneLoadOptions& options) {
  Scene scene;
  scene.file = path;
  requireInputFile(path, "", "mesh file");
  MeshFileExtras extras;
  if (isPointCloudFile(path)) {
    importPointCloud(scene, path, glm::dmat4(1.0), defaultMaterial(scene), {});
  } else {
    extras = importMeshFile(scene, path, glm::dmat4(1.0), std::nullopt);
  }
  validateGeometry(scene);
  scene.grid = fitGrid(scene.bounds(), 64);
  checkGrid(scene, path);
  const auto [lo, hi] = scene.bounds();
  const FileCamera* camera = chosenCamera(path, extras.cameras, options);
  takeFileLightsAndCamera(scene, extras, true, camera);
  addMeshMotion(scene, path, extras, NodeMotion{}, 0);
  if (!camera && lo.x <= hi.x) {
    // A three-quarter view from the front (+z), right and above: it sees a model that is flat in
    // any axis plane (one seen from +z alone is edge-on for the planes x or y = const).
    scene.camera.lookAt = 0.5 * (lo + hi);
    scene.camera.position =
        scene.camera.lookAt + glm::normalize(glm::dvec3(1.0, 1.0, 2.0)) * (2.0 * scene.grid.size);
  }
  if (scene.unlit()) addDefaultLights(scene);
  estimatePointCloudProperties(scene, std::vector<PointCloudOptions>(scene.pointClouds.size()));
  return scene;
}

json parseSceneFile(const std::string& path) {
  requireInputFile(path, "", "scene file");
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open scene file");
  try {
    return json::parse(in);
  } catch (const json::exception& e) {  // syntax errors, numbers beyond double (1e400)
    throw InputError(path, "", std::string("malformed JSON: ") + e.what());
  }
}

void readMaterials(const Field& root, Scene& scene) {
  if (!root.has("materials")) return;
  const Field mats = root.at("materials");
  if (!mats.value.is_object()) mats.fail("must be an object of name -> material");
  for (const auto& [name, v] : mats.value.items()) {
    Material m;
    m.name = name;
    readMaterial(mats.at(name), m, scene);
    scene.materials.push_back(m);
  }
}

// Each mesh file with its transform and material; a material of the file whose name matches one
// of the scene file's (the first `namedMaterials`) takes the scene file's values. Returns the
// files' lights and cameras, in the order of the files.
MeshFileExtras readMeshes(const Field& root, Scene& scene, size_t namedMaterials) {
  MeshFileExtras extras;
  if (!root.has("meshes") && !root.has("point_clouds")) root.at("meshes");  // names what is missing
  if (!root.has("meshes")) return extras;
  const Field meshes = root.at("meshes");
  if (!meshes.value.is_array()) meshes.fail("must be an array");
  for (size_t i = 0; i < meshes.value.size(); ++i) {
    const Field m = meshes.at(i);
    m.allowKeys({"file", "material", "transform", "animation"});
    const Field file = m.at("file");
    const fs::path meshPath = fs::path(scene.file).parent_path() / file.string();
    try {
      requireInputFile(meshPath.string(), "", "mesh file");
    } catch (const InputError& e) {
      file.fail(e.what());  // the scene file and field, then the mesh file and what is wrong
    }
    const std::optional<uint32_t> material = namedMaterial(m, scene, namedMaterials);
    NodeMotion entry =
        nodeMotion(m.has("transform") ? readTransformFields(m.at("transform")) : TransformFields{});
    if (m.has("animation")) readMeshMotion(m.at("animation"), entry);
    const size_t before = scene.materials.size();
    const size_t firstMesh = scene.meshes.size();
    MeshFileExtras carried = importMeshFile(scene, meshPath.string(), entry.rest, material);
    addMeshMotion(scene, scene.file, carried, entry, firstMesh);
    // The file's lights and cameras move with the entry too.
    for (NodePath& p : carried.lightPaths) p.nodes.front() = entry;
    for (FileCamera& c : carried.cameras) c.path.nodes.front() = entry;
    for (size_t k = before; k < scene.materials.size(); ++k)
      for (size_t j = 0; j < namedMaterials; ++j)
        if (scene.materials[k].name == scene.materials[j].name)
          scene.materials[k] = scene.materials[j];
    extras.lights.insert(extras.lights.end(), carried.lights.begin(), carried.lights.end());
    extras.cameras.insert(extras.cameras.end(), carried.cameras.begin(), carried.cameras.end());
    extras.lightPaths.insert(extras.lightPaths.end(), carried.lightPaths.begin(),
                             carried.lightPaths.end());
  }
  return extras;
}

// Calls read(element) for each element of the array `key`, if the scene file has it.
template <class Read>
void forEachOf(const Field& root, const char* key, Read read) {
  if (!root.has(key)) return;
  const Field array = root.at(key);
  if (!array.value.is_array()) array.fail("must be an array");
  for (size_t i = 0; i < array.value.size(); ++i) read(array.at(i));
}

// The grid the file gives (min, size and resolution), or one of its resolution (64 by default)
// fitted to the scene's bounds.
void readGrid(const Field& root, Scene& scene) {
  int resolution = 64;
  if (root.has("grid")) {
    const Field g = root.at("grid");
    g.allowKeys({"resolution", "min", "size"});
    if (g.has("resolution")) {
      const Field r = g.at("resolution");
      if (!r.value.is_number_integer()) r.fail("must be an integer");
      resolution = readResolution(scene.file, r.path, r.value.get<int64_t>());
    }
    if (g.has("min") != g.has("size")) g.fail("give both min and size, or neither");
    if (g.has("min")) {
      scene.grid.min = g.at("min").vec3();
      scene.grid.size = g.at("size").number();
      scene.grid.resolution = resolution;
      checkGrid(scene, scene.file);
      return;
    }
  }
  scene.grid = fitGrid(scene.bounds(), resolution);
  checkGrid(scene, scene.file);
}

// A scene file's JSON; `path` names it in errors, and relative file names are relative to its
// folder.
Scene loadSceneDocument(const json& doc, const std::string& path, const SceneLoadOptions& options) {
  Scene scene;
  scene.file = path;
  const Field root{path, doc, ""};
  root.allowKeys({"meshes", "point_clouds", "materials", "lights", "camera", "background", "grid",
                  "settings", "description"});
  readMaterials(root, scene);
  const size_t namedMaterials = scene.materials.size();
  const MeshFileExtras extras = readMeshes(root, scene, namedMaterials);
  std::vector<PointCloudOptions> cloudOptions;
  forEachOf(root, "point_clouds", [&](const Field& cloud) {
    cloudOptions.push_back(readPointCloud(cloud, scene, namedMaterials));
  });
  // The scene file's lights and camera replace its mesh files' (docs/scene-format.md, "glTF").
  if (root.has("lights"))
    forEachOf(root, "lights", [&](const Field& light) {
      if (light.has("animation"))
        scene.motion.lights.push_back(readLightMotion(light.at("animation"), scene.lights.size()));
      scene.lights.push_back(readLight(light));
    });
  const FileCamera* fileCamera = chosenCamera(path, extras.cameras, options);
  const bool takeFileCamera = fileCamera && (!options.camera.empty() || !root.has("camera"));
  if (root.has("camera")) scene.camera = readCamera(root.at("camera"));
  takeFileLightsAndCamera(scene, extras, !root.has("lights"),
                          takeFileCamera ? fileCamera : nullptr);
  if (!takeFileCamera && root.has("camera") && root.at("camera").has("animation"))
    scene.motion.camera = readCameraMotion(root.at("camera").at("animation"));
  if (root.has("background")) scene.background = root.at("background").color(0.0, 1e9);
  if (root.has("settings")) scene.settings = readSettings(root.at("settings"));
  validateGeometry(scene);
  estimatePointCloudProperties(scene, cloudOptions);
  readGrid(root, scene);
  return scene;
}

}  // namespace

Scene loadScene(const std::string& path, const SceneLoadOptions& options) {
  if (fs::path(path).extension().string() != ".json") return loadBareFile(path, options);
  return loadSceneDocument(parseSceneFile(path), path, options);
}

Scene loadSceneText(const std::string& text, const std::string& path,
                    const SceneLoadOptions& options) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    throw InputError(path, "", std::string("malformed JSON: ") + e.what());
  }
  return loadSceneDocument(doc, path, options);
}

void setImageWidth(Scene& scene, int width, const std::string& source) {
  if (width < 1 || width > 16384)
    throw InputError(source, "", "image width must be in [1, 16384], got " + std::to_string(width));
  const double aspect = double(scene.camera.height) / double(scene.camera.width);
  scene.camera.height = std::max(1, int(std::lround(double(width) * aspect)));
  scene.camera.width = width;
}

}  // namespace voxgi
