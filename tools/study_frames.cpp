// `voxgi study SCENE --frames A:B[:STEP] --reference REF_%04d.exr`: each technique through an
// animated scene's frames on the CPU, each frame measured against its reference (the --metric
// error beside a black frame's), in time (the flicker of its change from the frame before against
// the reference's, beside a sequence that holds still and the reference's own noise) and in cost
// (the frame updated from the one before, FrameRunner, beside the frame rebuilt from scratch, side
// by side in one run); a CSV row per technique and frame, and one plot of the three against the
// frame (tools/plot_study_frames.py; docs/motion.md, "The study in time").
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "common/error.h"
#include "common/frame_plan.h"
#include "common/io/buffer_io.h"
#include "common/io/input_file.h"
#include "common/io/output_file.h"
#include "common/scene_io/scene_load.h"
#include "common/scene_motion.h"
#include "cpu/backend.h"
#include "tools/bench.h"
#include "tools/compare.h"
#include "tools/frames.h"
#include "tools/plot_script.h"
#include "tools/study.h"
#include "validation/reference/temporal_metrics.h"

namespace voxgi::tools {

extern const char* const kPlotStudyFramesScript;  // tools/plot_study_frames.py

namespace {

// A reference frame: its image, its variance image (path-traced references have one) and the
// metrics' scale.
struct ReferenceFrame {
  Image image;
  std::optional<Image> variance;
  reference::MetricScale scale;
};

// One technique's frame: its image and what updating and rebuilding it cost (medians).
struct TechniqueFrame {
  Image image;
  double seconds = 0.0, rebuildSeconds = 0.0;
};

double seconds(const std::chrono::steady_clock::time_point& start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The technique through every frame, `repeats` times, updating (FrameRunner) and rebuilding
// (--scratch) alternately; the two give the same image, which is checked (unless
// update.interval > 1 makes the updated frames lag).
std::vector<TechniqueFrame> runSequence(const StudyOptions& o, const std::string& name,
                                        const Scene& scene, const std::vector<int>& frames) {
  const Technique& technique = findTechnique(name);
  std::vector<std::vector<double>> updates(frames.size()), rebuilds(frames.size());
  std::vector<TechniqueFrame> out(frames.size());
  cpu::CpuBackend cpu;
  for (int k = 0; k < o.repeats; ++k) {
    FrameRunner update(technique, cpu), rebuild(technique, cpu, true);
    for (size_t i = 0; i < frames.size(); ++i) {
      const Scene at =
          scene.motion.empty() ? scene : sceneAt(scene, frameSeconds(frames[i], o.fps));
      const Settings settings = resolveSettings(technique, at.settings, at.file, o.preset, o.sets);
      auto start = std::chrono::steady_clock::now();
      update.run(at, settings);
      updates[i].push_back(seconds(start));
      start = std::chrono::steady_clock::now();
      rebuild.run(at, settings);
      rebuilds[i].push_back(seconds(start));
      const Buffer& image = update.buffers().at(technique.image);
      // Under update.interval > 1 the updated frames lag by design.
      if (settings.updateInterval == 1 &&
          image.words != rebuild.buffers().at(technique.image).words)
        throw std::logic_error(name + ": frame " + std::to_string(frames[i]) +
                               " updated differs from the frame rebuilt");
      if (k + 1 == o.repeats) out[i].image = bufferImage(image);
    }
  }
  for (size_t i = 0; i < frames.size(); ++i) {
    out[i].seconds = median(updates[i]);
    out[i].rebuildSeconds = median(rebuilds[i]);
  }
  return out;
}

void checkFrameOptions(const StudyOptions& o) {
  if (!o.sweeps.empty() || o.terms || !o.mask.empty() || o.skipEmitters)
    throw InputError("--frames", "",
                     "a study in time takes no --sweep, --terms, --mask or --skip-emitters");
  for (const std::string& t : o.techniques)
    if (t == "path")
      throw InputError("--technique", "path",
                       "with --frames the path tracer is the reference (--reference), not a "
                       "technique studied");
}

}  // namespace

int runStudyFrames(const StudyOptions& o) {
  checkFrameOptions(o);
  const FrameRange range = parseFrames(o.frames, "--frames");
  std::vector<int> frames;
  for (int f = range.first; f <= range.last; f += range.step) frames.push_back(f);
  for (const int f : frames)
    requireInputFile(framePath(o.reference, f, "--reference"), "", "reference image");
  checkOutputPath(o.csv);
  if (!o.plot.empty()) checkOutputPath(o.plot);
  const Scene scene = loadStudyScene(o);
  std::vector<ReferenceFrame> references;
  for (const int f : frames) {
    const std::string path = framePath(o.reference, f, "--reference");
    ReferenceFrame r{readReference(path), {}, {}};
    checkSameSize(scene.camera.width, scene.camera.height,
                  o.scene + " camera.resolution (or --image)", r.image);
    r.variance = readVarianceImage(path, r.image);
    r.scale = reference::metricScale(r.image, {}, o.units);
    references.push_back(std::move(r));
  }

  std::ostringstream csv;
  csv.precision(6);
  csv << "technique,frame,seconds,rebuild_seconds,rmse,rel_mse,mare,ssim,ssim_loss,error,"
         "black_error,flicker,held,noise\n";
  std::cout << "study of " << o.scene << " over frames " << o.frames << " against " << o.reference
            << " (" << o.metric << " in units of each reference frame's mean)\n"
            << "  technique  mean error     black  mean flicker      held  update ms  rebuild ms"
               "\n  (flicker and cost over the frames after the first)\n";
  for (const std::string& technique : o.techniques) {
    const std::vector<TechniqueFrame> run = runSequence(o, technique, scene, frames);
    double error = 0.0, black = 0.0, flicker = 0.0, held = 0.0, update = 0.0, rebuild = 0.0;
    for (size_t i = 0; i < frames.size(); ++i) {
      const ReferenceFrame& r = references[i];
      const reference::ImageMetrics m =
          reference::compareImages(run[i].image, r.image, {}, r.scale);
      const reference::Baselines b = reference::trivialBaselines(r.image, {}, r.scale);
      csv << technique << "," << frames[i] << "," << run[i].seconds << "," << run[i].rebuildSeconds
          << "," << m.rmse << "," << m.relMse << "," << m.mare << "," << m.ssim << ","
          << 1.0 - m.ssim << "," << metricError(m, o.metric) << ","
          << metricError(b.black, o.metric) << ",";
      error += metricError(m, o.metric);
      black += metricError(b.black, o.metric);
      if (i > 0 || frames.size() == 1) {
        update += run[i].seconds;
        rebuild += run[i].rebuildSeconds;
      }
      if (i > 0) {
        const ReferenceFrame& before = references[i - 1];
        const reference::TemporalMetrics t =
            reference::compareChanges(run[i - 1].image, run[i].image, before.image, r.image, {},
                                      r.scale, before.variance, r.variance);
        csv << t.error << "," << t.held << ",";
        if (!std::isnan(t.noise)) csv << t.noise;
        flicker += t.error;
        held += t.held;
      } else {
        csv << ",,";
      }
      csv << "\n";
    }
    const double n = double(frames.size()), changes = std::max(n - 1.0, 1.0);
    std::cout << "  " << std::left << std::setw(9) << technique << std::right
              << std::setprecision(4) << std::setw(12) << error / n << std::setw(10) << black / n
              << std::setw(14) << flicker / changes << std::setw(10) << held / changes
              << std::setw(11) << 1e3 * update / changes << std::setw(12) << 1e3 * rebuild / changes
              << std::endl;
  }
  writeFileAtomically(o.csv, csv.str());
  std::cout << "wrote " << o.csv << "\n";
  if (!o.plot.empty()) {
    const std::string title = std::filesystem::path(o.scene).filename().string() + ", frames " +
                              o.frames + ", against " +
                              std::filesystem::path(o.reference).filename().string();
    runPlotScript(kPlotStudyFramesScript, o.csv, o.plot, {metricLabel(o.metric), title});
    std::cout << "wrote " << o.plot << "\n";
  }
  return kExitOk;
}

}  // namespace voxgi::tools
