// voxgi render: an image with a technique of the registry, or with the reference path tracer
// (--technique path, validation/reference/).
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <unistd.h>

#include "common/io/buffer_io.h"
#include "common/error.h"
#include "common/io/image_io.h"
#include "common/io/term_images.h"
#include "common/light_terms.h"
#include "common/io/output_file.h"
#include "tools/command.h"
#include "tools/frames.h"
#include "tools/sequence.h"
#include "validation/reference/path_trace.h"

namespace voxgi::tools {
namespace {

struct RenderOptions {
  SceneOptions scene;
  reference::PathTraceOptions path;
  std::string out, png;
  bool terms = false;
  std::string frames;  // --frames A:B[:STEP]; empty: one image
  double fps = 24.0;
  bool scratch = false;  // --scratch: every frame from scratch
  std::string shard;     // --shard I/N: the path tracer's share of --frames for a job array
};

// An image with a NaN or infinite pixel is not written: it would be garbage with exit 0. Input
// checks are meant to make this unreachable; if it happens, it is voxgi's bug (exit 1).
void requireFinite(const Image& image, const std::string& what) {
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const glm::vec3 p = image.at(x, y);
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw std::runtime_error(what + " has a non-finite pixel at (" + std::to_string(x) + ", " +
                                 std::to_string(y) + "); nothing written");
    }
}

// Every output can be written before anything runs.
void checkOutputs(const RenderOptions& o, bool variance) {
  checkOutputPath(o.out);
  if (variance) checkOutputPath(reference::variancePath(o.out));
  if (!o.png.empty()) checkOutputPath(o.png);
  if (o.terms)
    for (const LightTerm term : kLightTerms) checkOutputPath(termPath(o.out, term));
}

// A technique of the registry: the frame's stages on the sequence's backend, then its image.
int renderTechnique(const RenderOptions& o, StageSequence& sequence, Scene scene, bool frames) {
  const FrameRunner& run = sequence.frame(std::move(scene));
  const Technique& technique = findTechnique(o.scene.technique);
  const Image image = bufferImage(run.buffers().at(technique.image));
  requireFinite(image, std::string(technique.name) + "'s image");
  std::optional<TermImages> split;
  if (o.terms) {
    split = techniqueTerms(technique, run.buffers(), run.settings(), run.scene());
    if (!split)
      throw InputError("--terms", "",
                       std::string(technique.name) + " has no per-term light buffers");
  }
  writeExr(o.out, image);
  if (split) writeTermImages(o.out, *split);
  if (!o.png.empty()) writePng(o.png, image);
  std::cout << technique.name << " rendered " << run.scene().camera.width << "x"
            << run.scene().camera.height << " at " << run.scene().grid.resolution << "^3 ("
            << sequence.backendName() << ") in " << sequence.seconds() << " s -> " << o.out
            << (frames ? "; " + sequence.summary() : "") << "\n";
  if (const std::string note = lightingNote(run.scene()); !note.empty())
    std::cerr << "voxgi: " << note << "\n";
  return kExitOk;
}

std::atomic<bool> interrupted{false};

// Progress on a terminal, at most five times a second.
std::function<void(double)> progressPrinter() {
  auto printing = std::make_shared<std::mutex>();
  const auto start = std::chrono::steady_clock::now();
  auto lastPrint = std::make_shared<std::chrono::steady_clock::time_point>(start);
  return [=](double fraction) {
    const std::lock_guard<std::mutex> lock(*printing);
    const auto now = std::chrono::steady_clock::now();
    if (fraction < 1.0 && now - *lastPrint < std::chrono::milliseconds(200)) return;
    *lastPrint = now;
    const double elapsed = std::chrono::duration<double>(now - start).count();
    std::fprintf(stderr, "\rpath trace %5.1f%%  ETA %6.1f s ", 100.0 * fraction,
                 fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0);
  };
}

// The reference path tracer; Ctrl-C stops it with nothing written (exit 130).
int renderPath(const RenderOptions& o, const Scene& scene) {
  reference::PathTraceOptions options = o.path;
  options.cancel = &interrupted;
  std::signal(SIGINT, [](int) { interrupted = true; });
  const bool tty = isatty(STDERR_FILENO);
  if (tty) options.progress = progressPrinter();
  reference::PathTraceResult result;
  try {
    result = reference::pathTrace(scene, options);
  } catch (const reference::Cancelled&) {
    std::cerr << (tty ? "\n" : "") << "voxgi: interrupted; nothing written\n";
    return 130;
  }
  if (tty) std::cerr << "\n";
  requireFinite(result.image, "the path-traced image");
  writeExr(o.out, result.image);
  writeExr(reference::variancePath(o.out), result.variance);
  if (o.terms) writeTermImages(o.out, result.terms);
  if (!o.png.empty()) writePng(o.png, result.image);
  std::cout << "path traced " << scene.camera.width << "x" << scene.camera.height << " at "
            << options.spp << " spp in " << result.seconds << " s ("
            << double(result.rays) / result.seconds / 1e6 << " M rays/s) -> " << o.out << " and "
            << reference::variancePath(o.out) << "\n";
  if (const std::string note = lightingNote(scene); !note.empty())
    std::cerr << "voxgi: " << note << "\n";
  return kExitOk;
}

// One image, or the frames of --frames, each of the scene at its time (frame / fps seconds) with
// its own files; an animated scene's single image is its frame 0. Every output is checked before
// the first frame renders.
int render(const RenderOptions& o) {
  const bool path = o.scene.technique == "path";
  std::vector<std::pair<int, RenderOptions>> frames;
  if (o.frames.empty()) {
    frames.emplace_back(0, o);
  } else {
    const FrameRange range = parseFrames(o.frames, "--frames");
    for (int f = range.first; f <= range.last; f += range.step) {
      RenderOptions frame = o;
      frame.out = framePath(o.out, f, "--out");
      if (!o.png.empty()) frame.png = framePath(o.png, f, "--png");
      frames.emplace_back(f, frame);
    }
  }
  if (!o.shard.empty()) {
    // Only the path tracer's frames are independent of one another: a technique's sequence reuses
    // and carries buffers from frame to frame (docs/motion.md).
    if (!path || o.frames.empty())
      throw InputError("--shard", "", "shards the path tracer's --frames (--technique path)");
    const Shard shard = parseShard(o.shard, "--shard");
    std::vector<std::pair<int, RenderOptions>> mine;
    for (size_t k = 0; k < frames.size(); ++k)
      if (shard.owns(k)) mine.push_back(frames[k]);
    frames = std::move(mine);
  }
  for (const auto& [f, frame] : frames) checkOutputs(frame, path);
  if (!path) findTechnique(o.scene.technique);
  const Scene scene = o.scene.load();
  std::optional<StageSequence> sequence;
  if (!path) sequence.emplace(o.scene, o.scratch);
  for (const auto& [f, frame] : frames) {
    Scene at = scene.motion.empty() ? scene : sceneAt(scene, frameSeconds(f, o.fps));
    const int code = path ? renderPath(frame, at)
                          : renderTechnique(frame, *sequence, std::move(at), !o.frames.empty());
    if (code != kExitOk) return code;
  }
  return kExitOk;
}

template <class T, size_t N>
CLI::CheckedTransformer namesOf(const std::pair<const char*, T> (&names)[N]) {
  return CLI::CheckedTransformer(std::map<std::string, T>(std::begin(names), std::end(names)),
                                 CLI::ignore_case);
}

void addPathOptions(CLI::App& cmd, reference::PathTraceOptions& path) {
  cmd.add_option("--spp", path.spp, "path: samples per pixel")->check(CLI::Range(1, 1 << 20));
  cmd.add_option("--bounces", path.bounces,
                 "path: indirect bounces after the first hit (-1: unlimited, Russian roulette)")
      ->check(CLI::Range(-1, 1000));
  cmd.add_option("--seed", path.seed, "path: random seed");
  cmd.add_option("--sampler", path.sampler,
                 "path: sobol (Owen-scrambled Sobol', docs/path-tracer.md) or independent "
                 "(hashed random numbers)")
      ->transform(namesOf(reference::kSamplerNames));
  cmd.add_option("--light-sampling", path.lightSampling,
                 "path: solid_angle (uniform in the solid angle an area light subtends, "
                 "docs/path-tracer.md) or area")
      ->transform(namesOf(reference::kLightSamplingNames));
  cmd.add_option("--replicas", path.replicas,
                 "path, sobol: independently scrambled replicas whose spread gives the variance "
                 "image (docs/path-tracer.md, \"Variance\")")
      ->check(CLI::Range(1, reference::kMaxReplicas));
}

}  // namespace

