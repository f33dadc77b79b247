// Voxelization arithmetic shared by cpu/voxelize.cpp and shaders/voxelize.{frag,comp}: the exact
// per-(triangle, voxel) decision and weights, so both backends compute bit-identical sums.
// See docs/stages/voxelize.md for the method and glsl_cpp.h for the rules of shared code.
#ifndef VOXGI_VOXELIZE_KERNEL_H
#define VOXGI_VOXELIZE_KERNEL_H
#include "vector_math.h"
#include "voxelize_layout.h"

VOXGI_NAMESPACE_BEGIN

// Permutes p so that the dominant axis becomes z: (p[a+1], p[a+2], p[a]) (indices mod 3).
VOXGI_FN vec3 toDominant(vec3 p, uint axis) {
  if (axis == 0u) return vec3(p.y, p.z, p.x);
  if (axis == 1u) return vec3(p.z, p.x, p.y);
  return p;
}

// Inverse of toDominant for voxel indices.
VOXGI_FN ivec3 fromDominant(ivec3 c, uint axis) {
  if (axis == 0u) return ivec3(c.z, c.x, c.y);
  if (axis == 1u) return ivec3(c.y, c.z, c.x);
  return c;
}

// Signed separation of the triangle (a, b, c) from the box [-1/2, 1/2]^3 along one axis:
// > 0 separated, <= 0 the projections overlap (closed intervals). Not normalised by |axis|.
VOXGI_FN float axisSeparation(vec3 axis, vec3 a, vec3 b, vec3 c) {
  precise float pa = dot3(axis, a);
  precise float pb = dot3(axis, b);
  precise float pc = dot3(axis, c);
  precise float r = 0.5f * ((abs(axis.x) + abs(axis.y)) + abs(axis.z));
  precise float lo = min(pa, min(pb, pc));
  precise float hi = max(pa, max(pb, pc));
  precise float s = max(lo - r, -r - hi);
  return s;
}

// Separating-axis test of the closed triangle (a, b, c), given relative to a voxel's centre,
// against the closed voxel [-1/2, 1/2]^3 over the 13 axes (3 box normals, the triangle normal, 9
// edge crosses). Returns the largest separation: > 0 means disjoint, <= 0 means they touch. With
// `normalized`, each axis's separation is divided by its length (a distance in voxels) — used only
// by the CPU tie classifier, the decision itself never divides.
VOXGI_FN float satSeparation(vec3 a, vec3 b, vec3 c, bool normalized) {
  precise vec3 e0 = b - a;
  precise vec3 e1 = c - b;
  precise vec3 e2 = a - c;
  precise float worst = -3.0e38f;
  for (int i = 0; i < 13; ++i) {
    precise vec3 axis;
    if (i < 3) {
      axis = vec3(i == 0 ? 1.0f : 0.0f, i == 1 ? 1.0f : 0.0f, i == 2 ? 1.0f : 0.0f);
    } else if (i == 3) {
      axis = cross3(e0, e1);
    } else {
      int k = i - 4;
      precise vec3 unit =
          vec3(k % 3 == 0 ? 1.0f : 0.0f, k % 3 == 1 ? 1.0f : 0.0f, k % 3 == 2 ? 1.0f : 0.0f);
      precise vec3 edge = k < 3 ? e0 : (k < 6 ? e1 : e2);
      axis = cross3(unit, edge);
    }
    precise float s = axisSeparation(axis, a, b, c);
    if (!normalized && s > 0.0f) return s;  // deciding only: the first separating axis settles it
    if (normalized) {
      precise float len = sqrt(dot3(axis, axis));
      if (len == 0.0f) continue;  // an edge parallel to a box axis gives no axis
      s = s / len;
    }
    worst = max(worst, s);
  }
  return worst;
}

