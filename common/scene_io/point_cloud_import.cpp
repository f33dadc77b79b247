// Point clouds into the scene: a PLY's points in world space, with the colour space, transform
// and estimates the scene asks for (docs/scene-format.md, docs/svo.md "Point clouds").
#include <cmath>

#include <tbb/blocked_range.h>

#include "common/error.h"
#include "common/io/image_io.h"
#include "common/parallel.h"
#include "common/scene_io/point_cloud_ply.h"
#include "common/scene_io/point_neighbours.h"
#include "common/scene_io/scene_load.h"

namespace voxgi {

void importPointCloud(Scene& scene, const std::string& path, const glm::dmat4& transform,
                      uint32_t material, const PointCloudOptions& options) {
  PlyPoints file = readPlyPoints(path);
  if (file.positions.empty()) throw InputError(path, "element vertex", "no points");
  PointCloud cloud;
  cloud.name = path;
  cloud.material = material;
  // Positions by the transform, normals by its inverse transpose, radii by its mean scale.
  const glm::dmat3 linear(transform);
  const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(linear));
  const double scale = std::cbrt(std::abs(glm::determinant(linear)));
  const bool colors = options.colors != PointCloudOptions::Colors::ignore && !file.colors.empty();
  const bool srgb = options.colors == PointCloudOptions::Colors::srgb;
  cloud.positions = std::move(file.positions);
  cloud.normals = std::move(file.normals);
  cloud.radii = std::move(file.radii);
  if (colors) cloud.colors = std::move(file.colors);
  parallelFor(
      tbb::blocked_range<size_t>(0, cloud.size(), 16384), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i) {
          cloud.positions[i] = glm::dvec3(transform * glm::dvec4(cloud.positions[i], 1.0));
          if (!cloud.normals.empty())
            cloud.normals[i] =
                glm::vec3(glm::normalize(normalMatrix * glm::dvec3(cloud.normals[i])));
          if (!cloud.radii.empty()) cloud.radii[i] = float(cloud.radii[i] * scale);
          if (colors && srgb) {
            const glm::vec3 c = cloud.colors[i];
            cloud.colors[i] = glm::vec3(srgbToLinear(c.x), srgbToLinear(c.y), srgbToLinear(c.z));
          }
        }
      });
  if (cloud.normals.empty() && !options.estimateNormals)
    throw InputError(path, "element vertex",
                     "no normals (nx ny nz); in a scene file, \"normals\": \"estimate\" estimates "
                     "them from each point's neighbours");
  scene.pointClouds.push_back(std::move(cloud));
}

void estimatePointCloudProperties(Scene& scene, const std::vector<PointCloudOptions>& options) {
  for (size_t c = 0; c < scene.pointClouds.size(); ++c) {
    PointCloud& cloud = scene.pointClouds[c];
    if (cloud.radii.empty()) estimateRadii(cloud);
    if (cloud.normals.empty())
      estimateNormals(cloud, options[c].viewpoint.value_or(scene.camera.position));
  }
}

}  // namespace voxgi