void addRenderCommand(CLI::App& app, Globals& globals, Commands& commands) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd =
      app.add_subcommand("render", "render an image with a technique (" + techniqueNames() +
                                       ") or the reference path tracer (path)");
  o->scene.add(*cmd, globals, true);
  std::vector<std::string> names = techniqueList();
  names.push_back("path");
  cmd->add_option("--technique", o->scene.technique,
                  "technique: " + techniqueNames() + ", or path (the reference)")
      ->check(CLI::IsMember(names));
  addPathOptions(*cmd, o->path);
  cmd->add_option("--out", o->out, "output EXR (linear); path also writes OUT.variance.exr")
      ->required();
  cmd->add_option("--png", o->png, "also write a tone-mapped sRGB preview");
  cmd->add_flag("--terms", o->terms,
                "also write the image's light terms as OUT.<term>.exr: emission, direct, "
                "indirect_diffuse, indirect_specular (docs/accuracy.md, \"Error budget\")");
  std::string settingsHelp;
  for (const Technique& t : techniques()) settingsHelp += describeSettings(t);
  cmd->footer(settingsHelp);
  cmd->add_option("--frames", o->frames,
                  "render frames A to B (A:B, or A:B:STEP) of an animated scene, frame f at f / "
                  "fps seconds; --out (and --png) then hold a frame field such as %04d "
                  "(docs/motion.md)");
  cmd->add_option("--fps", o->fps, "frames per second of --frames")->check(CLI::Range(1e-3, 1e6));
  cmd->add_option("--shard", o->shard,
                  "I/N: with --technique path and --frames, render the frames k (in the range's "
                  "order) with k % N == I only, for a batch scheduler's job array "
                  "(docs/accuracy.md, \"Studies on a cluster\")");
  cmd->add_flag("--scratch", o->scratch,
                "run every stage of every frame, instead of reusing the buffers of the stages "
                "whose inputs did not change since the frame before (the frames are the same "
                "either way; docs/motion.md)");
  commands.push_back({cmd, [o] { return render(*o); }});
}

}  // namespace voxgi::tools
