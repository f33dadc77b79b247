#include "tools/sequence.h"

#include <chrono>
#include <iostream>

namespace voxgi::tools {

StageSequence::StageSequence(const SceneOptions& options, bool scratch)
    : options_(options),
      backend_(chooseBackend(options.backend, gpu::parseGlPlatform(options.gl))),
      runner_(findTechnique(options.technique), backend_.stages(), scratch) {
  if (!backend_.note.empty()) std::cerr << "voxgi: " << backend_.note << "\n";
}

const FrameRunner& StageSequence::frame(Scene scene) {
  const auto start = std::chrono::steady_clock::now();
  const Settings settings = options_.settings(scene);
  ran_ = 0;
  runner_.run(std::move(scene), settings, [&](const StageSpec&, double) { ++ran_; });
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return runner_;
}

std::string StageSequence::backendName() const {
  return backend_.gpu ? "gpu: " + backend_.context->renderer() : "cpu";
}

std::string StageSequence::summary() const {
  return "ran " + std::to_string(ran_) + " of " + std::to_string(runner_.steps().size()) +
         " stages (" + runner_.why() + ")";
}

}  // namespace voxgi::tools
