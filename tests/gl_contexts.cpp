#include "tests/gl_contexts.h"

#include <map>
#include <memory>

#include "common/pipeline.h"
#include "cpu/backend.h"
#include "gpu/backend.h"
#include "tests/test_scenes.h"

namespace voxgi::test {

gpu::GlContext& glContext(gpu::GlPlatform platform) {
  static std::map<gpu::GlPlatform, std::unique_ptr<gpu::GlContext>> contexts;
  auto& c = contexts[platform];
  if (!c) c = gpu::GlContext::create(platform);
  return *c;
}

std::vector<validation::StageReport> diffVct(const Scene& scene, const Settings& settings,
                                             gpu::GlContext& context,
                                             const std::vector<std::string>& stages) {
  return diffTechnique(vct(), scene, settings, context, stages);
}

std::vector<validation::StageReport> diffTechnique(const Technique& technique, const Scene& scene,
                                                   const Settings& settings,
                                                   gpu::GlContext& context,
                                                   const std::vector<std::string>& stages) {
  const VoxelTriangles tris = prepareVoxelTriangles(scene, scene.grid);
  std::vector<const StageSpec*> specs;
  for (const std::string& s : stages) specs.push_back(&resolveStage(technique, s));
  cpu::CpuBackend cpu;
  gpu::GpuBackend gpu(context);
  return validation::diffStages(StageContext{technique, scene, settings, tris}, cpu, gpu, specs,
                                "");
}

}  // namespace voxgi::test
