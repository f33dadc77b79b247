#include "common/scene_io/gltf_authored.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "common/error.h"

namespace voxgi {
namespace {

using nlohmann::json;

// A glTF JSON value with its path ("materials[2].emissiveFactor"), for messages.
struct GltfValue {
  const std::string& file;
  const json* value;  // null: absent
  std::string path;

  [[noreturn]] void fail(const std::string& reason) const { throw InputError(file, path, reason); }
  bool present() const { return value != nullptr; }
  GltfValue member(const char* key) const {
    const std::string child = path.empty() ? key : path + "." + key;
    if (value == nullptr) return {file, nullptr, child};
    if (!value->is_object()) fail("must be an object");
    const auto it = value->find(key);
    return {file, it == value->end() ? nullptr : &*it, child};
  }
  size_t size() const {
    if (value == nullptr) return 0;
    if (!value->is_array()) fail("must be an array");
    return value->size();
  }
  GltfValue at(size_t i) const {
    return {file, &value->at(i), path + "[" + std::to_string(i) + "]"};
  }
  double number(double fallback, double lo, double hi) const {
    if (value == nullptr) return fallback;
    if (!value->is_number()) fail("must be a number");
    const double d = value->get<double>();
    if (!(d >= lo && d <= hi)) {
      std::ostringstream s;
      s << "must be in [" << lo << ", " << hi << "], got " << d;
      fail(s.str());
    }
    return d;
  }
  size_t index(size_t count) const {
    if (!value->is_number_unsigned() || value->get<uint64_t>() >= count)
      fail("must name one of " + std::to_string(count));
    return size_t(value->get<uint64_t>());
  }
  // `n` numbers in [lo, hi], or `fallback` when absent.
  template <int N>
  glm::vec<N, double> numbers(glm::vec<N, double> fallback, double lo, double hi) const {
    if (value == nullptr) return fallback;
    if (!value->is_array() || value->size() < size_t(N))
      fail("must be an array of " + std::to_string(N) + " numbers");
    glm::vec<N, double> out;
    for (int i = 0; i < N; ++i) out[i] = at(size_t(i)).number(0.0, lo, hi);
    return out;
  }
  std::string string() const {
    if (value == nullptr) return {};
    if (!value->is_string()) fail("must be a string");
    return value->get<std::string>();
  }
};

constexpr double kGltfHuge = 1e30;  // a bound on factors and coordinates before voxgi's own checks

Material gltfMaterial(const GltfValue& m, size_t i) {
  const GltfValue pbr = m.member("pbrMetallicRoughness");
  const glm::dvec4 base = pbr.member("baseColorFactor").numbers<4>(glm::dvec4(1.0), 0.0, 1.0);
  const double metallic = pbr.member("metallicFactor").number(1.0, 0.0, 1.0);
  const double roughness = pbr.member("roughnessFactor").number(1.0, 0.0, 1.0);
  const GltfValue extensions = m.member("extensions");
  const GltfValue specular = extensions.member("KHR_materials_specular");
  const double specularFactor = specular.member("specularFactor").number(1.0, 0.0, 1.0);
  const glm::dvec3 specularColor =
      specular.member("specularColorFactor").numbers<3>(glm::dvec3(1.0), 0.0, kGltfHuge);
  // KHR_materials_ior (1.5 by default, F0 = 0.04; 0 stands for infinity, a reflectance of 1) and
  // KHR_materials_specular: min(F0(ior) * specularColorFactor, 1) * specularFactor.
  const double ior =
      extensions.member("KHR_materials_ior").member("ior").number(1.5, 0.0, kGltfHuge);
  if (ior > 0.0 && ior < 1.0)
    extensions.member("KHR_materials_ior").member("ior").fail("must be 0 or at least 1");
  const double f0Ior = ior == 0.0 ? 1.0 : ((ior - 1.0) / (ior + 1.0)) * ((ior - 1.0) / (ior + 1.0));
  const glm::dvec3 f0 = glm::min(f0Ior * specularColor, 1.0) * specularFactor;
  Material out =
      metallicRoughnessMaterial(glm::vec3(base), float(metallic), float(roughness), glm::vec3(f0));
  const double strength = extensions.member("KHR_materials_emissive_strength")
                              .member("emissiveStrength")
                              .number(1.0, 0.0, kGltfHuge);
  out.emission =
      glm::vec3(strength * m.member("emissiveFactor").numbers<3>(glm::dvec3(0.0), 0.0, 1.0));
  out.name = m.member("name").string();
  if (out.name.empty()) out.name = "materials[" + std::to_string(i) + "]";
  return out;
}

// A textureInfo (baseColorTexture, emissiveTexture): its texture, which must read TEXCOORD_0 (voxgi
// keeps one set of texture coordinates per mesh).
std::optional<size_t> textureInfo(const GltfValue& info, size_t textures) {
  if (!info.present()) return std::nullopt;
  if (info.member("texCoord").number(0.0, 0.0, kGltfHuge) != 0.0)
    info.member("texCoord").fail("voxgi reads TEXCOORD_0 only");
  return info.member("index").index(textures);
}

GltfMaterialTextures gltfMaterialTextures(const GltfValue& m, size_t textures) {
  return {textureInfo(m.member("pbrMetallicRoughness").member("baseColorTexture"), textures),
          textureInfo(m.member("emissiveTexture"), textures)};
}

// glTF's wrap modes (the GL enums) as texture_kernel.h's.
uint32_t wrapMode(const GltfValue& v) {
  const double mode = v.number(10497.0, 0.0, kGltfHuge);
  if (mode == 10497.0) return shared::kWrapRepeat;
  if (mode == 33071.0) return shared::kWrapClamp;
  if (mode == 33648.0) return shared::kWrapMirror;
  v.fail("must be 10497 (repeat), 33071 (clamp to edge) or 33648 (mirrored repeat)");
}

GltfTexture gltfTexture(const GltfValue& t, size_t images, const GltfValue& samplers) {
  const GltfValue source = t.member("source");
  if (!source.present())
    t.fail("has no source image (voxgi reads PNG and JPEG images, no extension formats)");
  GltfTexture out{source.index(images), shared::kWrapRepeat, shared::kWrapRepeat};
  const GltfValue sampler = t.member("sampler");
  if (sampler.present()) {
    const GltfValue s = samplers.at(sampler.index(samplers.size()));
    out.wrapS = wrapMode(s.member("wrapS"));
    out.wrapT = wrapMode(s.member("wrapT"));
  }
  return out;
}

// Where a node puts a light or camera: within voxgi's bound on positions (docs/scene-format.md).
void checkPlacedPoint(const GltfValue& what, const glm::dmat4& toWorld) {
  const glm::dvec3 p(toWorld * glm::dvec4(0.0, 0.0, 0.0, 1.0));
  if (!(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) <= kMaxCoordinate))
    what.fail("its node places it beyond 1e15 of the origin (after the scene's transform)");
}

Light gltfLight(const GltfValue& l, const glm::dmat4& toWorld) {
  Light out;
  const std::string type = l.member("type").string();
  const std::optional<Light::Type> kind = lightType(type);
  if (!kind) l.member("type").fail("must be point, spot or directional, got '" + type + "'");
  out.type = *kind;
  const glm::dvec3 color = l.member("color").numbers<3>(glm::dvec3(1.0), 0.0, kGltfHuge);
  const double intensity = l.member("intensity").number(1.0, 0.0, kGltfHuge);
  const glm::dvec3 radiometric = color * intensity / kLumensPerWatt;
  if (std::max({radiometric.x, radiometric.y, radiometric.z}) > kMaxLightIntensity)
    l.fail("color x intensity / 683 must be at most 1e12 (voxgi's bound on a light's intensity)");
  out.intensity = glm::vec3(radiometric);
  checkPlacedPoint(l, toWorld);
  // A light shines along its node's -z.
  if (!placeLightAtNode(out, toWorld)) l.fail("its node's transform has no -z axis (scale 0)");
  if (out.type == Light::Type::spot) {
    const GltfValue spot = l.member("spot");
    const double half = std::numbers::pi / 2.0;
    const double outer = spot.member("outerConeAngle").number(std::numbers::pi / 4.0, 0.0, half);
    const double inner = spot.member("innerConeAngle").number(0.0, 0.0, half);
    if (!(inner < outer)) spot.fail("innerConeAngle must be less than outerConeAngle");
    // glTF's edge fades as the square of a ramp in cos between the two angles; voxgi's spot has a
    // hard edge, put where it passes the same flux: 1 - cos(edge) = (1 - ci) + (ci - co) / 3.
    const double ci = std::cos(inner), co = std::cos(outer);
    const double edge = std::acos(ci - (ci - co) / 3.0);
    out.spotAngleDeg = float(std::clamp(2.0 * edge * 180.0 / std::numbers::pi, 1e-3, 179.9));
  }
  return out;
}

// A perspective camera looking down its node's -z with +y up; nullopt for an orthographic one.
std::optional<Camera> gltfCamera(const GltfValue& c, const glm::dmat4& toWorld) {
  const std::string type = c.member("type").string();
  if (type == "orthographic") return std::nullopt;
  if (type != "perspective") c.member("type").fail("must be perspective or orthographic");
  const GltfValue p = c.member("perspective");
  if (!p.present()) p.fail("missing (a perspective camera needs it)");
  Camera out;
  const double yfov = p.member("yfov").number(-1.0, 1e-5, std::numbers::pi * 179.0 / 180.0);
  if (yfov < 0.0) p.member("yfov").fail("missing (this field is required)");
  out.fovYDeg = yfov * 180.0 / std::numbers::pi;
  const double aspect = p.member("aspectRatio").number(1.0, 1.0 / 16384.0, 16384.0);
  out.width = 256;
  out.height = int(std::clamp(std::lround(256.0 / aspect), 1l, 16384l));
  checkPlacedPoint(c, toWorld);
  if (!placeCameraAtNode(out, toWorld))
    c.fail("its node's transform has no view direction and up (a scale of 0 or a shear)");
  return out;
}

// A node's own transform: its matrix, or its translation, rotation and scale (kept apart, for an
// animation to key).
NodeMotion nodeTransform(const GltfValue& node) {
  NodeMotion n;
  const GltfValue matrix = node.member("matrix");
  if (matrix.present()) {
    if (matrix.size() != 16) matrix.fail("must be an array of 16 numbers");
    for (int i = 0; i < 16; ++i)
      glm::value_ptr(n.rest)[i] = matrix.at(size_t(i)).number(0, -kGltfHuge, kGltfHuge);
    return n;  // column-major in both glTF and glm
  }
  n.translate = node.member("translation").numbers<3>(glm::dvec3(0.0), -kGltfHuge, kGltfHuge);
  const glm::dvec4 r = node.member("rotation").numbers<4>(glm::dvec4(0, 0, 0, 1), -1.0, 1.0);
  n.scale = node.member("scale").numbers<3>(glm::dvec3(1.0), -kGltfHuge, kGltfHuge);
  const glm::dquat q(r.w, r.x, r.y, r.z);  // glTF stores x, y, z, w; glm takes w first
  const double length = glm::length(q);
  if (!(length > 0.0)) node.member("rotation").fail("must be a non-zero quaternion");
  n.rotation = glm::mat3_cast(q / length);
  n.rest = glm::translate(glm::dmat4(1.0), n.translate) * glm::mat4_cast(q / length) *
           glm::scale(glm::dmat4(1.0), n.scale);
  return n;
}

}  // namespace

