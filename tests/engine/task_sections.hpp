// The section view of the two layered tasks' scenes, as the section tests set it up
// (test_section_view.cpp's goldens, test_section_geometry.cpp's needle in the cut): the layered
// target's block (assets/scenes/tissue_block_task.json) and the epidural task's lumbar section
// (lumbar_section.json), both with their top at z = 0.07 over (0.33, 0) as the tasks' markers put
// them. In plane: the needle on the task's planned axis (straight down through the entry marker)
// to the task's goal, the layered target's 35 mm target and the epidural space 50 mm down, cut
// through the needle. Out of plane: the needle entering in front of the plane y = 0 through the
// planned axis at 45 degrees and crossing it, cut by that plane fixed as a task fixes it.
#pragma once

#include <gtest/gtest.h>

#include <ostream>
#include <string>

#include "engine/gpu_scene.hpp"

namespace needle::test {

struct TaskSection {
  const char* scene;
  const char* golden;
  bool in_plane;
  double entry_y;  // out of plane: where the needle enters, in front of y = 0 (m)
  double depth;    // along the needle from the entry (m)
};
inline void PrintTo(const TaskSection& c, std::ostream* os) { *os << c.golden; }

inline const auto kTaskSections =
    ::testing::Values(TaskSection{"tissue_block_task.json", "section_layered_target_in_plane", true, 0.0, 0.034},
                      TaskSection{"tissue_block_task.json", "section_layered_target_out_of_plane", false, -0.02, 0.035},
                      TaskSection{"lumbar_section.json", "section_epidural_in_plane", true, 0.0, 0.05},
                      TaskSection{"lumbar_section.json", "section_epidural_out_of_plane", false, -0.03, 0.05});
inline std::string task_section_name(const ::testing::TestParamInfo<TaskSection>& info) {
  return std::string(info.param.golden).substr(8);  // after "section_"
}

inline engine::NeedleLoad task_needle(const TaskSection& c) {
  engine::NeedleLoad needle;
  needle.contact = engine::NeedleContact::Inserted;
  needle.surface_point = {0.33, c.in_plane ? 0.0 : c.entry_y, 0.07};
  needle.axis = c.in_plane ? glm::dvec3(0.0, 0.0, -1.0) : glm::dvec3(0.0, 0.70710678, -0.70710678);
  needle.tip = needle.surface_point + c.depth * needle.axis;
  return needle;
}

// The frame of the task's scene with its needle, nearer than the task's framing (which shows the
// whole scene and the tool's start, the needle a pixel or two wide at 320x240), so the shaft covers
// the pixels the checks read; no section yet.
inline engine::FrameParams task_frame(engine::GpuScene& scene, const engine::NeedleLoad& needle) {
  engine::FrameParams params = scene.frame_params(&needle);
  params.camera.position = params.camera.target + 0.6f * (params.camera.position - params.camera.target);
  return params;
}

// The section: through the needle in plane, the plane y = 0 facing the camera out of plane.
inline engine::Section task_section(const TaskSection& c, const engine::Camera& camera,
                                    const engine::NeedleLoad& needle) {
  if (c.in_plane) return engine::section_through_needle(camera, &needle);
  engine::Section section;
  section.point = glm::vec3(0.33f, 0.0f, 0.07f);
  section.normal = glm::vec3(0.0f, camera.position.y > camera.target.y ? 1.0f : -1.0f, 0.0f);
  return section;
}

}  // namespace needle::test
