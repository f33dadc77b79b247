// Scenes the light propagation volume tests light: boxes, point lights, emitters, a shaded floor.
#pragma once

#include <vector>

#include "common/buffer.h"
#include "common/scene.h"
#include "common/technique.h"
#include "tests/test_scenes.h"

namespace voxgi::test {

const Technique& lpvTechnique();

// The six faces of the cube [lo, hi]^3.
std::vector<Triangle> cubeFaces(double lo, double hi);

Material grey(glm::vec3 albedo);

Light pointLight(glm::dvec3 at, glm::vec3 intensity);

// Adds `triangles` as a mesh of their own, of an emissive material (albedo 0).
void addEmitter(Scene& scene, const std::vector<Triangle>& triangles, glm::vec3 radiance);

// A square [lo, hi]^2 of the plane y = at, wound to face -y.
std::vector<Triangle> downwardSquare(double at, double lo, double hi);

// Direct light on a floor at y = 0.1 under a blocker, seen from between them looking down (the
// whole shadow in view), with a 128^2 RSM.
BufferSet shadeFloor(Scene scene);

// The pixels of shadeFloor's image that see the floor (the scene's first two triangles): the
// element, where it is in world units and its direct diffuse light.
struct FloorPixel {
  size_t element;
  glm::dvec3 position;
  glm::vec3 direct;
};
std::vector<FloorPixel> shadedFloorPixels(const Scene& scene);

}  // namespace voxgi::test
