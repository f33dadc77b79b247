#include "common/kernel_params.h"

namespace voxgi {

shared::LightVoxelsParams lightVoxelsParams(const StageContext& ctx, int lightCount,
                                            bool emissive) {
  const Settings& s = ctx.settings;
  return {glm::ivec4(ctx.scene.grid.resolution, lightCount,
                     s.attenuation == LightAttenuation::normal_weighted ? 1 : 0,
                     static_cast<int>(s.voxelShadow)),
          glm::vec4(static_cast<float>(ctx.scene.grid.voxelSize()), s.voxelShadowKappa,
                    s.voxelShadowOffset, emissive ? 1.0f : 0.0f)};
}

}  // namespace voxgi
