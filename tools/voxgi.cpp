// The voxgi command line (docs/architecture.md, "Command line"): one file per command
// (tools/command.h). Exit codes: 0 ok, 1 internal failure or a failed diff, 2 bad input (one line
// naming the file and field).
#include <malloc.h>

#include <filesystem>
#include <iostream>
#include <memory>

#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include "common/error.h"
#include "gpu/context.h"
#include "tools/command.h"

using namespace voxgi;

int main(int argc, char** argv) {
  // Keep what is freed for the next allocation instead of returning it to the system: a stage
  // that runs again (the next frame, a benchmark's repeat) then reuses its scratch and outputs of
  // the run before rather than faulting in fresh pages, which costs ~3 ms per MB on the VMs voxgi
  // is benchmarked on, 40 x a memcpy (docs/benchmarks.md). glibc otherwise maps every block over
  // 32 MB afresh and returns it on free.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  CLI::App app{"voxgi: real-time global illumination with a CPU reference and OpenGL shaders"};
  app.require_subcommand(1);
  tools::Globals globals;
  app.add_option("--threads", globals.threads, "worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  tools::Commands commands;
  tools::addVoxelizeCommand(app, globals, commands);
  tools::addDiffCommand(app, globals, commands);
  tools::addDumpCommand(app, globals, commands);
  tools::addPlanCommand(app, globals, commands);
  tools::addRenderCommand(app, globals, commands);
  tools::addLedgerCommand(app, globals, commands);
  tools::addSampleCommand(app, commands);
  tools::addCompareCommand(app, commands);
  tools::addStudyCommand(app, commands);
  tools::addBenchCommand(app, commands);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help on a subcommand, --version
    std::cerr << "voxgi: " << printable(e.what()) << " (see voxgi --help)\n";
    return kExitBadInput;
  }
  std::unique_ptr<tbb::global_control> limit;
  if (globals.threads > 0)
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  static_cast<size_t>(globals.threads));
  try {
    for (const tools::Command& command : commands)
      if (*command.app) return command.run();
  } catch (const InputError& e) {
    std::cerr << "voxgi: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::filesystem::filesystem_error& e) {
    // A path the user gave that the filesystem refuses (permissions, a full disk, a name too
    // long) where no check named it first: still one line naming the path.
    std::cerr << "voxgi: " << printable(e.path1().string()) << ": " << printable(e.code().message())
              << "\n";
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    // The memory checks before each large allocation (common/memory.h) name the field to lower;
    // this is an allocation they did not foresee.
    std::cerr << "voxgi: out of memory (an allocation failed past voxgi's memory checks)\n";
    return kExitInternal;
  } catch (const gpu::GlUnavailable& e) {
    std::cerr << "voxgi: no OpenGL 4.5 context: " << printable(e.what())
              << " (use --backend cpu or auto)\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "voxgi: internal error: " << printable(e.what()) << "\n";
    return kExitInternal;
  }
  return kExitInternal;
}
