// Scenes for the ultrasound tests, built by hand (the engine's tests do not read haptics' scenario
// files; tests/app checks the scenarios' conversion): the layered tissue block of
// assets/scenarios/tissue_block_layers.json, a muscle slab with a bone plate under half of it,
// and the probe and needles that image them.
#pragma once

#include <glm/glm.hpp>

#include "engine/ultrasound.hpp"

namespace needle::test {

// A box as the tissue model has it: the intersection of six half-spaces.
inline engine::EchoLayer echo_box(const char* name, glm::dvec3 lo, glm::dvec3 hi,
                                  const engine::EchoMaterial& material) {
  engine::EchoLayer layer{name, {}, true, material};
  for (int k = 0; k < 3; ++k) {
    glm::dvec3 e(0.0);
    e[k] = 1.0;
    layer.primitives.push_back({engine::EchoPrimitive::Kind::Plane, hi, e, 0.0});
    layer.primitives.push_back({engine::EchoPrimitive::Kind::Plane, lo, -e, 0.0});
  }
  return layer;
}

// The materials of assets/tissues/{skin,subcutaneous_fat,muscle,bone}.json's ultrasound blocks.
inline const engine::EchoMaterial kSkin{1.99, 0.35, 0.8, 1.0}, kFat{1.39, 0.63, 0.25, 0.5},
    kMuscle{1.68, 0.96, 0.45, 1.0}, kBone{6.50, 15.0, 0.9, 1.0};

// The block, world frame: 0.1 m square, skin from z = 0.07 down 2 mm, fat 10 mm, muscle 28 mm,
// bone 10 mm, centred on (0.33, 0).
inline engine::EchoScene block_scene() {
  engine::EchoScene scene;
  const double x0 = 0.28, x1 = 0.38, y0 = -0.05, y1 = 0.05;
  scene.layers = {echo_box("skin", {x0, y0, 0.068}, {x1, y1, 0.07}, kSkin),
                  echo_box("fat", {x0, y0, 0.058}, {x1, y1, 0.068}, kFat),
                  echo_box("muscle", {x0, y0, 0.03}, {x1, y1, 0.058}, kMuscle),
                  echo_box("bone", {x0, y0, 0.02}, {x1, y1, 0.03}, kBone)};
  return scene;
}

// Muscle 40 mm deep with a bone plate 10 mm thick at 25 mm under the half x > 0.33 only.
inline engine::EchoScene half_bone_scene() {
  engine::EchoScene scene;
  scene.layers = {echo_box("muscle", {0.28, -0.05, 0.03}, {0.38, 0.05, 0.07}, kMuscle),
                  echo_box("bone", {0.33, -0.05, 0.035}, {0.38, 0.05, 0.045}, kBone)};
  return scene;
}

// A linear probe on the block's skin over its centre, beams down, the array along x.
inline engine::UltrasoundProbe block_probe() {
  engine::UltrasoundProbe probe;
  probe.position = {0.33, 0.0, 0.07};
  probe.direction = {0.0, 0.0, -1.0};
  probe.lateral = {1.0, 0.0, 0.0};
  probe.depth_m = 0.05;
  probe.width_m = 0.04;
  return probe;
}

// A needle entering at `entry` along `axis` (unit), its tip `depth` metres along it.
inline engine::NeedleLoad needle_along(glm::dvec3 entry, glm::dvec3 axis, double depth) {
  engine::NeedleLoad needle;
  needle.contact = engine::NeedleContact::Inserted;
  needle.axis = glm::normalize(axis);
  needle.tip = entry + depth * needle.axis;
  needle.surface_point = entry;
  needle.surface_normal = {0.0, 0.0, 1.0};
  return needle;
}

// In the probe's plane, from the left at 30° below the skin; across it, crossing the plane at 20 mm.
inline engine::NeedleLoad in_plane_needle() {
  return needle_along({0.305, 0.0, 0.07}, {std::cos(0.5236), 0.0, -std::sin(0.5236)}, 0.04);
}
inline engine::NeedleLoad out_of_plane_needle() {
  return needle_along({0.335, -0.02, 0.07}, {0.0, 0.7071, -0.7071}, 0.032);
}

}  // namespace needle::test
