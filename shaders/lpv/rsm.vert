#version 450 core
// rsm: the scene's voxel-local triangles (3 vertices each, pulled by gl_VertexID) through one
// shadow-map view's view-projection.
layout(std430, binding = 0) readonly buffer Vertices { float vertexData[]; };
uniform mat4 uViewProjection;
out vec3 vPosition;

void main() {
  int i = 3 * gl_VertexID;
  vPosition = vec3(vertexData[i], vertexData[i + 1], vertexData[i + 2]);
  gl_Position = uViewProjection * vec4(vPosition, 1.0f);
}
