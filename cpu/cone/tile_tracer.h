// The phases of the shared kernel's shadePixel (shaders/shared/cone/pixel_light.h) over a
// tile of pixels, each phase's cones marched together in SIMD lanes (cpu/cone/cone_lanes.h): the
// same numbers tracePixel gives pixel by pixel, faster. Used by vct's trace_cones over the dense
// pyramid and by svo's shade over the octree's bricks.
#pragma once

#include <span>
#include <vector>

#include "cpu/cone/cone_lanes.h"
#include "shaders/shared/cone/pixel_light.h"

namespace voxgi::cpu {

// A pixel of a tile with a surface, what its cones start from, and its direct light as the lights
// add up.
struct TilePixel {
  size_t e;  // the pixel's element in the image
  glm::ivec2 at;
  glm::vec3 p, n, origin, mirror;
  glm::vec3 tangent, bitangent;  // the diffuse cones' frame around n
  shared::ObjectData object;
  shared::DirectLight direct;
};

// The pixel at `at` (element e) whose surface point is p with unit normal n.
inline TilePixel tilePixel(size_t e, glm::ivec2 at, glm::vec3 p, glm::vec3 n,
                           const shared::ObjectData& object,
                           const shared::ConeTraceParams& params) {
  glm::vec3 t, b;
  shared::tangentFrame(n, t, b);
  return {e,
          at,
          p,
          n,
          shared::coneOrigin(p, n, params),
          shared::mirrorDirection(p, n, params),
          t,
          b,
          object,
          shared::noDirectLight()};
}

class TileTracer {
 public:
  // The cones march through `lanes`; `lights` and `cones` are FETCH(lightAt) and FETCH(coneAt).
  TileTracer(const cone_lanes::Volumes& lanes, std::span<const shared::LightData> lights,
             std::span<const shared::ConeData> cones, const shared::ConeTraceParams& params)
      : lanes_(lanes), lights_(lights), cones_(cones), params_(params) {}

  // Direct light, one light at a time in the kernel's order.
  void addDirectLight(std::vector<TilePixel>& pixels) {
    std::vector<shared::LightPath> paths(pixels.size());
    for (int i = 0; i < params_.lightCount; ++i) {
      jobs_.clear();
      for (size_t k = 0; k < pixels.size(); ++k) {
        const TilePixel& px = pixels[k];
        paths[k] = shared::lightPath(lights_[size_t(i)], px.p, px.n, params_);
        if (paths[k].arrives && paths[k].shadowLength > 0.0f)
          jobs_.push_back({px.origin, paths[k].toLight, paths[k].cosine, paths[k].tanHalf,
                           paths[k].shadowLength});
      }
      march(shared::shadowMarchKind(params_));
      size_t hit = 0;
      for (size_t k = 0; k < pixels.size(); ++k) {
        if (!paths[k].arrives) continue;
        const float visibility =
            paths[k].shadowLength > 0.0f ? 1.0f - hits_[hit++].occlusion : 1.0f;
        TilePixel& px = pixels[k];
        px.direct =
            shared::addLight(px.direct, paths[k], visibility, px.mirror, px.object, params_);
      }
    }
  }

  // The diffuse cones, cone by cone: a lane's next cone is its neighbour's, much like it.
  std::vector<shared::DiffuseSum> traceDiffuse(const std::vector<TilePixel>& pixels) {
    const int coneCount = params_.diffuseConeCount;
    jobs_.clear();
    for (int c = 0; c < coneCount; ++c)
      for (const TilePixel& px : pixels) {
        const shared::ConeData& cone = cones_[size_t(c)];
        jobs_.push_back({px.origin,
                         shared::diffuseConeDirection(px.tangent, px.bitangent, px.n, cone),
                         cone.direction.z, cone.tanHalfAperture, params_.maxDistance});
      }
    march(shared::diffuseMarchKind(params_));
    std::vector<shared::DiffuseSum> sums(pixels.size(), shared::noDiffuse());
    for (int c = 0; c < coneCount; ++c)
      for (size_t k = 0; k < pixels.size(); ++k)
        sums[k] = shared::addDiffuseCone(sums[k], hits_[size_t(c) * pixels.size() + k],
                                         cones_[size_t(c)]);
    return sums;
  }

  // The specular cones of glossy pixels, then every pixel's terms (finishPixel).
  std::vector<shared::PixelLight> finish(const std::vector<TilePixel>& pixels,
                                         const std::vector<shared::DiffuseSum>& diffuse) {
    jobs_.clear();
    for (const TilePixel& px : pixels)
      if (px.object.specularTanHalfAperture > 0.0f)
        jobs_.push_back({px.origin, px.mirror, shared::dot3(px.n, px.mirror),
                         px.object.specularTanHalfAperture, params_.maxDistance});
    march(shared::kMarchRadiance);
    std::vector<shared::PixelLight> lights(pixels.size());
    size_t specular = 0;
    for (size_t k = 0; k < pixels.size(); ++k) {
      const TilePixel& px = pixels[k];
      const shared::ConeHit specularHit =
          px.object.specularTanHalfAperture > 0.0f ? hits_[specular++] : shared::noConeHit();
      lights[k] = shared::finishPixel(px.direct, diffuse[k], specularHit, px.object, params_);
    }
    return lights;
  }

 private:
  void march(int kind) {
    hits_.resize(jobs_.size());
    marchCones(simdLevel(), lanes_, jobs_, kind, params_, hits_);
  }

  const cone_lanes::Volumes& lanes_;
  std::span<const shared::LightData> lights_;
  std::span<const shared::ConeData> cones_;
  const shared::ConeTraceParams& params_;
  std::vector<ConeJob> jobs_;
  std::vector<shared::ConeHit> hits_;
};

}  // namespace voxgi::cpu
