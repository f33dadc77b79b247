// voxgi bench path (docs/benchmarks.md, docs/path-tracer.md): what a reference costs per unit of
// error. Per scene and transport (direct light, one bounce, every bounce), each estimator's render
// at the same spp (the independent sampler with area light sampling, as before the Sobol' points;
// Sobol' with area; Sobol' with solid angle, the default), timed (median of the repeats) and
// measured against a converged render of the same transport: samples/s, rays/s, MSE, the MSE of
// the direct and the indirect light, and the efficiency 1 / (seconds x MSE) against the first's,
// all in one run.
#include <algorithm>
#include <initializer_list>
#include <iomanip>
#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

#include "common/light_terms.h"
#include "common/output_file.h"
#include "common/scene_load.h"
#include "tools/bench.h"
#include "validation/reference/path_trace.h"

namespace voxgi::tools {
namespace {

struct Transport {
  const char* name;
  int bounces;
};
constexpr Transport kTransports[] = {{"direct", 0}, {"one bounce", 1}, {"full", -1}};

struct Estimator {
  const char* sampler;
  const char* lightSampling;
  reference::SamplerKind samplerKind;
  reference::LightSampling lightSamplingKind;
};
constexpr Estimator kEstimators[] = {
    {"independent", "area", reference::SamplerKind::independent, reference::LightSampling::area},
    {"sobol", "area", reference::SamplerKind::sobol, reference::LightSampling::area},
    {"sobol", "solid_angle", reference::SamplerKind::sobol, reference::LightSampling::solid_angle}};

// Mean over pixels and channels of the squared difference between the sums of `terms` in two
// term sets.
double termsError(const TermImages& image, const TermImages& reference,
                  std::initializer_list<LightTerm> terms) {
  double sum = 0.0;
  const size_t pixels = termImage(image, LightTerm::direct).pixels.size();
  for (size_t i = 0; i < pixels; ++i)
    for (int c = 0; c < 3; ++c) {
      double d = 0.0;
      for (const LightTerm t : terms)
        d +=
            double(termImage(image, t).pixels[i][c]) - double(termImage(reference, t).pixels[i][c]);
      sum += d * d;
    }
  return sum / (3.0 * double(pixels));
}

// Mean over pixels and channels of the squared difference, and of the reference's own variance
// (what its noise adds to that).
std::pair<double, double> meanSquaredError(const Image& image, const Image& reference,
                                           const Image& referenceVariance) {
  double sum = 0.0, floor = 0.0;
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = double(image.pixels[i][c]) - double(reference.pixels[i][c]);
      sum += d * d;
      floor += double(referenceVariance.pixels[i][c]);
    }
  const double n = 3.0 * double(image.pixels.size());
  return {sum / n, floor / n};
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
      << "| scene | transport | sampler | light sampling | spp | seconds | samples/s | rays/s "
         "| MSE | MSE direct | MSE indirect | efficiency 1/(s MSE) | × independent, area "
         "|\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
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
      double baseline = 0.0;  // the first estimator's efficiency
      for (const Estimator& estimator : kEstimators) {
        reference::PathTraceOptions options;
        options.spp = o.spp;
        options.bounces = transport.bounces;
        options.sampler = estimator.samplerKind;
        options.lightSampling = estimator.lightSamplingKind;
        reference::PathTraceResult result;
        const double seconds =
            medianSeconds(o.repeats, [&] { result = reference::pathTrace(scene, options); });
        const auto [mse, floor] = meanSquaredError(result.image, ref.image, ref.variance);
        const double direct = termsError(result.terms, ref.terms, {LightTerm::direct});
        const double indirect = termsError(
            result.terms, ref.terms, {LightTerm::indirect_diffuse, LightTerm::indirect_specular});
        const double efficiency = 1.0 / (seconds * mse);
        if (baseline == 0.0) baseline = efficiency;
        const double samples = double(o.spp) * double(result.image.pixels.size());
        std::cout << "| " << scene.file << " | " << transport.name << " | " << estimator.sampler
                  << " | " << estimator.lightSampling << " | " << o.spp << " | "
                  << std::setprecision(3) << seconds << " | " << samples / seconds << " | "
                  << double(result.rays) / seconds << " | " << mse << " | " << direct << " | "
                  << indirect << " | " << efficiency << " | " << std::setprecision(2)
                  << efficiency / baseline << " |\n";
        // Its Monte Carlo variance estimate overstates a scrambled Sobol' render's error: a
        // warning to check with a larger --reference-spp, not a floor.
        if (floor > 0.1 * mse)
          std::cout << "  (the converged render's variance estimate, " << floor
                    << ", exceeds a tenth of this MSE: check with a larger --reference-spp)\n";
        rows.push_back({{"scene", scene.file},
                        {"transport", transport.name},
                        {"sampler", estimator.sampler},
                        {"light_sampling", estimator.lightSampling},
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
