#version 450
// Tissue deformation: each work item moves one rest vertex by the windowed regularized
// Kelvinlets of this frame (kelvinlet.glsl) and turns its normal by the field's Jacobian. Mirrors
// engine/deformation/deformation_field.cpp (deform), the double-precision reference.
#extension GL_GOOGLE_include_directive : require
#include "kelvinlet.glsl"

layout(local_size_x = 64) in;

#define MAX_LOADS 8
layout(set = 0, binding = 0, std140) uniform Field {
  vec4 material;  // x: a = 1/(4πμ), y: b = a/(4(1−ν))
  uvec4 counts;   // x: loads, y: ranges, z: work items (vertices to process)
  Load loads[MAX_LOADS];
} field;
layout(set = 0, binding = 1, std430) readonly buffer Rest { float rest[]; };      // 6 floats/vertex
layout(set = 0, binding = 2, std430) buffer Vertices { float vertices[]; };      // MeshVertex, 12 floats
layout(set = 0, binding = 3, std430) readonly buffer Ranges { uvec2 ranges[]; };  // (first vertex, first item)

uint vertex_of(uint item) {
  uint lo = 0, hi = field.counts.y - 1;  // the last range whose first item is <= item
  while (lo < hi) {
    uint mid = (lo + hi + 1) / 2;
    if (ranges[mid].y <= item) lo = mid; else hi = mid - 1;
  }
  return ranges[lo].x + (item - ranges[lo].y);
}

void main() {
  uint item = gl_GlobalInvocationID.x;
  if (item >= field.counts.z) return;
  uint v = vertex_of(item);
  vec3 p = vec3(rest[6 * v], rest[6 * v + 1], rest[6 * v + 2]);
  vec3 n = vec3(rest[6 * v + 3], rest[6 * v + 4], rest[6 * v + 5]);

  float a = field.material.x, b = field.material.y;
  vec3 u = vec3(0.0);
  mat3 jacobian = mat3(0.0);
  for (uint i = 0; i < field.counts.x; ++i) add_kelvinlet(field.loads[i], p, a, b, true, u, jacobian);
  vec3 deformed_normal = normalize(inverse(transpose(mat3(1.0) + jacobian)) * n);
  vec3 deformed_position = p + u;
  vertices[12 * v + 0] = deformed_position.x;
  vertices[12 * v + 1] = deformed_position.y;
  vertices[12 * v + 2] = deformed_position.z;
  vertices[12 * v + 3] = deformed_normal.x;
  vertices[12 * v + 4] = deformed_normal.y;
  vertices[12 * v + 5] = deformed_normal.z;
}
