#version 450
// Scan lines: one work item a line marches down its samples through the layers at their rest
// position (the tissue's displacement undone), reflects at each interface and at the needle's wall
// (with its reverberation tail), attenuates, and writes each sample's echo: the tissue's
// backscatter on the scatterer of its cell (a fixed random phasor: speckle that stays put) plus the
// specular echoes, split between the two samples around their depth. Mirrors the CPU reference,
// engine/ultrasound/echo_model.cpp (trace_scan_lines).
#extension GL_GOOGLE_include_directive : require
#include "ultrasound.glsl"

layout(local_size_x = 64) in;

struct LayerSample {
  float phi;
  vec3 normal;
};

LayerSample point_distance(vec3 x, vec3 c, float r) {
  vec3 d = x - c;
  float len = length(d);
  if (len < 1e-12) return LayerSample(-r, vec3(1.0, 0.0, 0.0));
  return LayerSample(len - r, d / len);
}

LayerSample evaluate_primitive(Primitive p, vec3 x) {
  int kind = int(p.a_kind.w);
  if (kind == 1) return LayerSample(dot(p.b_radius.xyz, x - p.a_kind.xyz), p.b_radius.xyz);
  if (kind == 2) {
    vec3 axis = p.b_radius.xyz - p.a_kind.xyz;
    float len2 = dot(axis, axis);
    float t = len2 > 0.0 ? clamp(dot(x - p.a_kind.xyz, axis) / len2, 0.0, 1.0) : 0.0;
    return point_distance(x, p.a_kind.xyz + t * axis, p.b_radius.w);
  }
  return point_distance(x, p.a_kind.xyz, p.b_radius.w);
}

LayerSample evaluate_layer(uint k, vec3 x) {
  Layer layer = layers[k];
  bool intersection = layer.shape.z == 1u;
  LayerSample best = LayerSample(intersection ? -1e30 : 1e30, vec3(1.0, 0.0, 0.0));
  for (uint i = 0; i < layer.shape.y; ++i) {
    LayerSample s = evaluate_primitive(primitives[layer.shape.x + i], x);
    if (intersection ? s.phi > best.phi : s.phi < best.phi) best = s;
  }
  return best;
}

int layer_at(vec3 x) {
  for (int k = int(echo.counts.z) - 1; k >= 0; --k)
    if (evaluate_layer(uint(k), x).phi < 0.0) return k;
  return -1;
}

vec3 rest_position(vec3 x) {
  vec3 rest = x;
  if (echo.counts.w == 0u) return rest;
  for (int i = 0; i < 4; ++i) {  // echo_model.hpp kRestIterations
    vec3 u = vec3(0.0);
    mat3 unused = mat3(0.0);
    for (uint k = 0; k < echo.counts.w; ++k) add_kelvinlet(echo.loads[k], rest, echo.material.x, echo.material.y, false, u, unused);
    rest = x - u;
  }
  return rest;
}

float impedance(int layer) { return layer < 0 ? echo.media.x : layers[layer].material.x; }
float reflection(float z1, float z2) { return (z2 - z1) / (z2 + z1); }
float specular_factor(vec3 normal) {
  float theta = acos(min(1.0, abs(dot(normal, echo.direction.xyz))));
  return exp(-(theta * theta) / (echo.beam.w * echo.beam.w));
}
float time_gain(float depth) { return exp(2.0 * echo.beam.y * depth); }

// A random number in [0, 1) from integer coordinates (a PCG-style integer hash): the same cell
// always gives the same numbers.
uint hash(uvec3 v) {
  uint h = v.x * 747796405u + v.y * 2891336453u + v.z * 1181783497u;
  h ^= h >> 16; h *= 2246822519u; h ^= h >> 13; h *= 3266489917u; h ^= h >> 16;
  return h;
}

// The scatterer of the cell holding rest position x: a unit phasor scaled by 1/sqrt(density), or none.
vec2 scatterer(vec3 x, float density) {
  uvec3 cell = uvec3(ivec3(floor(x / echo.display.w)));
  uint h = hash(cell);
  if (float(h & 0xffffu) / 65536.0 >= density) return vec2(0.0);
  float phase = 6.283185307 * float(h >> 16) / 65536.0;
  return vec2(cos(phase), sin(phase)) / sqrt(density);
}

