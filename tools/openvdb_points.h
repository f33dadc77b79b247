// voxgi bench svo's peer: OpenVDB's point rasterisation of a cloud. Its templates take minutes to
// compile (7 under ASan on this machine), so only release builds have it: the sanitizer builds,
// which compile voxgi for the command-line tests, report the column as absent (NaN).
#pragma once

#include "common/scene.h"

namespace voxgi::tools {

// The median seconds of `repeats` runs of createPointIndexGrid and createPointDataGrid at voxel
// size `leaf`, then the points' colour rasterised with trilinear weights (rasterizeTrilinear: a
// one-leaf RoI's weights); NaN in a build without it.
double openVdbPointsSeconds(const PointCloud& cloud, double leaf, int repeats);

}  // namespace voxgi::tools
