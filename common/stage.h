// What a stage runs on: the scene, the settings, and inputs prepared once for both backends.
#pragma once

#include <string>

#include "common/buffer.h"
#include "common/scene.h"
#include "common/voxel_triangles.h"

namespace voxgi {

enum class VoxelizeMode { conservative, antialiased };
VoxelizeMode parseVoxelizeMode(const std::string& text);  // throws InputError
const char* voxelizeModeName(VoxelizeMode mode);

struct Settings {
  VoxelizeMode voxelizeMode = VoxelizeMode::conservative;
};

struct StageContext {
  const Scene& scene;
  const Settings& settings;
  const VoxelTriangles& triangles;  // prepareVoxelTriangles(scene, scene.grid)
};

// Checks the grid and memory before a stage allocates its buffers on `scene.grid`;
// throws InputError naming the scene's grid.resolution.
void checkStageMemory(const Scene& scene, std::string_view stage, double copies = 1.0);

}  // namespace voxgi
