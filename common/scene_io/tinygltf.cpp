// The one translation unit that compiles tinygltf's implementation (common/scene_io/tinygltf.h).
#include <fstream>  // its writers use std::ofstream without including it under TINYGLTF_NO_FS

#define TINYGLTF_IMPLEMENTATION
#include "common/scene_io/tinygltf.h"