// Where the line meets the needle's near wall and the echo's weight, 0 when it misses it
// (echo_model.cpp, needle_hit).
vec2 needle_hit(vec3 line_origin) {
  if (echo.needle_tip.w == 0.0) return vec2(0.0);
  vec3 a = echo.needle_axis.xyz, tip = echo.needle_tip.xyz - line_origin;
  float x0 = dot(tip, echo.lateral.xyz), z0 = dot(tip, echo.direction.xyz), e0 = dot(tip, echo.elevation.xyz);
  float al = dot(a, echo.lateral.xyz), ad = dot(a, echo.direction.xyz), ae = dot(a, echo.elevation.xyz);
  float r = echo.needle.x;
  float t0 = 0.0, t1 = echo.needle_axis.w;
  if (abs(al) < 1e-9) {
    if (abs(x0) > r) return vec2(0.0);
  } else {
    float ta = (x0 - r) / al, tb = (x0 + r) / al;
    t0 = max(t0, min(ta, tb));
    t1 = min(t1, max(ta, tb));
    if (t0 > t1) return vec2(0.0);
  }
  float t = abs(ae) > 1e-9 ? clamp(e0 / ae, t0, t1) : clamp(abs(al) < 1e-9 ? t0 : x0 / al, t0, t1);
  float elevation = e0 - t * ae;
  float tilt = asin(min(1.0, abs(ad)));
  float weight = exp(-0.5 * elevation * elevation / (echo.needle.y * echo.needle.y)) * exp(-(tilt * tilt) / (echo.beam.w * echo.beam.w));
  if (weight < 1e-3) return vec2(0.0);
  float wall = r / sqrt(max(1.0 - ad * ad, 1e-2));
  return vec2(z0 - t * ad - wall, weight);
}

void main() {
  uint line = gl_GlobalInvocationID.x;
  if (line >= echo.counts.x) return;
  uint samples = echo.counts.y;
  vec3 beam = echo.direction.xyz;
  vec3 origin = echo.origin.xyz + ((float(line) + 0.5) * echo.image.w - 0.5 * echo.image.y) * echo.lateral.xyz;
  vec2 hit = needle_hit(origin);
  uint base = line * samples;

  uint count = 0u;
  float shadow = -1.0;
  float amplitude = 1.0;  // round trip, without time-gain compensation
  int current = -1;
  float z_prev = 0.0;
  vec3 rest_prev = rest_position(origin);
  vec2 pending = vec2(0.0);  // the previous sample's echo, which later echoes may still add to
  float tail = 0.0, tail_depth = 0.0;  // the needle's reverberation: next echo and where
  int tail_left = 0;
  for (uint j = 0u; j < samples; ++j) {
    float z = (float(j) + 0.5) * echo.image.z;
    vec3 rest = rest_position(origin + z * beam);
    int layer = layer_at(rest);
    float span = z - z_prev;
    vec2 here = vec2(0.0);
    if (layer != current) {
      int k = layer > current ? layer : current;
      float phi0 = evaluate_layer(uint(k), rest_prev).phi;
      LayerSample s1 = evaluate_layer(uint(k), rest);
      float f = phi0 != s1.phi ? clamp(phi0 / (phi0 - s1.phi), 0.0, 1.0) : 0.0;
      float depth = z_prev + f * span;
      if (count < MAX_INTERFACES) lines[line].interfaces[count++] = Interface(depth, current, layer, 0.0);
      float r = reflection(impedance(current), impedance(layer));
      float echo_amplitude = amplitude * abs(r) * specular_factor(s1.normal) * time_gain(depth);
      if (j > 0u) pending.x += echo_amplitude * (1.0 - f);
      here.x += echo_amplitude * (j > 0u ? f : 1.0);
      amplitude *= 1.0 - r * r;
      current = layer;
    }
    if (hit.y > 0.0 && hit.x > z_prev && hit.x <= z) {
      float r = reflection(impedance(current), echo.media.y);
      float f = (hit.x - z_prev) / span;
      float echo_amplitude = amplitude * abs(r) * hit.y * time_gain(hit.x);
      if (j > 0u) pending.x += echo_amplitude * (1.0 - f);
      here.x += echo_amplitude * (j > 0u ? f : 1.0);
      amplitude *= 1.0 - r * r * hit.y;
      tail = echo_amplitude * echo.media.z;
      tail_depth = hit.x + 2.0 * echo.needle.x;
      tail_left = int(echo.needle.z);
    }
    while (tail_left > 0 && tail_depth <= z) {
      float f = clamp((tail_depth - z_prev) / span, 0.0, 1.0);
      pending.x += tail * (1.0 - f);
      here.x += tail * f;
      tail *= echo.media.z;
      tail_depth += 2.0 * echo.needle.x;
      --tail_left;
    }
    float alpha = current < 0 ? 0.0 : layers[current].material.y * echo.beam.x;
    amplitude *= exp(-2.0 * alpha * span);
    float gained = amplitude * time_gain(z);
    if (shadow < 0.0 && gained < echo.media.w) shadow = z;
    if (current >= 0) {
      float backscatter = gained * echo.beam.z * layers[current].material.z;
      if (echo.kernel.z == 1u)
        here += backscatter * echo.display.z * scatterer(rest, layers[current].material.w);
      else
        here.x += backscatter;
    }
    if (j > 0u) echoes[base + j - 1u] = pending;
    pending = here;
    z_prev = z;
    rest_prev = rest;
  }
  echoes[base + samples - 1u] = pending;
  lines[line].count = count;
  lines[line].shadow_depth = shadow;
  lines[line].needle_depth = hit.x;
  lines[line].needle_weight = hit.y;
}