// Area of the part of triangle (a, b, c) (relative to the voxel centre) inside the closed voxel,
// projected on the plane normal to `axis`: Sutherland-Hodgman clipping against the 6 faces, then
// the shoelace formula. Multiply by the triangle's area scale for the true area. `centre` is the
// mean of the clipped polygon's corners (where a textured triangle is sampled for the voxel).
VOXGI_FN float projectedAreaInVoxel(vec3 a, vec3 b, vec3 c, uint axis, OUT(vec3) centre) {
  vec3 poly[9];
  vec3 next[9];
  poly[0] = a;
  poly[1] = b;
  poly[2] = c;
  int n = 3;
  for (int plane = 0; plane < 6 && n > 0; ++plane) {
    int comp = plane / 2;
    precise float side = (plane % 2 == 0) ? 1.0f : -1.0f;
    int m = 0;
    for (int i = 0; i < n; ++i) {
      precise vec3 p = poly[i];
      precise vec3 q = poly[(i + 1) % n];
      precise float dp = side * p[comp] - 0.5f;
      precise float dq = side * q[comp] - 0.5f;
      if (dp <= 0.0f) next[m++] = p;
      if ((dp < 0.0f && dq > 0.0f) || (dp > 0.0f && dq < 0.0f)) {
        precise float t = dp / (dp - dq);
        precise vec3 x = p + t * (q - p);
        x[comp] = side * 0.5f;
        next[m++] = x;
      }
    }
    for (int i = 0; i < m; ++i) poly[i] = next[i];
    n = m;
  }
  precise vec3 sum = vec3(0.0f);
  for (int i = 0; i < n; ++i) sum = sum + poly[i];
  centre = sum / float(max(n, 1));
  precise float twice = 0.0f;
  for (int i = 0; i < n; ++i) {
    precise vec3 p = toDominant(poly[i], axis);
    precise vec3 q = toDominant(poly[(i + 1) % n], axis);
    twice = twice + (p.x * q.y - q.x * p.y);
  }
  precise float area = 0.5f * abs(twice);
  return area;
}

// Margin, in voxels, on interpolated plane heights: far above their float error for N <= 2048.
const float kLayerMargin = 0.0078125f;

// The layers (voxel range along the dominant axis, inclusive, clamped to [0, N-1]) that the
// triangle can touch inside column `col` of the dominant plane: closed layer k spans [k, k+1], so
// it can touch heights [zlo, zhi] iff ceil(zlo) - 1 <= k <= floor(zhi); the heights are the
// triangle's plane over the column's square, widened by kLayerMargin (the separating-axis test
// decides).
VOXGI_FN ivec2 columnLayers(VoxelTriangle t, ivec2 col, int resolution) {
  uint axis = t.dominantAxis;
  precise vec3 p0 = toDominant(vec3(t.v0), axis);
  precise vec3 p1 = toDominant(vec3(t.v1), axis);
  precise vec3 p2 = toDominant(vec3(t.v2), axis);
  precise vec3 n = cross3(p1 - p0, p2 - p0);
  precise float zlo = 3.0e38f;
  precise float zhi = -3.0e38f;
  for (int corner = 0; corner < 4; ++corner) {
    precise float u = float(col.x + (corner % 2));
    precise float w = float(col.y + (corner / 2));
    precise float z = p0.z - (n.x * (u - p0.x) + n.y * (w - p0.y)) / n.z;
    zlo = min(zlo, z);
    zhi = max(zhi, z);
  }
  precise float tlo = min(p0.z, min(p1.z, p2.z));
  precise float thi = max(p0.z, max(p1.z, p2.z));
  precise float limit = float(resolution) + 1.0f;
  zlo = clamp(max(zlo - kLayerMargin, tlo), -1.0f, limit);
  zhi = clamp(min(zhi + kLayerMargin, thi), -1.0f, limit);
  return ivec2(max(int(ceil(zlo)) - 1, 0), min(int(floor(zhi)), resolution - 1));
}

// Rounds a non-negative fixed-point value to the nearest unit (ties up).
VOXGI_FN uint quantize(float x) {
  return uint(floor(x + 0.5f));
}
VOXGI_FN int quantizeSigned(float x) {
  return int(floor(x + 0.5f));
}

// The sums a triangle adds with the given fixed-point weight, where its albedo and emission (over
// the emission scale) are these.
VOXGI_FN VoxelContribution weightedContribution(VoxelTriangle t, uint weight, vec3 albedo,
                                                vec3 emission) {
  precise float w = float(weight);
  VoxelContribution c;
  c.weight = weight;
  c.emitterWeight = vec3(t.emission) == vec3(0.0f) ? 0u : weight;
  c.albedo = uvec3(quantize(w * albedo.x), quantize(w * albedo.y), quantize(w * albedo.z));
  c.normal = ivec3(quantizeSigned(w * t.normal.x), quantizeSigned(w * t.normal.y),
                   quantizeSigned(w * t.normal.z));
  c.emission = uvec3(quantize(w * emission.x), quantize(w * emission.y), quantize(w * emission.z));
  return c;
}

