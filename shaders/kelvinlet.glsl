// One windowed regularized Kelvinlet (engine/deformation/kelvinlet.cpp, the double-precision
// reference): shared by the deformation pass (deform.comp) and the ultrasound's passes
// (ultrasound_lines.comp, ultrasound_echoes.comp), which undo the tissue's displacement to find
// a sample's rest position.
struct Load {
  vec4 center_epsilon;  // xyz centre, w regularization radius ε
  vec4 force_support;   // xyz force, w window radius R
};

// Adds the load's displacement at p to u and, when with_jacobian, its Jacobian to jacobian
// (a = 1/(4πμ), b = a/(4(1−ν))). Zero at and beyond the support. Callers that pass a constant
// false get the derivative terms removed by the compiler.
void add_kelvinlet(Load load, vec3 p, float a, float b, bool with_jacobian, inout vec3 u, inout mat3 jacobian) {
  vec3 r = p - load.center_epsilon.xyz;
  float t = dot(r, r);
  float support2 = load.force_support.w * load.force_support.w;
  if (t >= support2) return;
  vec3 f = load.force_support.xyz;
  float eps2 = load.center_epsilon.w * load.center_epsilon.w;
  float re2 = t + eps2, re = sqrt(re2), re3 = re2 * re;
  float A = (a - b) / re + a * eps2 / (2.0 * re3);
  float B = b / re3;
  float rf = dot(r, f);
  vec3 val = A * f + B * rf * r;
  float q = 1.0 - t / support2;
  float w = q * q;
  u += w * val;
  if (with_jacobian) {
    float re5 = re3 * re2;
    float A_t = -(a - b) / (2.0 * re3) - 3.0 * a * eps2 / (4.0 * re5);
    float B_t = -1.5 * b / re5;
    float w_t = -2.0 * q / support2;
    // outerProduct(c, r) is c rᵀ, as glm's.
    mat3 dv = 2.0 * A_t * outerProduct(f, r) + 2.0 * B_t * rf * outerProduct(r, r) + B * (rf * mat3(1.0) + outerProduct(r, f));
    jacobian += 2.0 * w_t * outerProduct(val, r) + w * dv;
  }
}
