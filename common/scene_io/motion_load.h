// The `animation` fields of a scene file (docs/motion.md): keyframes of a mesh entry's transform,
// of a light's position, direction and intensity, and of the camera's position, look_at and up.
#pragma once

#include "common/scene_io/json_field.h"
#include "common/scene_motion.h"

namespace voxgi {

// A `transform` object: translate, rotate_deg, scale (a number or three, non-zero).
TransformFields readTransformFields(const Field& f);

// meshes[i].animation: keyframes of "translate", "rotate_deg" and "scale" (keys of `node`).
void readMeshMotion(const Field& f, NodeMotion& node);
// lights[i].animation: keyframes of "position", "direction" and "intensity".
LightMotion readLightMotion(const Field& f, size_t light);
// camera.animation: keyframes of "position", "look_at" and "up".
CameraMotion readCameraMotion(const Field& f);

}  // namespace voxgi
