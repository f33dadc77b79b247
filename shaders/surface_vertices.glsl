// The scene's voxel-local triangles as the surface shaders (gbuffer, lpv/rsm) read them: three
// vertices per triangle, three floats per vertex (common/camera_geometry.h's `vertices`, bound by
// gpu/surface_raster.cpp).
layout(std430, binding = 0) readonly buffer Vertices { float vertexData[]; };

// Vertex `i` of the list (3 per triangle, so gl_VertexID in the vertex stage).
vec3 surfaceVertex(int i) {
  return vec3(vertexData[3 * i], vertexData[3 * i + 1], vertexData[3 * i + 2]);
}
