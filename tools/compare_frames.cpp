// `voxgi compare TEST_%04d.exr REF_%04d.exr --frames A:B[:STEP]`: a sequence against its
// reference, frame by frame (relMSE and SSIM beside a black frame's) and in time (the flicker of
// each frame against the reference's change from the frame before, beside a sequence that holds
// still and the reference's own noise), with each frame's error map.
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "common/error.h"
#include "common/io/input_file.h"
#include "common/io/output_file.h"
#include "tools/compare.h"
#include "tools/frames.h"
#include "tools/metrics_json.h"
#include "validation/reference/path_trace.h"
#include "validation/reference/temporal_metrics.h"

namespace voxgi::tools {
namespace {

// A frame's error map, named as compare names one image's: TEST's name + .error.png.
std::string frameErrorMap(const std::string& test) {
  const std::filesystem::path t(test);
  return (t.parent_path() / (t.stem().string() + ".error.png")).string();
}

}  // namespace

int runCompareFrames(const CompareOptions& o) {
  if (!o.errorPng.empty() || o.terms || o.scanline >= 0 || !o.mask.empty() || o.skipEmitters)
    throw InputError("--frames", "",
                     "compares whole images: --error-png, --terms, --scanline, --mask and "
                     "--skip-emitters are for one image");
  const FrameRange range = parseFrames(o.frames, "--frames");
  std::vector<int> frames;
  for (int f = range.first; f <= range.last; f += range.step) frames.push_back(f);
  // Every frame's files exist and its error map can be written before the first is read.
  for (const int f : frames) {
    requireInputFile(framePath(o.test, f, "test"), "", "image");
    requireInputFile(framePath(o.reference, f, "reference"), "", "reference image");
    checkOutputPath(frameErrorMap(framePath(o.test, f, "test")));
  }
  if (!o.json.empty()) checkOutputPath(o.json);
  std::cout << "compare " << o.test << " against " << o.reference << ", frames " << o.frames
            << "\n  relMSE and SSIM in units of each reference frame's mean; flicker: RMS of "
               "(t_f - t_prev) - (r_f - r_prev) in those units; held: a sequence that does not "
               "change (or a black one); noise: the reference's own (its variance images)\n"
            << "  frame      relMSE    SSIM  black relMSE     flicker      held     noise\n";
  nlohmann::json rows = nlohmann::json::array();
  Image previousTest, previousReference;
  std::optional<Image> previousVariance;
  double sumRel = 0.0, sumFlicker = 0.0, sumHeld = 0.0;
  for (size_t i = 0; i < frames.size(); ++i) {
    const std::string testPath = framePath(o.test, frames[i], "test");
    const std::string referencePath = framePath(o.reference, frames[i], "reference");
    Image reference = readReference(referencePath);
    Image test = readImage(testPath);
    checkSameSize(test.width, test.height, testPath, reference);
    if (i > 0) checkSameSize(reference.width, reference.height, referencePath, previousReference);
    std::optional<Image> variance = readVarianceImage(referencePath, reference);
    const reference::MetricScale scale = reference::metricScale(reference, {}, o.units);
    const reference::ImageMetrics m = reference::compareImages(test, reference, {}, scale);
    const reference::Baselines baselines = reference::trivialBaselines(reference, {}, scale);
    writeRgb8Png(frameErrorMap(testPath), reference.width, reference.height,
                 reference::errorColours(test, reference, {}, scale));
    nlohmann::json row = metricsJson(m);
    row["frame"] = frames[i];
    row["black_rel_mse"] = baselines.black.relMse;
    std::cout << "  " << std::left << std::setw(7) << frames[i] << std::right << std::setw(10)
              << std::setprecision(4) << m.relMse << std::setw(8) << m.ssim << std::setw(14)
              << baselines.black.relMse;
    sumRel += m.relMse;
    if (i > 0) {
      const reference::TemporalMetrics t = reference::compareChanges(
          previousTest, test, previousReference, reference, {}, scale, previousVariance, variance);
      std::cout << std::setw(12) << t.error << std::setw(10) << t.held << std::setw(10) << t.noise;
      row["flicker"] = t.error;
      row["held"] = t.held;
      if (!std::isnan(t.noise)) row["noise"] = t.noise;
      sumFlicker += t.error;
      sumHeld += t.held;
    }
    std::cout << "\n";
    rows.push_back(row);
    previousTest = std::move(test);
    previousReference = std::move(reference);
    previousVariance = std::move(variance);
  }
  const double n = double(frames.size()), changes = double(std::max<size_t>(frames.size(), 2) - 1);
  std::cout << "  mean   " << std::setw(10) << sumRel / n << std::setw(22) << "" << std::setw(12)
            << (frames.size() > 1 ? sumFlicker / changes : 0.0) << std::setw(10)
            << (frames.size() > 1 ? sumHeld / changes : 0.0) << "\n";
  if (!o.json.empty())
    writeFileAtomically(o.json, nlohmann::json{{"test", o.test},
                                               {"reference", o.reference},
                                               {"frames", rows},
                                               {"mean_rel_mse", sumRel / n},
                                               {"mean_flicker", sumFlicker / changes},
                                               {"mean_held", sumHeld / changes}}
                                        .dump(2) +
                                    "\n");
  return kExitOk;
}

}  // namespace voxgi::tools
