#include "common/light_terms.h"

#include "common/error.h"
#include "common/technique.h"
#include "shaders/shared/compose.h"

namespace voxgi {

std::string_view termName(LightTerm term) {
  switch (term) {
    case LightTerm::emission:
      return "emission";
    case LightTerm::direct:
      return "direct";
    case LightTerm::indirect_diffuse:
      return "indirect_diffuse";
    case LightTerm::indirect_specular:
      return "indirect_specular";
  }
  return "";
}

Image directOnly(const TermImages& terms) {
  Image out = termImage(terms, LightTerm::emission);
  const Image& direct = termImage(terms, LightTerm::direct);
  for (size_t e = 0; e < out.pixels.size(); ++e) out.pixels[e] += direct.pixels[e];
  return out;
}

std::optional<TermImages> techniqueTerms(const Technique& technique, const BufferSet& buffers,
                                         const Settings& settings, const Scene& scene) {
  using enum BufferId;
  if (!buffers.contains(common_gbuffer_object_id)) {
    // Only a dark plan (EffectPlan::dark) runs no gbuffer: nothing emits light, every term is
    // black.
    TermImages black;
    for (Image& image : black) image = Image(scene.camera.width, scene.camera.height);
    return black;
  }
  const LightTermBuffers ids = technique.lightTerms(settings);
  // A buffer the technique has and its plan produced, or nullptr.
  const auto find = [&](std::optional<BufferId> id) { return id ? buffers.find(*id) : nullptr; };
  const Buffer *directDiffuse = find(ids.directDiffuse), *directSpecular = find(ids.directSpecular),
               *indirectDiffuse = find(ids.indirectDiffuse),
               *indirectSpecular = find(ids.indirectSpecular),
               *ambient = find(ids.ambientOcclusion);
  if (indirectDiffuse == nullptr) return std::nullopt;
  const Buffer& objectId = buffers.at(common_gbuffer_object_id);
  const Buffer *albedo = buffers.find(common_gbuffer_pixel_albedo),
               *specular = buffers.find(common_gbuffer_pixel_specular),
               *emission = buffers.find(common_gbuffer_pixel_emission);
  const int w = objectId.extent.x, h = objectId.extent.y;
  TermImages terms;
  for (Image& image : terms) image = Image(w, h);
  const glm::vec3 zero(0.0f);
  for (size_t e = 0; e < size_t(w) * size_t(h); ++e) {
    const uint32_t id = objectId.get<uint32_t>(e, 0);
    const glm::vec3 a = vec3AtOr0(albedo, e), s = vec3AtOr0(specular, e);
    const float ao = ambient == nullptr ? 0.0f : ambient->get<float>(e, 0);
    // Each term is the composition with the other terms' inputs at zero.
    termImage(terms, LightTerm::emission).pixels[e] = shared::composePixel(
        id, zero, zero, vec3AtOr0(emission, e), zero, zero, zero, zero, 0.0f, scene.background);
    termImage(terms, LightTerm::direct).pixels[e] =
        shared::composePixel(id, a, s, zero, vec3AtOr0(directDiffuse, e),
                             vec3AtOr0(directSpecular, e), zero, zero, 0.0f, zero);
    termImage(terms, LightTerm::indirect_diffuse).pixels[e] = shared::composePixel(
        id, a, s, zero, zero, zero, vec3AtOr0(indirectDiffuse, e), zero, ao, zero);
    termImage(terms, LightTerm::indirect_specular).pixels[e] = shared::composePixel(
        id, a, s, zero, zero, zero, zero, vec3AtOr0(indirectSpecular, e), 0.0f, zero);
  }
  return terms;
}

}  // namespace voxgi
