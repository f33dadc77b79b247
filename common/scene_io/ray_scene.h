// An Embree scene of triangle meshes and point-cloud discs for ray queries, the one place voxgi
// talks to Embree: the CPU gbuffer stage casts its pixel rays through it and the reference path
// tracer its paths.
#pragma once

#include <span>

#include <glm/glm.hpp>

namespace voxgi {

class RayScene {
 public:
  // high: a slower build for faster traversal (the path tracer traces millions of rays).
  enum class BuildQuality { medium, high };
  explicit RayScene(BuildQuality quality = BuildQuality::medium);
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  // Adds geometry `id` (ids 0, 1, ... in order): triangles indexing `vertices`. Then commit().
  void addMesh(unsigned id, std::span<const glm::vec3> vertices,
               std::span<const glm::uvec3> triangles);
  // Adds geometry `id` of oriented discs (primitive i: centre, unit normal, radius), Embree's
  // RTC_GEOMETRY_TYPE_ORIENTED_DISC_POINT: a ray meets a disc from either side.
  void addDiscs(unsigned id, std::span<const glm::vec3> centres, std::span<const glm::vec3> normals,
                std::span<const float> radii);
  // Adds geometry `id` of triangles t = vertices 3t, 3t + 1, 3t + 2 (primitive t).
  void addTriangleSoup(unsigned id, std::span<const glm::vec3> vertices);
  void commit();

  struct Hit {
    bool found = false;
    float t = 0.0f;  // distance parameter along the ray direction
    unsigned geometry = 0, primitive = 0;
    // Embree's barycentric coordinates of the hit on a triangle: the weights of its second and
    // third vertices.
    glm::vec2 barycentric{0.0f};
  };
  // The nearest triangle along o + t d, t > 0.
  Hit intersect(glm::vec3 o, glm::vec3 d) const;
  // Whether a triangle lies on o + t d for 0 < t < distance.
  bool occluded(glm::vec3 o, glm::vec3 d, float distance) const;

 private:
  struct Handles;
  Handles* handles_;
};

}  // namespace voxgi
