// The path tracer's area lights: the scene's emissive triangles, with each pair that forms a
// rectangle joined into one, picked by power and sampled by the solid angle they subtend where
// that lowers the variance enough to pay for itself, by area elsewhere (docs/path-tracer.md,
// "Light sampling").
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace voxgi::reference {

// Rec. 709 luminance: what the path tracer weighs emitters and lobes by.
inline float luminance(glm::vec3 c) {
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

// How a point on the chosen emitter is drawn.
enum class LightSampling {
  // Uniform in the solid angle the emitter subtends [Arvo 1995b; Urena 2013] where area
  // sampling's weight cos θ' / d² would vary by more than 2 x over it; by area elsewhere.
  solid_angle,
  area,  // uniform in area
};
// The names of the CLI, the study's sweeps and the benchmarks.
inline constexpr std::pair<const char*, LightSampling> kLightSamplingNames[] = {
    {"solid_angle", LightSampling::solid_angle}, {"area", LightSampling::area}};

struct Emitter {
  bool rectangle = false;  // else a triangle
  // A triangle's vertices p0, p0 + e1, p0 + e2; a rectangle's corner p0 and edges e1 ⟂ e2.
  glm::vec3 p0{0.0f}, e1{0.0f}, e2{0.0f};
  glm::vec3 normal{0.0f};    // unit; the side that emits
  glm::vec3 emission{0.0f};  // its material's constant; times its texture where it has one
  float area = 0.0f;
  uint32_t mesh = 0, triangle = 0;  // where it came from (a rectangle: its first triangle)
};

// A point drawn on an emitter for a shading point.
struct EmitterSample {
  glm::vec3 direction{0.0f};  // unit, from the shading point
  float distance = 0.0f;
  float cosLight = 0.0f;  // between the emitter's normal and -direction; <= 0: its back
  float pdf = 0.0f;       // per unit solid angle, the emitter's pick included
  const Emitter* emitter = nullptr;
};

// The weights of a triangle emitter's vertices p0 + e1 and p0 + e2 at point q of its plane.
glm::vec2 emitterBarycentric(const Emitter& e, glm::vec3 q);

class Emitters {
 public:
  // Adds one mesh's emissive triangles (positions in the tracer's frame). Consecutive triangles
  // that form a rectangle become one emitter (quads arrive from OBJ and glTF as such pairs),
  // unless `triangles only`: a textured emitter stays triangles, so that a point on it has
  // barycentric coordinates in its own triangle (emitterBarycentric).
  void addMesh(uint32_t mesh, const std::vector<glm::vec3>& vertices,
               const std::vector<glm::uvec3>& triangles, glm::vec3 emission,
               bool trianglesOnly = false);

  bool empty() const { return emitters_.empty(); }

  // A point for shading point x from u in [0, 1)²: u.x picks the emitter by power and, stretched
  // back to [0, 1) within its interval, is the first coordinate of the point with u.y.
  EmitterSample sample(glm::vec3 x, glm::vec2 u, LightSampling how) const;

  // The pdf per unit solid angle with which sample() from x draws the direction to the point of
  // mesh triangle (mesh, triangle) at squared distance d2 under cosine cosLight; 0 for a
  // triangle that is not an emitter.
  float pdf(glm::vec3 x, uint32_t mesh, uint32_t triangle, float d2, float cosLight,
            LightSampling how) const;

 private:
  float pickProbability(const Emitter& e) const;

  std::vector<Emitter> emitters_;
  std::vector<float> cdf_;                       // running sum of area x luminance
  float weight_ = 0.0f;                          // the total
  std::vector<std::vector<int32_t>> emitterOf_;  // per mesh, per triangle: index or -1
};

}  // namespace voxgi::reference
