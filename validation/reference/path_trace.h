// The reference renderer: an unbiased path tracer on Embree 3 with the scene semantics of the
// real-time techniques (docs/path-tracer.md). Deterministic: every sample number is a function
// of (seed, pixel, sample, dimension), so the image is bit-identical for any thread count.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>

#include "common/image_io.h"
#include "common/light_terms.h"
#include "common/scene.h"
#include "validation/reference/emitters.h"
#include "validation/reference/sampler.h"

namespace voxgi::reference {

struct PathTraceOptions {
  int spp = 64;
  int bounces = -1;  // indirect bounces after the first hit; -1: unlimited (Russian roulette)
  uint64_t seed = 0;
  SamplerKind sampler = SamplerKind::sobol;                  // validation/reference/sampler.h
  LightSampling lightSampling = LightSampling::solid_angle;  // validation/reference/emitters.h
  const std::atomic<bool>* cancel = nullptr;      // set from elsewhere (Ctrl-C) to stop early
  std::function<void(double fraction)> progress;  // called as rows finish, from worker threads
};

struct PathTraceResult {
  Image image;        // mean radiance per pixel
  Image variance;     // variance of that mean per pixel and channel (sample variance / spp)
  TermImages terms;   // the mean split into the light terms (common/light_terms.h)
  uint64_t rays = 0;  // camera, bounce and shadow rays traced
  double seconds = 0.0;
};

// Thrown when options.cancel was set: nothing of the render is usable.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled") {}
};

PathTraceResult pathTrace(const Scene& scene, const PathTraceOptions& options);

// Where the variance image of `image` goes: "IMG.variance.exr" beside "IMG.exr".
std::string variancePath(const std::string& image);

}  // namespace voxgi::reference
