// The terms a rendered image splits into, for the error budget (docs/accuracy.md, "Error
// budget"): every renderer's image is their sum, and each term is measured against the same term
// of the path-traced reference. Direct light comes straight from a light source (a point, spot or
// directional light, or an emissive surface) to the first visible surface; indirect light was
// reflected at least once more, or comes from the background, and is split by the first surface's
// lobe that reflects it. A cone tracer with emitters.mode=voxels gathers the emissive surfaces'
// direct light with its diffuse cones, so its indirect diffuse term holds it: the budget shows that
// as light missing from the direct term and added to the indirect one.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "common/buffer.h"
#include "common/image.h"
#include "common/scene.h"
#include "common/settings.h"

namespace voxgi {

struct Technique;

enum class LightTerm { emission, direct, indirect_diffuse, indirect_specular };
constexpr std::array<LightTerm, 4> kLightTerms{LightTerm::emission, LightTerm::direct,
                                               LightTerm::indirect_diffuse,
                                               LightTerm::indirect_specular};

std::string_view termName(LightTerm term);

// One image per term, indexed by LightTerm.
using TermImages = std::array<Image, kLightTerms.size()>;
inline Image& termImage(TermImages& images, LightTerm term) {
  return images[size_t(term)];
}
inline const Image& termImage(const TermImages& images, LightTerm term) {
  return images[size_t(term)];
}

// The image without its indirect terms: emission + direct. Against the reference it is the
// baseline that asks whether a technique's indirect light helps at all (docs/accuracy.md).
Image directOnly(const TermImages& terms);

// A staged technique's terms from the buffers its run left: the gbuffer's materials times the
// light buffers of its shading stage (Technique::lightTerms), put together by the kernel that
// composes its image (shaders/shared/compose.h), so the terms add up to the image up to
// float rounding. nullopt when the technique has no such buffers.
std::optional<TermImages> techniqueTerms(const Technique& technique, const BufferSet& buffers,
                                         const Settings& settings, const Scene& scene);

}  // namespace voxgi
