// voxgi voxelize: a scene's voxelize stage into an OpenVDB file.
#include <iostream>
#include <memory>

#include "common/error.h"
#include "common/io/output_file.h"
#include "common/io/vdb_io.h"
#include "tools/command.h"

namespace voxgi::tools {
namespace {

struct VoxelizeOptions {
  SceneOptions scene;
  std::string out;
  bool sums = false;
};

int runVoxelize(const VoxelizeOptions& o) {
  checkOutputPath(o.out);
  const StageSpec& voxelize = stageSpec(StageId::common_voxelize);
  // --sums keeps the fixed-point sums (the plan's voxel_sums), as voxgi dump does.
  const StageRun run = runStages(o.scene, &voxelize, o.sums);
  // A voxel is occupied exactly when its weight sum is not 0, and so its opacity is above 0.
  size_t occupied = 0;
  const Buffer& opacity = run.buffers.at(BufferId::common_voxelize_opacity);
  for (size_t e = 0; e < opacity.elementCount(); ++e) occupied += opacity.get<float>(e, 0) > 0.0f;
  writeVdb(o.out, buffersOf(run.buffers, voxelize, o.sums), run.scene.grid,
           {{"voxgi_mode", voxelizeModeName(run.settings.voxelizeMode)},
            {"voxgi_backend", run.backend.gpu ? run.backend.context->renderer() : "cpu"}});
  std::cout << "voxelized " << run.scene.triangleCount() << " triangles into "
            << run.scene.grid.resolution << "^3 (" << voxelizeModeName(run.settings.voxelizeMode)
            << ", " << run.backendName() << "): " << occupied << " occupied voxels in "
            << run.seconds << " s -> " << o.out << "\n";
  return kExitOk;
}

}  // namespace

void addVoxelizeCommand(CLI::App& app, Globals& globals, Commands& commands) {
  auto o = std::make_shared<VoxelizeOptions>();
  CLI::App* cmd = app.add_subcommand("voxelize", "voxelize a scene into an OpenVDB file");
  o->scene.add(*cmd, globals, true);
  cmd->add_option("--out", o->out, "output .vdb")->required();
  cmd->add_flag("--sums", o->sums, "also write the fixed-point sums");
  commands.push_back({cmd, [o] { return runVoxelize(*o); }});
}

}  // namespace voxgi::tools
