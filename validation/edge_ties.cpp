// Tie classifiers of the stages that cast a ray per pixel or texel on the CPU and rasterize on the
// GPU. Triangles: an element whose triangle differs is a tie when a 4-neighbour in the same image
// picked another triangle on the CPU (the element lies on a triangle edge there). Discs (point
// clouds in the gbuffer): the element is a tie when the ray meets either disc within a rounding of
// its rim, or meets both surfaces at depths the GPU's depth buffer cannot tell apart.
#include <cmath>
#include <memory>
#include <stdexcept>

#include "common/camera_geometry.h"
#include "validation/diff.h"

namespace voxgi::validation {
namespace {

// Whether element e of `c` (primitive ids of images `rows` rows high stacked along y) has a
// 4-neighbour in its image with another id.
bool onEdge(const Buffer& c, size_t e, int rows) {
  const uint32_t mine = c.words[e];
  const int w = c.extent.x;
  const int x = int(e % size_t(w)), y = int(e / size_t(w));
  const int top = y / rows * rows;
  const int dx[] = {1, -1, 0, 0}, dy[] = {0, 0, 1, -1};
  for (int i = 0; i < 4; ++i) {
    const int nx = x + dx[i], ny = y + dy[i];
    if (nx < 0 || ny < top || nx >= w || ny >= top + rows) continue;
    if (c.words[size_t(ny) * size_t(w) + size_t(nx)] != mine) return true;
  }
  return false;
}

TieClassifier edgeTies(const Buffer& c, const Buffer& g, int rows) {
  return [&c, &g, rows](size_t e) { return c.words[e] != g.words[e] && onEdge(c, e, rows); };
}

// Distance along d (unnormalised) from o to the plane through p with normal n.
float planeDistance(glm::vec3 o, glm::vec3 d, glm::vec3 p, glm::vec3 n) {
  const float facing = glm::dot(d, n);
  return facing == 0.0f ? INFINITY : glm::dot(p - o, n) / facing;
}

// Where the disc rim decides: the hit's distance from the centre within this fraction of the
// radius (both backends compute it in float from the same values, a few ULP apart).
constexpr float kRim = 1e-4f;
// A float depth buffer's resolution at ray distance t: z = (f / (f - n)) (1 - n / t) moves by
// n / t^2 per unit of t, and z near 1 has ULPs of 2^-24; 16 of them cover interpolation.
float depthResolution(float t) {
  return 16.0f * std::ldexp(1.0f, -24) * t * t / kGbufferNearPlane;
}

}  // namespace

TieClassifier gbufferTies(const StageContext& ctx, const BufferSet& cpu, const BufferSet& gpu) {
  const Buffer& c = cpu.at(BufferId::common_gbuffer_primitive_id);
  const Buffer& g = gpu.at(BufferId::common_gbuffer_primitive_id);
  const int rows = c.extent.y;
  if (ctx.scene.pointClouds.empty()) return edgeTies(c, g, rows);
  auto geometry = std::make_shared<CameraGeometry>(prepareCameraGeometry(ctx.scene));
  return [&c, &g, rows, geometry](size_t e) {
    const uint32_t ids[2] = {c.words[e], g.words[e]};
    if (ids[0] == ids[1]) return false;
    const auto triangles = uint32_t(geometry->triangles.size());
    if (ids[0] <= triangles && ids[1] <= triangles) return onEdge(c, e, rows);
    const CameraRays& cam = geometry->camera;
    const int w = c.extent.x;
    const glm::vec3 d = cam.pixelDirection(int(e % size_t(w)), int(e / size_t(w)));
    float t[2] = {0.0f, 0.0f};
    for (int k = 0; k < 2; ++k) {
      if (ids[k] == 0) continue;
      if (ids[k] <= triangles) {
        const size_t i = ids[k] - 1;
        t[k] = planeDistance(cam.origin, d, geometry->vertices[3 * i],
                             glm::vec3(geometry->triangles[i].normal));
        continue;
      }
      const SurfaceDisc& disc = geometry->discs[ids[k] - triangles - 1];
      const glm::vec3 centre(disc.center);
      t[k] = planeDistance(cam.origin, d, centre, glm::vec3(disc.normal));
      const float q = glm::length(cam.origin + d * t[k] - centre) / disc.radius;
      if (std::abs(q - 1.0f) <= kRim) return true;
    }
    return ids[0] != 0 && ids[1] != 0 &&
           std::abs(t[0] - t[1]) <= depthResolution(std::max(t[0], t[1]));
  };
}

TieClassifier mapTies(const StageSpec& stage, const BufferSet& cpu, const BufferSet& gpu) {
  for (const BufferSpec* b : stageBuffers(stage))
    if (b->name == "primitive_id") {
      const Buffer& c = cpu.at(b->id);
      return edgeTies(c, gpu.at(b->id), c.extent.x);  // square maps: a map is as high as wide
    }
  throw std::logic_error(stage.qualifiedName() +
                         " compares texel_edges ties but declares no primitive_id buffer");
}

}  // namespace voxgi::validation
