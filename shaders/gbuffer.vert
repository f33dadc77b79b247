#version 450 core
// gbuffer: the scene's voxel-local triangles (3 vertices each, pulled by gl_VertexID) through the
// camera's view-projection.
#include "surface_vertices.glsl"
uniform mat4 uViewProjection;
out vec3 vPosition;

void main() {
  vPosition = surfaceVertex(gl_VertexID);
  gl_Position = uViewProjection * vec4(vPosition, 1.0f);
}