// Conservative mode: does triangle t touch voxel `voxel`, and with what weight? The weight is the
// triangle's area inside the voxel, at least one unit, so a touch without area still counts;
// `centre` is where the triangle's part inside the voxel is sampled (voxel-local).
VOXGI_FN bool conservativeWeight(VoxelTriangle t, ivec3 voxel, OUT(uint) weight, OUT(vec3) centre) {
  precise vec3 middle = vec3(voxel) + vec3(0.5f);
  precise vec3 a = vec3(t.v0) - middle;
  precise vec3 b = vec3(t.v1) - middle;
  precise vec3 d = vec3(t.v2) - middle;
  if (satSeparation(a, b, d, false) > 0.0f) return false;
  vec3 local;
  precise float area = projectedAreaInVoxel(a, b, d, t.dominantAxis, local) * t.areaScale;
  weight = max(1u, quantize(area * kWeightScale));
  centre = local + middle;
  return true;
}

// Antialiased mode: the triangle is split into n*n congruent sub-triangles (row i, column j,
// pointing up or down); each sub-triangle's centroid is one sample of area t.sampleArea, at
// barycentric weights (b1, b2) of v1 and v2.
VOXGI_FN vec2 antialiasedBarycentric(VoxelTriangle t, int i, int j, bool up) {
  precise float n = float(t.subdivision);
  precise float offset = up ? 0.33333334f : 0.6666667f;
  precise float b1 = (float(i) + offset) / n;
  precise float b2 = (float(j) + offset) / n;
  return vec2(b1, b2);
}
VOXGI_FN vec3 antialiasedSample(VoxelTriangle t, vec2 b) {
  precise vec3 v0 = vec3(t.v0);
  precise vec3 p = (v0 + b.x * (vec3(t.v1) - v0)) + b.y * (vec3(t.v2) - v0);
  return p;
}

// The samples of row i in splatting order, the one order every backend and the tie classifier
// use: cell j's upward sub-triangle (k = 2j), then its downward one (k = 2j + 1); the last cell of
// a row has only the upward half.
VOXGI_FN int antialiasedRowSamples(VoxelTriangle t, int i) {
  return 2 * (int(t.subdivision) - i) - 1;
}
VOXGI_FN vec2 antialiasedRowBarycentric(VoxelTriangle t, int i, int k) {
  return antialiasedBarycentric(t, i, k / 2, k % 2 == 0);
}

// The voxel whose centre is the lower corner of the trilinear tent cell holding p.
VOXGI_FN ivec3 tentBase(vec3 p) {
  return ivec3(floor(p - vec3(0.5f)));
}

// A sample's weight for corner (0..7: bit 0 = +x, bit 1 = +y, bit 2 = +z) of its tent cell:
// sample area times the trilinear (tent) kernel, in fixed-point units before rounding.
VOXGI_FN float tentWeightValue(VoxelTriangle t, vec3 p, ivec3 base, int corner) {
  precise vec3 f = p - vec3(0.5f) - vec3(base);
  precise float wx = (corner % 2 == 1) ? f.x : 1.0f - f.x;
  precise float wy = ((corner / 2) % 2 == 1) ? f.y : 1.0f - f.y;
  precise float wz = (corner / 4 == 1) ? f.z : 1.0f - f.z;
  precise float w = ((wx * wy) * wz) * (t.sampleArea * kWeightScale);
  return w;
}

// The rounded weight; zero weights add nothing.
VOXGI_FN uint tentWeight(VoxelTriangle t, vec3 p, ivec3 base, int corner) {
  return quantize(tentWeightValue(t, p, base, corner));
}

VOXGI_FN ivec3 tentCorner(ivec3 base, int corner) {
  return base + ivec3(corner % 2, (corner / 2) % 2, corner / 4);
}

// Resolves a voxel's sums to averages; zero where nothing was accumulated.
VOXGI_FN vec3 resolveAverage(uvec3 sum, uint weight) {
  if (weight == 0u) return vec3(0.0f);
  precise float w = float(weight);
  precise vec3 r = vec3(float(sum.x) / w, float(sum.y) / w, float(sum.z) / w);
  return r;
}

VOXGI_FN vec3 resolveNormal(ivec3 sum, uint weight) {
  if (weight == 0u) return vec3(0.0f);
  precise float w = float(weight);
  precise vec3 r = vec3(float(sum.x) / w, float(sum.y) / w, float(sum.z) / w);
  return r;
}

VOXGI_FN vec3 resolveEmission(uvec3 sum, uint weight, float emissionScale) {
  precise vec3 r = resolveAverage(sum, weight) * emissionScale;
  return r;
}

// Opacity: conservative mode marks every touched voxel opaque; antialiased mode uses the
// splatted area density (h^2 units), clamped to 1.
VOXGI_FN float resolveOpacity(uint weight, bool antialiased) {
  if (!antialiased) return weight > 0u ? 1.0f : 0.0f;
  return min(1.0f, float(weight) * (1.0f / kWeightScale));
}

VOXGI_NAMESPACE_END
#endif
