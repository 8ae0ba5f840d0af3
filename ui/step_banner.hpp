// The banner over the 3D view when a step ends (docs/SCORING.md, "The trainee panel"): for a few
// seconds, "Step 2 of 5 timed out: insert" and why ("The 20 s limit passed; the step needed the tip
// 25-35 mm deep along the planned axis, in the tissue, held 0.5 s."), or "completed" and what comes next. Worked out
// from the step records and the newest state's time alone, so a picture taken as a step ends shows it too.
#pragma once

#include <optional>
#include <string>

#include "training/tasks/task_progress.hpp"

namespace needle::ui {

// How long the banner stays after a step ends: design value, long enough to read its two short lines
// (about 20 words) before the next step's cues take the eye, short enough not to hide the view long.
inline constexpr double kBannerSeconds = 4.0;

struct StepBanner {
  std::string title;   // "Step 2 of 5 timed out: insert"
  std::string detail;  // why, or what comes next
  bool completed = false;
};

// The banner of the last step that ended within kBannerSeconds before `now_s`; nullopt when none.
std::optional<StepBanner> step_banner(const training::Task& task, const training::TaskProgress& progress, double now_s);

// Draws it at the top of the view, centred, green when the step was completed, red when it was not.
void draw_step_banner(const StepBanner& banner);

}  // namespace needle::ui
