// voxgi bench path (docs/benchmarks.md, docs/path-tracer.md): what a reference costs per unit of
// error. Per scene and transport (direct light, one bounce, every bounce), each estimator's render
// at the same spp (the independent sampler with area light sampling, as before the Sobol' points;
// one Sobol' sequence with area, and with solid angle; the default, two Sobol' replicas with solid
// angle, whose spread gives an honest variance image), timed (median of the repeats) and
// measured against a converged render of the same transport: samples/s, rays/s, MSE, the MSE of
// the direct and the indirect light, and the efficiency 1 / (seconds x MSE) against the first's,
// all in one run.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include "common/light_terms.h"
#include "common/io/output_file.h"
#include "common/scene_io/scene_load.h"
#include "tools/bench.h"
#include "validation/reference/image_metrics.h"
#include "validation/reference/path_trace.h"

namespace voxgi::tools {
namespace {

struct Transport {
  const char* name;
  int bounces;
};
constexpr Transport kTransports[] = {{"direct", 0}, {"one bounce", 1}, {"full", -1}};

struct Estimator {
  reference::SamplerKind sampler;
  reference::LightSampling lightSampling;
  int replicas;  // PathTraceOptions::replicas
};
constexpr Estimator kEstimators[] = {
    {reference::SamplerKind::independent, reference::LightSampling::area, 1},
    {reference::SamplerKind::sobol, reference::LightSampling::area, 1},
    {reference::SamplerKind::sobol, reference::LightSampling::solid_angle, 1},
    {reference::SamplerKind::sobol, reference::LightSampling::solid_angle,
     reference::kDefaultReplicas}};

// The name a table of names (reference::kSamplerNames, kLightSamplingNames) gives `value`.
template <class T, size_t N>
const char* nameOf(const std::pair<const char*, T> (&names)[N], T value) {
  for (const auto& [name, v] : names)
    if (v == value) return name;
  return "?";
}

// An image's indirect light: the sum of its two lobes' terms.
Image indirectLight(const TermImages& terms) {
  Image sum = termImage(terms, LightTerm::indirect_diffuse);
  const Image& specular = termImage(terms, LightTerm::indirect_specular);
  for (size_t i = 0; i < sum.pixels.size(); ++i) sum.pixels[i] += specular.pixels[i];
  return sum;
}

// Mean over pixels and channels of the squared difference (the square of compare's RMSE).
double meanSquaredError(const Image& image, const Image& reference) {
  const double rmse = reference::compareImages(image, reference).rmse;
  return rmse * rmse;
}

}  // namespace

void addBenchPathOptions(CLI::App& cmd, BenchPathOptions& o) {
  cmd.add_option("--scenes", o.scenes, "scenes (default: the shipped Cornell box and bunny)")
      ->delimiter(',');
  cmd.add_option("--image", o.image, "image width in pixels (the height keeps the aspect)")
      ->check(CLI::Range(8, 4096));
  cmd.add_option("--spp", o.spp, "samples per pixel of the timed renders")
      ->check(CLI::Range(1, 1 << 16));
  cmd.add_option("--reference-spp", o.referenceSpp,
                 "samples per pixel of the converged render (the defaults, its own seed)")
      ->check(CLI::Range(16, 1 << 20));
  cmd.add_option("--threads", o.threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  cmd.add_option("--repeat", o.repeats, "runs per measurement (the median time is reported)")
      ->check(CLI::Range(1, 100));
  cmd.add_option("--json", o.json, "also write the figures as JSON");
}

int runBenchPath(const BenchPathOptions& o) {
  std::optional<tbb::global_control> limit;
  if (o.threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, size_t(o.threads));
  nlohmann::json rows = nlohmann::json::array();
  std::cout
      << "| scene | transport | sampler | light sampling | replicas | spp | seconds | samples/s | "
         "rays/s | MSE | MSE direct | MSE indirect | efficiency 1/(s MSE) | × independent, area "
         "|\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string& path : o.scenes) {
    Scene scene = loadScene(path);
    const double aspect = double(scene.camera.height) / double(scene.camera.width);
    scene.camera.width = o.image;
    scene.camera.height = std::max(1, int(std::lround(o.image * aspect)));
    for (const Transport& transport : kTransports) {
      reference::PathTraceOptions converged;
      converged.spp = o.referenceSpp;
      converged.bounces = transport.bounces;
      converged.seed = 0x5eed5eedull;  // independent of the timed renders' seed 0
      const reference::PathTraceResult ref = reference::pathTrace(scene, converged);
      // What the converged render's own noise adds to an MSE, by its (honest) variance image.
      const double floor = std::pow(
          reference::noiseFloor(ref.image, ref.variance, {}, reference::MetricScale{}).rmse, 2);
      const Image& refDirect = termImage(ref.terms, LightTerm::direct);
      const Image refIndirect = indirectLight(ref.terms);
      double baseline = 0.0;  // the first estimator's efficiency
      for (const Estimator& estimator : kEstimators) {
        reference::PathTraceOptions options;
        options.spp = o.spp;
        options.bounces = transport.bounces;
        options.sampler = estimator.sampler;
        options.lightSampling = estimator.lightSampling;
        options.replicas = estimator.replicas;
        reference::PathTraceResult result;
        const double seconds =
            medianSeconds(o.repeats, [&] { result = reference::pathTrace(scene, options); });
        const double mse = meanSquaredError(result.image, ref.image);
        const double direct =
            meanSquaredError(termImage(result.terms, LightTerm::direct), refDirect);
        const double indirect = meanSquaredError(indirectLight(result.terms), refIndirect);
        const double efficiency = 1.0 / (seconds * mse);
        if (baseline == 0.0) baseline = efficiency;
        const double samples = double(o.spp) * double(result.image.pixels.size());
        const char* sampler = nameOf(reference::kSamplerNames, estimator.sampler);
        const char* lightSampling = nameOf(reference::kLightSamplingNames, estimator.lightSampling);
        std::cout << "| " << scene.file << " | " << transport.name << " | " << sampler << " | "
                  << lightSampling << " | " << estimator.replicas << " | " << o.spp << " | "
                  << std::setprecision(3) << seconds << " | " << samples / seconds << " | "
                  << double(result.rays) / seconds << " | " << mse << " | " << direct << " | "
                  << indirect << " | " << efficiency << " | " << std::setprecision(2)
                  << efficiency / baseline << " |\n";
        // The converged render's noise should be far below the error measured against it.
        if (floor > 0.1 * mse)
          std::cout << "  (the converged render's variance estimate, " << floor
                    << ", exceeds a tenth of this MSE: check with a larger --reference-spp)\n";
        rows.push_back({{"scene", scene.file},
                        {"transport", transport.name},
                        {"sampler", sampler},
                        {"light_sampling", lightSampling},
                        {"replicas", estimator.replicas},
                        {"spp", o.spp},
                        {"seconds", seconds},
                        {"samples_per_second", samples / seconds},
                        {"rays_per_second", double(result.rays) / seconds},
                        {"mse", mse},
                        {"mse_direct", direct},
                        {"mse_indirect", indirect},
                        {"reference_variance", floor},
                        {"efficiency", efficiency},
                        {"efficiency_vs_independent_area", efficiency / baseline}});
      }
    }
  }
  if (!o.json.empty()) writeFileAtomically(o.json, rows.dump(2) + "\n");
  return 0;
}

}  // namespace voxgi::tools
