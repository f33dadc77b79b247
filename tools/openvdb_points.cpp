#include "tools/openvdb_points.h"

#include <cmath>

#ifndef VOXGI_NO_OPENVDB_POINTS
#include <openvdb/openvdb.h>
#include <openvdb/points/PointConversion.h>
#include <openvdb/points/PointRasterizeTrilinear.h>
#endif

#include "tools/bench.h"

namespace voxgi::tools {

double openVdbPointsSeconds(const PointCloud& cloud, double leaf, int repeats) {
#ifdef VOXGI_NO_OPENVDB_POINTS
  (void)cloud, (void)leaf, (void)repeats;
  return std::nan("");
#else
  openvdb::initialize();
  std::vector<openvdb::Vec3R> positions(cloud.size());
  std::vector<openvdb::Vec3f> colors(cloud.size());
  for (size_t i = 0; i < cloud.size(); ++i) {
    positions[i] = openvdb::Vec3R(cloud.positions[i].x, cloud.positions[i].y, cloud.positions[i].z);
    const glm::vec3 c = cloud.colors.empty() ? glm::vec3(0.8f) : cloud.colors[i];
    colors[i] = openvdb::Vec3f(c.x, c.y, c.z);
  }
  const openvdb::points::PointAttributeVector<openvdb::Vec3R> wrapper(positions);
  const auto transform = openvdb::math::Transform::createLinearTransform(leaf);
  return medianSeconds(repeats, [&] {
    const auto index =
        openvdb::tools::createPointIndexGrid<openvdb::tools::PointIndexGrid>(wrapper, *transform);
    auto grid = openvdb::points::createPointDataGrid<openvdb::points::NullCodec,
                                                     openvdb::points::PointDataGrid>(
        *index, wrapper, *transform);
    openvdb::points::appendAttribute<openvdb::Vec3f>(grid->tree(), "Cd");
    const openvdb::points::PointAttributeVector<openvdb::Vec3f> cd(colors);
    openvdb::points::populateAttribute<openvdb::points::PointDataTree,
                                       openvdb::tools::PointIndexTree,
                                       openvdb::points::PointAttributeVector<openvdb::Vec3f> >(
        grid->tree(), index->tree(), "Cd", cd);
    const auto raster =
        openvdb::points::rasterizeTrilinear<false, openvdb::Vec3f>(grid->tree(), "Cd");
    if (raster->activeVoxelCount() == 0) throw std::runtime_error("OpenVDB rasterised nothing");
  });
#endif
}

}  // namespace voxgi::tools
