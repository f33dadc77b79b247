// voxgi bench path (docs/benchmarks.md, docs/path-tracer.md): what a reference costs per unit of
// error. Per scene and transport (direct light, one bounce, every bounce), each sampler's render
// at the same spp, timed (median of the repeats) and measured against a converged render of the
// same transport: samples/s, rays/s, MSE and the efficiency 1 / (seconds x MSE), with each
// sampler's efficiency against the independent one's, all in one run.
#include <algorithm>
#include <iomanip>
#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>
#include <tbb/global_control.h>

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

const char* samplerName(reference::SamplerKind k) {
  return k == reference::SamplerKind::sobol ? "sobol" : "independent";
}

}  // namespace

void addBenchPathOptions(CLI::App& cmd, BenchPathOptions& o) {
  cmd.add_option("--scenes", o.scenes, "scenes")->delimiter(',');
  cmd.add_option("--image", o.image, "image width in pixels (the height keeps the aspect)")
      ->check(CLI::Range(8, 4096));
  cmd.add_option("--spp", o.spp, "samples per pixel of the timed renders")
      ->check(CLI::Range(1, 1 << 16));
  cmd.add_option("--reference-spp", o.referenceSpp,
                 "samples per pixel of the converged render (sobol, its own seed)")
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
      << "| scene | transport | sampler | spp | seconds | samples/s | rays/s | MSE | "
         "efficiency 1/(s MSE) | × independent |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string& path : o.scenes) {
    Scene scene = loadScene(path);
    const double aspect = double(scene.camera.height) / double(scene.camera.width);
    scene.camera.width = o.image;
    scene.camera.height = std::max(1, int(std::lround(o.image * aspect)));
    for (const Transport& transport : kTransports) {
      reference::PathTraceOptions converged;
      converged.spp = o.referenceSpp;
      converged.bounces = transport.bounces;
      converged.sampler = reference::SamplerKind::sobol;
      converged.seed = 0x5eed5eedull;  // independent of the timed renders' seed 0
      const reference::PathTraceResult ref = reference::pathTrace(scene, converged);
      double independentEfficiency = 0.0;
      for (const reference::SamplerKind sampler :
           {reference::SamplerKind::independent, reference::SamplerKind::sobol}) {
        reference::PathTraceOptions options;
        options.spp = o.spp;
        options.bounces = transport.bounces;
        options.sampler = sampler;
        reference::PathTraceResult result;
        const double seconds =
            medianSeconds(o.repeats, [&] { result = reference::pathTrace(scene, options); });
        const auto [mse, floor] = meanSquaredError(result.image, ref.image, ref.variance);
        const double efficiency = 1.0 / (seconds * mse);
        if (sampler == reference::SamplerKind::independent) independentEfficiency = efficiency;
        const double samples = double(o.spp) * double(result.image.pixels.size());
        std::cout << "| " << scene.file << " | " << transport.name << " | " << samplerName(sampler)
                  << " | " << o.spp << " | " << std::setprecision(3) << seconds << " | "
                  << std::setprecision(3) << samples / seconds << " | "
                  << double(result.rays) / seconds << " | " << mse << " | " << efficiency << " | "
                  << std::setprecision(2) << efficiency / independentEfficiency << " |\n";
        // Its Monte Carlo variance estimate overstates a scrambled Sobol' render's error: a
        // warning to check with a larger --reference-spp, not a floor.
        if (floor > 0.1 * mse)
          std::cout << "  (the converged render's variance estimate, " << floor
                    << ", exceeds a tenth of this MSE: check with a larger --reference-spp)\n";
        rows.push_back({{"scene", scene.file},
                        {"transport", transport.name},
                        {"sampler", samplerName(sampler)},
                        {"spp", o.spp},
                        {"seconds", seconds},
                        {"samples_per_second", samples / seconds},
                        {"rays_per_second", double(result.rays) / seconds},
                        {"mse", mse},
                        {"reference_variance", floor},
                        {"efficiency", efficiency},
                        {"efficiency_vs_independent", efficiency / independentEfficiency}});
      }
    }
  }
  if (!o.json.empty()) writeFileAtomically(o.json, rows.dump(2) + "\n");
  return 0;
}

}  // namespace voxgi::tools
