// The gbuffer stage's buffers as the shading stages read them (trace_cones, compose, the light
// propagation volumes' and the octree's shade), by their declarations in common/shared_stages.inc.
#pragma once

#include "common/buffer.h"

namespace voxgi {

struct GbufferView {
  const Buffer& position;
  const Buffer& normal;
  const Buffer& albedo;
  const Buffer& specular;
  const Buffer* emission;  // nullptr where the plan has no emission
  const Buffer& objectId;

  explicit GbufferView(const BufferSet& buffers)
      : position(buffers.at(BufferId::common_gbuffer_pixel_position)),
        normal(buffers.at(BufferId::common_gbuffer_pixel_normal)),
        albedo(buffers.at(BufferId::common_gbuffer_pixel_albedo)),
        specular(buffers.at(BufferId::common_gbuffer_pixel_specular)),
        emission(buffers.find(BufferId::common_gbuffer_pixel_emission)),
        objectId(buffers.at(BufferId::common_gbuffer_object_id)) {}
};

}  // namespace voxgi
