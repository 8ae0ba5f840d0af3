// What the ultrasound images in a task: the haptic tissue model's layers (their shapes moved from
// the robots' base frame to the world, what each is to sound from its tissue file) with the
// scene's deformable tissue, so that the layers move as the rendered mesh does; and the probe the
// task places, or one that follows the needle. Here because it joins haptics and training to the
// engine, which know nothing of each other (docs/ARCHITECTURE.md).
#pragma once

#include "engine/scene.hpp"
#include "engine/ultrasound.hpp"
#include "haptics/sim/scenario.hpp"
#include "training/tasks/task.hpp"

namespace needle::app {

// A layer without an "ultrasound" block is imaged as engine::EchoMaterial's generic soft tissue.
engine::EchoScene echo_scene(const haptics::Scenario& scenario, const engine::Scene& scene);
// The task's scenario and scene (no layers when the task names no scenario). Throws their loaders' errors.
engine::EchoScene echo_scene(const training::Task& task);

// Whether the task's tissue layers carry their own ultrasound parameters (their tissue files'
// `ultrasound` blocks, docs/TISSUE.md): a task made to be imaged even without a probe of its own,
// as the layered tasks are. Throws the scenario loader's errors.
bool layers_have_acoustics(const training::Task& task);

engine::UltrasoundProbe to_engine(const training::UltrasoundProbeSpec& probe);

// The paramedian sagittal oblique view of a lumbar patient (its spine along +y, its back facing +z):
// a 5 MHz linear probe 60 mm wide imaging 80 mm deep, its array along the spine, `offset_m` to the
// patient's right of the midline point `over` (world) and its beam tilted `medial_tilt_rad` toward
// the midline, lowered onto the skin: the laminae's "sawtooth" and the interlaminar windows between
// them, through which the flavum, the dura and the front of the canal show. The view is the one
// Karmakar et al. (Br J Anaesth 2009;102:845-854) image before a paramedian epidural; the offset,
// tilt, width and depth are the caller's (design values there).
engine::UltrasoundProbe paramedian_sagittal_oblique_probe(const engine::EchoScene& scene, const glm::dvec3& over,
                                                          double offset_m, double medial_tilt_rad);

struct ProbePlan {
  engine::UltrasoundProbe probe;
  bool follow_needle = false;  // the view's probe moves over the tip in the needle's plane
};
// The task's probe; without one, a 7.5 MHz linear probe, 60 mm deep, on the skin over the task's
// first point marker with its beams straight down (world −z), following the needle.
ProbePlan task_probe(const training::Task& task, const engine::EchoScene& echo);

}  // namespace needle::app
