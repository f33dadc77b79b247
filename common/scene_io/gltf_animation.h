// glTF animations (glTF 2.0 §3.11) as keys on the file's nodes: every animation in the file plays
// at once from 0 s, each channel keying a node's translation, rotation or scale.
#pragma once

#include <string>

#include "common/scene_io/gltf_authored.h"
#include "common/scene_io/tinygltf.h"

namespace voxgi {

// Keys authored.nodes from the animations of `model` (the file `path`). Morph-target weights are
// not read (voxgi moves meshes rigidly); a node part keyed by two animations keeps the first's keys
// (docs/motion.md). Throws InputError naming the file and the animation's field for a channel that
// names no node or sampler, keys a node given by a matrix, or whose keys are malformed.
void readGltfAnimations(const std::string& path, const tinygltf::Model& model,
                        GltfAuthored& authored);

}  // namespace voxgi
