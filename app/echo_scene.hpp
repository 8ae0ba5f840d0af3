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

struct ProbePlan {
  engine::UltrasoundProbe probe;
  bool follow_needle = false;  // the view's probe moves over the tip in the needle's plane
};
// The task's probe; without one, a 7.5 MHz linear probe, 60 mm deep, on the skin over the task's
// first point marker with its beams straight down (world −z), following the needle.
ProbePlan task_probe(const training::Task& task, const engine::EchoScene& echo);

}  // namespace needle::app
