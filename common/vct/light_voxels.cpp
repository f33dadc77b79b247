#include "common/vct/light_voxels.h"

#include "common/lights.h"

namespace voxgi {

shared::LightVoxelsParams lightVoxelsParams(const StageContext& ctx, int lightCount,
                                            bool emission) {
  const VctSettings& s = ctx.settings.vct;
  return {glm::ivec4(ctx.scene.grid.resolution, lightCount,
                     s.attenuation == LightAttenuation::normal_weighted ? 1 : 0,
                     static_cast<int>(s.voxelShadow)),
          glm::vec4(static_cast<float>(ctx.scene.grid.voxelSize()), s.voxelShadowKappa,
                    s.voxelShadowOffset, emission ? 1.0f : 0.0f)};
}

LightVoxelsSetup prepareLightVoxels(const StageContext& ctx, bool emissionVolume) {
  const EmitterLighting emitters = emittersFor(ctx.scene, ctx.settings.vct.emitters);
  LightVoxelsSetup s{sceneLights(ctx.scene, emitters), {}};
  s.params = lightVoxelsParams(ctx, int(s.lights.size()),
                               emissionVolume && emitters == EmitterLighting::voxels);
  return s;
}

}  // namespace voxgi