Material metallicRoughnessMaterial(const glm::vec3& baseColor, float metallic, float roughness,
                                   const glm::vec3& dielectricF0) {
  Material m;
  // The non-metallic part is Lambertian under a Fresnel coat of reflectance F0; the metallic part
  // reflects the base colour. Each channel's albedo + specular stays <= 1.
  m.albedo = baseColor * (1.0f - metallic) * (1.0f - dielectricF0);
  m.specular = glm::mix(dielectricF0, baseColor, metallic);
  // GGX's alpha = roughness^2 taken as Beckmann's, and the Phong exponent with the same highlight
  // [Walter et al. 2007, §5.2]: n = 2 / alpha^2 - 2; at least 1 (a cosine lobe for the roughest),
  // at most the scene format's 10^6 (a mirror).
  const double alpha = double(roughness) * double(roughness);
  const double n = alpha > 0.0 ? 2.0 / (alpha * alpha) - 2.0 : 1e6;
  m.shininess = float(std::clamp(n, 1.0, 1e6));
  return m;
}

GltfAuthored readGltfAuthored(const std::string& path, const json& doc,
                              const glm::dmat4& transform) {
  const GltfValue root{path, &doc, ""};
  // An extension a file requires changes what its data means (compressed meshes, quantized
  // positions): one voxgi does not read is refused rather than rendered wrong.
  const GltfValue required = root.member("extensionsRequired");
  for (size_t i = 0; i < required.size(); ++i) {
    const std::string name = required.at(i).string();
    if (name != "KHR_lights_punctual" && name != "KHR_materials_emissive_strength" &&
        name != "KHR_materials_specular" && name != "KHR_materials_ior")
      required.at(i).fail("the file requires " + name + ", which voxgi does not support");
  }
  GltfAuthored out;
  const GltfValue materials = root.member("materials");
  const GltfValue textures = root.member("textures");
  for (size_t i = 0; i < materials.size(); ++i) {
    out.materials.push_back(gltfMaterial(materials.at(i), i));
    out.materialTextures.push_back(gltfMaterialTextures(materials.at(i), textures.size()));
  }
  for (size_t i = 0; i < textures.size(); ++i)
    out.textures.push_back(
        gltfTexture(textures.at(i), root.member("images").size(), root.member("samplers")));

  const GltfValue lights = root.member("extensions").member("KHR_lights_punctual").member("lights");
  const GltfValue cameras = root.member("cameras");
  const GltfValue nodes = root.member("nodes");
  const GltfValue scenes = root.member("scenes");
  if (scenes.size() == 0) return out;  // no scene: Assimp places nothing either
  const GltfValue sceneIndex = root.member("scene");
  const size_t scene = sceneIndex.present() ? sceneIndex.index(scenes.size()) : 0;

  // Depth first from the default scene's roots, as Assimp walks it. A node reached twice would
  // make the hierarchy a graph (glTF forbids it) and the walk endless.
  struct Item {
    size_t node;
    glm::dmat4 parent;
    std::vector<size_t> path;  // the node's ancestors, the root first
  };
  std::vector<Item> stack;
  const GltfValue roots = scenes.at(scene).member("nodes");
  for (size_t i = roots.size(); i-- > 0;)
    stack.push_back({roots.at(i).index(nodes.size()), transform, {}});
  std::vector<bool> visited(nodes.size(), false);
  out.nodes.resize(nodes.size());
  out.nodeMatrix.resize(nodes.size());
  while (!stack.empty()) {
    Item item = std::move(stack.back());
    stack.pop_back();
    const GltfValue node = nodes.at(item.node);
    if (visited[item.node]) node.fail("is reached twice (the node hierarchy must be a tree)");
    visited[item.node] = true;
    out.nodes[item.node] = nodeTransform(node);
    out.nodeMatrix[item.node] = node.member("matrix").present();
    const glm::dmat4 toWorld = item.parent * out.nodes[item.node].rest;
    item.path.push_back(item.node);
    const GltfValue light = node.member("extensions").member("KHR_lights_punctual").member("light");
    if (light.present()) {
      out.extras.lights.push_back(gltfLight(lights.at(light.index(lights.size())), toWorld));
      out.lightNodes.push_back(item.path);
    }
    const GltfValue mesh = node.member("mesh");
    if (mesh.present())
      out.meshes.push_back({mesh.index(root.member("meshes").size()), toWorld, item.path});
    const GltfValue camera = node.member("camera");
    if (camera.present()) {
      const GltfValue c = cameras.at(camera.index(cameras.size()));
      if (const std::optional<Camera> cam = gltfCamera(c, toWorld)) {
        std::string name = node.member("name").string();
        if (name.empty()) name = c.member("name").string();
        out.extras.cameras.push_back({name, *cam, {}});
        out.cameraNodes.push_back(item.path);
      }
    }
    const GltfValue children = node.member("children");
    for (size_t i = children.size(); i-- > 0;)
      stack.push_back({children.at(i).index(nodes.size()), toWorld, item.path});
  }
  return out;
}

}  // namespace voxgi
