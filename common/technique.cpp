#include "common/technique.h"

#include "common/error.h"

namespace voxgi {

std::span<const Technique> techniques() {
  // Each technique, followed by its variants.
  static const std::vector<Technique> table = [] {
    std::vector<Technique> out;
#define VOXGI_TECHNIQUE(technique, image_stage, image, description)                               \
  out.push_back(Technique{#technique, description, BufferId::technique##_##image_stage##_##image, \
                          &technique::params, &technique::presets, &technique::planEffects,       \
                          &technique::sparseLayouts, &technique::lightTerms, #technique});        \
  for (const Variant& v : technique::variants()) {                                                \
    out.push_back(out.back());                                                                    \
    out.back().name = v.name;                                                                     \
    out.back().summary = v.summary;                                                               \
    out.back().defaults = &v.defaults;                                                            \
  }
#define VOXGI_EFFECT(owner, effect, meaning)
#define VOXGI_STAGE(owner, stage, reads, summary)
#define VOXGI_STEP(technique, owner, stage)
#define VOXGI_BUFFER(owner, stage, buffer, type, components, shape, need, meaning)
#include "common/stages.inc"
    return out;
  }();
  return table;
}

std::string techniqueNames() {
  std::string names;
  for (const Technique& t : techniques())
    names.append(names.empty() ? "" : "|").append(std::string(t.name));
  return names;
}

const Technique& findTechnique(std::string_view name, const std::string& source) {
  for (const Technique& t : techniques())
    if (t.name == name) return t;
  throw InputError(source, "", "must be " + techniqueNames() + ", got '" + std::string(name) + "'");
}

}  // namespace voxgi
