// The blocks' samples of trace_cones at cones.diffuse_scale = s > 1: which pixel of an s x s block
// traces the block's diffuse cones, and the record it leaves (DiffuseSample, cone_types.h) for
// diffuse_upsample.h to blend. Shared by cpu/vct/trace_cones.cpp and
// shaders/vct/trace_cones_samples.comp.
#ifndef VOXGI_DIFFUSE_SAMPLES_H
#define VOXGI_DIFFUSE_SAMPLES_H
#include "../cone/pixel_light.h"

VOXGI_NAMESPACE_BEGIN

// The block's pixel tried k-th (k = 0 .. s^2 - 1) for its sample: the block's centre first, then
// on in scan order, wrapping; the first with a surface is the sample.
VOXGI_FN ivec2 blockCandidate(int k, int scale) {
  int centre = scale / 2;
  int i = (centre * scale + centre + k) % (scale * scale);
  return ivec2(i % scale, i / scale);
}

VOXGI_FN DiffuseSample diffuseSample(vec3 p, vec3 n, DiffuseSum s) {
  DiffuseSample d;
  d.position = vec4(p, 1.0f);
  d.normal = vec4(n, 0.0f);
  d.radiance = vec4(s.radiance, 0.0f);
  d.sums = vec4(s.ambient, s.weights, 0.0f, 0.0f);
  return d;
}

// The sample of a block whose sample pixel is at p with unit normal n: its diffuse cone set as
// tracePixel traces it.
VOLUME_FN DiffuseSample traceDiffuseSample(VOLUMES_IN vec3 p, vec3 n, ConeTraceParams params) {
  return diffuseSample(p, n, traceDiffuse(VOLUMES p, n, params));
}

VOXGI_FN DiffuseSample noDiffuseSample() {
  DiffuseSample d;
  d.position = vec4(0.0f);
  d.normal = vec4(0.0f);
  d.radiance = vec4(0.0f);
  d.sums = vec4(0.0f);
  return d;
}

VOXGI_NAMESPACE_END
#endif
