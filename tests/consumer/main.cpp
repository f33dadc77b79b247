// Loads a scene and voxelizes it with the installed voxgi libraries, through the stage runner.
#include <iostream>

#include <voxgi/common/pipeline.h>
#include <voxgi/common/scene_io/scene_load.h>
#include <voxgi/cpu/backend.h>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  voxgi::Scene scene = voxgi::loadScene(argv[1]);
  scene.grid.resolution = 16;
  const voxgi::Settings settings;
  const voxgi::VoxelTriangles triangles = voxgi::prepareVoxelTriangles(scene, scene.grid);
  const voxgi::StageContext ctx{voxgi::findTechnique("vct"), scene, settings, triangles};
  voxgi::BufferSet buffers;
  voxgi::cpu::CpuBackend cpu;
  voxgi::runPipeline(cpu, ctx, buffers, &voxgi::stageSpec(voxgi::StageId::common_voxelize));
  size_t occupied = 0;
  const voxgi::Buffer& opacity = buffers.at(voxgi::BufferId::common_voxelize_opacity);
  for (size_t e = 0; e < opacity.elementCount(); ++e) occupied += opacity.get<float>(e, 0) > 0.0f;
  std::cout << "consumer: " << occupied << " occupied voxels\n";
  return occupied > 0 ? 0 : 1;
}
