// What the gbuffer stage needs on both backends, prepared once: the camera, the scene's triangles
// in voxel-local coordinates (the space every later stage works in) with per-triangle unit normals
// and material indices, and its point clouds' points as discs.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "common/scene.h"
#include "shaders/shared/gbuffer_kernel.h"

namespace voxgi {

// The GPU gbuffer's near plane, in voxels (its depth buffer's resolution depends on it).
constexpr float kGbufferNearPlane = 1e-2f;

struct CameraRays {
  glm::vec3 origin, forward, right, up;  // voxel-local; right/up unit
  float tanHalfFov = 0.0f, aspect = 1.0f;
  int width = 0, height = 0;
  // Unnormalised direction through pixel (x, y)'s centre, row 0 at the top (as the path tracer).
  glm::vec3 pixelDirection(int x, int y) const;
  // A pixel's side at depth 1 (voxels per voxel of depth): its texture footprint's scale
  // (shaders/shared/surface_hit.h).
  float pixelSide() const { return 2.0f * tanHalfFov / float(height); }
  // OpenGL view-projection with depth range [near, far] in voxels and y flipped, so that GL
  // framebuffer row 0 is image row 0 and pixel centres coincide with pixelDirection's.
  glm::mat4 viewProjection(float nearPlane, float farPlane) const;
};

using shared::SurfaceDisc;
using shared::SurfaceTriangle;

struct CameraGeometry {
  CameraRays camera;
  std::vector<glm::vec3> vertices;         // 3 per triangle, voxel-local
  std::vector<SurfaceTriangle> triangles;  // one per triangle
  std::vector<SurfaceDisc> discs;          // one per point of the point clouds, cloud by cloud
  float farPlane = 1.0f;                   // beyond every vertex, in voxels
};

CameraRays cameraRays(const Scene& scene);

// The view matrix of an eye at `origin` with unit axes right, up, forward (it looks down -z).
glm::mat4 viewMatrix(glm::vec3 origin, glm::vec3 forward, glm::vec3 right, glm::vec3 up);
// A perspective projection of half-extents tanX, tanY at depth 1 and depth range [near, far],
// y flipped so that GL framebuffer row 0 is the image's top row.
glm::mat4 flippedPerspective(float tanX, float tanY, float nearPlane, float farPlane);
CameraGeometry prepareCameraGeometry(const Scene& scene);
// The scene's materials as the surface kernels read them (indexed by SurfaceTriangle::material).
std::vector<shared::MaterialData> materialData(const Scene& scene);

}  // namespace voxgi
