#version 450
// Scan lines: one work item a line walks its samples in depth order (their layers and scatterers
// from ultrasound_cells.comp), reflects at each interface (placed between its two samples where
// the crossed surface's φ changes sign) and at the needle's wall (with its reverberation tail),
// attenuates, and turns each sample's scatterer into its echo: the tissue's backscatter on that
// phasor plus the specular echoes, split between the two samples around their depth. Mirrors the
// CPU reference, engine/ultrasound/echo_model.cpp (trace_scan_lines).
#extension GL_GOOGLE_include_directive : require
#include "ultrasound.glsl"

layout(local_size_x = 64) in;

float impedance(int layer) { return layer < 0 ? echo.media.x : layers[layer].material.x; }
float reflection(float z1, float z2) { return (z2 - z1) / (z2 + z1); }
float specular_factor(vec3 normal) {
  float theta = acos(min(1.0, abs(dot(normal, echo.direction.xyz))));
  return exp(-(theta * theta) / (echo.beam.w * echo.beam.w));
}
float time_gain(float depth) { return exp(2.0 * echo.beam.y * depth); }

// Where the line meets the needle's near wall and the echo's weight, 0 when it misses it
// (echo_model.cpp, needle_hit).
vec2 needle_hit(vec3 origin) {
  if (echo.needle_tip.w == 0.0) return vec2(0.0);
  vec3 a = echo.needle_axis.xyz, tip = echo.needle_tip.xyz - origin;
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
  vec3 origin = line_origin(line);
  vec2 hit = needle_hit(origin);
  uint base = line * samples;

  uint count = 0u;
  float shadow = -1.0;
  float amplitude = 1.0;  // round trip, without time-gain compensation
  int current = -1;
  float alpha = 0.0;      // the current layer's attenuation, Np/m one way
  float z_prev = 0.0;
  vec2 pending = vec2(0.0);  // the previous sample's echo, which later echoes may still add to
  float tail = 0.0, tail_depth = 0.0;  // the needle's reverberation: next echo and where
  int tail_left = 0;
  for (uint j = 0u; j < samples; ++j) {
    float z = sample_depth(j);
    int layer = cell_layers[base + j];
    vec2 scatter = echoes[base + j];
    float span = z - z_prev;
    vec2 here = vec2(0.0);
    if (layer != current) {
      int k = layer > current ? layer : current;
      float phi0 = evaluate_layer(uint(k), rest_position(origin + z_prev * beam)).phi;
      LayerSample s1 = evaluate_layer(uint(k), rest_position(origin + z * beam));
      float f = phi0 != s1.phi ? clamp(phi0 / (phi0 - s1.phi), 0.0, 1.0) : 0.0;
      float depth = z_prev + f * span;
      if (count < MAX_INTERFACES) lines[line].interfaces[count++] = Interface(depth, current, layer, 0.0);
      float r = reflection(impedance(current), impedance(layer));
      float echo_amplitude = amplitude * abs(r) * specular_factor(s1.normal) * time_gain(depth);
      if (j > 0u) pending.x += echo_amplitude * (1.0 - f);
      here.x += echo_amplitude * (j > 0u ? f : 1.0);
      amplitude *= 1.0 - r * r;
      current = layer;
      alpha = current < 0 ? 0.0 : layers[current].material.y * echo.beam.x;
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
    amplitude *= exp(-2.0 * alpha * span);
    float gained = amplitude * time_gain(z);
    if (shadow < 0.0 && gained < echo.media.w) shadow = z;
    if (current >= 0) here += gained * echo.beam.z * layers[current].material.z * echo.display.z * scatter;
    if (j > 0u) echoes[base + j - 1u] = pending;
    pending = here;
    z_prev = z;
  }
  echoes[base + samples - 1u] = pending;
  lines[line].count = count;
  lines[line].shadow_depth = shadow;
  lines[line].needle_depth = hit.x;
  lines[line].needle_weight = hit.y;
}
