#version 450
// Tissue deformation: each work item moves one rest vertex by the windowed regularized
// Kelvinlets of this frame and turns its normal by the field's Jacobian. Mirrors
// engine/deformation/kelvinlet.cpp and engine/deformation/deformation_field.cpp (deform), the
// double-precision reference.
layout(local_size_x = 64) in;

#define MAX_LOADS 8
struct Load {
  vec4 center_epsilon;  // xyz centre, w regularization radius ε (model space)
  vec4 force_support;   // xyz force, w window radius R
};
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
  for (uint i = 0; i < field.counts.x; ++i) {
    vec3 r = p - field.loads[i].center_epsilon.xyz;
    float t = dot(r, r);
    float support2 = field.loads[i].force_support.w * field.loads[i].force_support.w;
    if (t >= support2) continue;
    vec3 f = field.loads[i].force_support.xyz;
    float eps2 = field.loads[i].center_epsilon.w * field.loads[i].center_epsilon.w;
    float re2 = t + eps2, re = sqrt(re2), re3 = re2 * re, re5 = re3 * re2;
    float A = (a - b) / re + a * eps2 / (2.0 * re3);
    float B = b / re3;
    float A_t = -(a - b) / (2.0 * re3) - 3.0 * a * eps2 / (4.0 * re5);
    float B_t = -1.5 * b / re5;
    float rf = dot(r, f);
    vec3 val = A * f + B * rf * r;
    float q = 1.0 - t / support2;
    float w = q * q, w_t = -2.0 * q / support2;
    // outerProduct(c, r) is c rᵀ, as glm's.
    mat3 dv = 2.0 * A_t * outerProduct(f, r) + 2.0 * B_t * rf * outerProduct(r, r) + B * (rf * mat3(1.0) + outerProduct(r, f));
    u += w * val;
    jacobian += 2.0 * w_t * outerProduct(val, r) + w * dv;
  }
  vec3 deformed_normal = normalize(inverse(transpose(mat3(1.0) + jacobian)) * n);
  vec3 deformed_position = p + u;
  vertices[12 * v + 0] = deformed_position.x;
  vertices[12 * v + 1] = deformed_position.y;
  vertices[12 * v + 2] = deformed_position.z;
  vertices[12 * v + 3] = deformed_normal.x;
  vertices[12 * v + 4] = deformed_normal.y;
  vertices[12 * v + 5] = deformed_normal.z;
}
