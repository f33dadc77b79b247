// Loads a scene and voxelizes it with the installed voxgi libraries.
#include <iostream>

#include <voxgi/common/scene_load.h>
#include <voxgi/cpu/stages.h>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  voxgi::Scene scene = voxgi::loadScene(argv[1]);
  scene.grid.resolution = 16;
  const voxgi::Settings settings;
  const voxgi::VoxelTriangles triangles = voxgi::prepareVoxelTriangles(scene, scene.grid);
  voxgi::BufferSet buffers;
  voxgi::cpu::voxelize({scene, settings, triangles}, buffers);
  size_t occupied = 0;
  for (uint32_t w : buffers.at("weight_sum").words) occupied += w != 0u;
  std::cout << "consumer: " << occupied << " occupied voxels\n";
  return occupied > 0 ? 0 : 1;
}
