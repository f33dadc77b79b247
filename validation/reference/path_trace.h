// The reference renderer: an unbiased path tracer on Embree 3 with the scene semantics of the
// real-time techniques (docs/path-tracer.md). Deterministic: every sample number is a function
// of (seed, pixel, sample, dimension), so the image is bit-identical for any thread count.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>

#include "common/image.h"
#include "common/light_terms.h"
#include "common/scene.h"
#include "validation/reference/emitters.h"
#include "validation/reference/sampler.h"

namespace voxgi::reference {

// Replicas of the default estimator: two cost 1.5 x the MSE of one sequence on the Cornell box
// (docs/path-tracer.md, "Variance"); more cost more.
constexpr int kDefaultReplicas = 2;

struct PathTraceOptions {
  int spp = 64;
  int bounces = -1;  // indirect bounces after the first hit; -1: unlimited (Russian roulette)
  uint64_t seed = 0;
  SamplerKind sampler = SamplerKind::sobol;  // validation/reference/sampler.h
  // sobol: independently scrambled replicas, sample s in replica s % replicas, whose means'
  // spread gives the variance image; 1: one sequence (the lowest error, but then the variance
  // image is the sample variance, which overstates a scrambled sequence's error)
  int replicas = kDefaultReplicas;
  LightSampling lightSampling = LightSampling::solid_angle;  // validation/reference/emitters.h
  const std::atomic<bool>* cancel = nullptr;      // set from elsewhere (Ctrl-C) to stop early
  std::function<void(double fraction)> progress;  // called as rows finish, from worker threads
};

// The most replicas PathTraceOptions::replicas takes.
constexpr int kMaxReplicas = 64;
// The half width of the square of pixels over which the variance image is averaged.
constexpr int kVarianceRadius = 2;

struct PathTraceResult {
  Image image;        // mean radiance per pixel
  Image variance;     // the variance of that mean per pixel and channel (docs/path-tracer.md,
                      // "Variance"): the replicas' spread (sobol) or the sample variance / spp
                      // (independent), averaged over the pixel's 5 x 5 neighbourhood
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
