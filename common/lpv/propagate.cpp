#include "common/lpv/propagate.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "common/lights.h"
#include "common/lpv/propagation_faces.h"
#include "common/lpv/sh_buffers.h"
#include "shaders/shared/lpv/storage.h"
#include "shaders/shared/lpv/sh.h"

namespace voxgi::lpv {
namespace {

// Y_i(d) in double (the float shBasis rounds its constants).
double basis(int i, const glm::dvec3& d) {
  const double k0 = 0.5 / std::sqrt(M_PI), k1 = std::sqrt(3.0) * k0, k2 = std::sqrt(15.0) * k0,
               k3 = std::sqrt(5.0) * k0 / 2.0, k4 = k2 / 2.0;
  switch (i) {
    case 0:
      return k0;
    case 1:
      return -k1 * d.y;
    case 2:
      return k1 * d.z;
    case 3:
      return -k1 * d.x;
    case 4:
      return k2 * d.x * d.y;
    case 5:
      return -k2 * d.y * d.z;
    case 6:
      return k3 * (3.0 * d.z * d.z - 1.0);
    case 7:
      return -k2 * d.x * d.z;
    default:
      return k4 * (d.x * d.x - d.y * d.y);
  }
}

double cosineLobe(int i) {  // A_l
  const int l = shared::shBand(i);
  return l == 0 ? M_PI : (l == 1 ? 2.0 * M_PI / 3.0 : M_PI / 4.0);
}

}  // namespace

Propagation preparePropagation(const LpvSettings& s, int resolution) {
  Propagation out;
  const double perSteradian =
      s.normalization == LpvNormalization::energy ? 1.0 / M_PI : 1.0 / (4.0 * M_PI);
  for (const PropagationFace& f : propagationFaces(s.directionCount())) {
    shared::PropagationEntry e{};
    e.offset = glm::ivec4(f.offset, 0);
    for (int i = 0; i < 9; ++i) {
      e.sampled[i] = float(basis(i, f.direction));
      e.reprojected[i] = float(f.solidAngle * perSteradian * cosineLobe(i) * basis(i, f.normal));
    }
    for (int i = 0; i < 4; ++i) e.blocking[i] = float(basis(i, -f.direction));
    out.entries.push_back(e);
  }
  out.steps = propagationSteps(s, resolution);
  out.params.resolution = resolution;
  out.params.coefficients = s.coefficients();
  out.params.entryCount = int(out.entries.size());
  out.params.clampNegative = s.clampNegative == LpvToggle::on ? 1 : 0;
  return out;
}

std::vector<uint32_t> packStoredVolume(const std::vector<float>& volume, int values,
                                       const shared::PropagateParams& params) {
  const size_t cells = volume.size() / size_t(values);
  const size_t words = size_t(shared::packedCellWords(values));
  std::vector<uint32_t> packed(cells * words, 0u);
  for (size_t cell = 0; cell < cells; ++cell)
    for (int v = 0; v < values; ++v) {
      uint32_t& w = packed[cell * words + size_t(v / 2)];
      w = shared::packStored(w, v % 2, volume[cell * size_t(values) + size_t(v)], params);
    }
  return packed;
}

void unpackStoredVolume(const uint32_t* packed, size_t cells, int values,
                        const shared::PropagateParams& params, uint32_t* out) {
  const size_t words = size_t(shared::packedCellWords(values));
  for (size_t cell = 0; cell < cells; ++cell)
    for (int v = 0; v < values; ++v)
      out[cell * size_t(values) + size_t(v)] = std::bit_cast<uint32_t>(
          shared::unpackStored(packed[cell * words + size_t(v / 2)], v % 2, params));
}

void prepareStorage(const LpvSettings& s, shared::PropagateParams& params,
                    std::vector<float>& volume) {
  params.halfPrecision = 0;
  params.storageScale = params.inverseStorageScale = 1.0f;
  if (s.storage == LpvStorage::f32) return;
  float largest = 0.0f;
  for (float v : volume) largest = std::max(largest, std::abs(v));
  int exponent = 0;
  if (largest > 0.0f) std::frexp(largest, &exponent);  // largest < 2^exponent
  const float scale = std::ldexp(1.0f, exponent);
  params.halfPrecision = 1;
  params.storageScale = scale;
  params.inverseStorageScale = 1.0f / scale;
  for (float& v : volume) v = shared::storedValue(v, params);
}

shared::ShadeParams shadeParams(const StageContext& ctx) {
  const double s = ctx.scene.grid.voxelSize();
  shared::ShadeParams p{};
  const int lights = ctx.plan.runs(StageId::lpv_rsm)
                         ? int(sceneLights(ctx.scene, ctx.settings.vct.emitters).size())
                         : 0;
  p.resolution = ctx.scene.grid.resolution;
  p.coefficients = ctx.settings.lpv.coefficients();
  p.lightCount = lights;
  p.inverseCellArea = float(1.0 / (s * s));
  p.offsetCells = ctx.settings.lpv.shadeOffset;
  p.camera = glm::vec4(glm::vec3(ctx.scene.grid.toVoxel(ctx.scene.camera.position)), 0.0f);
  return p;
}

}  // namespace voxgi::lpv
