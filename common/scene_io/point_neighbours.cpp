#include "common/scene_io/point_neighbours.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <nanoflann.hpp>
#include <tbb/blocked_range.h>

#include "common/error.h"
#include "common/parallel.h"

namespace voxgi {
namespace {

// nanoflann's view of the positions.
struct Points {
  const std::vector<glm::dvec3>& p;
  size_t kdtree_get_point_count() const { return p.size(); }
  double kdtree_get_pt(size_t i, size_t axis) const { return p[i][int(axis)]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using Tree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Points>,
                                                 Points, 3, uint32_t>;

// f(i, indices, squared distances) with the kNeighbours nearest points of every point (itself
// first), in parallel; each point's neighbours depend on the positions alone.
template <class F>
void forEachNeighbourhood(const PointCloud& cloud, const F& f) {
  if (cloud.size() < size_t(kNeighbours))
    throw InputError(cloud.name, "",
                     "estimating radii or normals needs at least " + std::to_string(kNeighbours) +
                         " points, the cloud has " + std::to_string(cloud.size()));
  const Points points{cloud.positions};
  Tree tree(3, points, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  parallelFor(
      tbb::blocked_range<size_t>(0, cloud.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
        std::array<uint32_t, kNeighbours> index;
        std::array<double, kNeighbours> d2;
        for (size_t i = r.begin(); i != r.end(); ++i) {
          const double q[3] = {cloud.positions[i].x, cloud.positions[i].y, cloud.positions[i].z};
          tree.knnSearch(q, kNeighbours, index.data(), d2.data());
          f(i, index, d2);
        }
      });
}

}  // namespace

void estimateRadii(PointCloud& cloud) {
  constexpr int k = 8;
  std::vector<float> radii(cloud.size());
  // Sorted by distance with the point itself (distance 0) first: entry k is the k-th other point.
  forEachNeighbourhood(cloud, [&](size_t i, const auto&, const auto& d2) {
    radii[i] = float(std::sqrt(2.0 / k) * std::sqrt(d2[k]));
  });
  std::vector<float> positive;
  for (const float r : radii)
    if (r > 0.0f) positive.push_back(r);
  if (positive.empty())
    throw InputError(cloud.name, "radius",
                     "cannot estimate radii: every point shares its position with 8 others");
  std::nth_element(positive.begin(), positive.begin() + ptrdiff_t(positive.size() / 2),
                   positive.end());
  const float median = positive[positive.size() / 2];
  for (float& r : radii)
    if (r == 0.0f) r = median;
  cloud.radii = std::move(radii);
}

void estimateNormals(PointCloud& cloud, const glm::dvec3& viewpoint) {
  std::vector<glm::vec3> normals(cloud.size());
  forEachNeighbourhood(cloud, [&](size_t i, const auto& index, const auto&) {
    glm::dvec3 mean(0.0);
    for (const uint32_t j : index) mean += cloud.positions[j];
    mean /= double(index.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const uint32_t j : index) {
      const glm::dvec3 d = cloud.positions[j] - mean;
      const Eigen::Vector3d e(d.x, d.y, d.z);
      covariance += e * e.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(covariance);
    const Eigen::Vector3d v = solver.eigenvectors().col(0);  // eigenvalues ascend
    glm::dvec3 n(v.x(), v.y(), v.z());
    const double length = glm::length(n);
    n = length > 0.0 ? n / length : glm::dvec3(0.0, 0.0, 1.0);
    if (glm::dot(n, viewpoint - cloud.positions[i]) < 0.0) n = -n;
    normals[i] = glm::vec3(n);
  });
  cloud.normals = std::move(normals);
}

}  // namespace voxgi
