// A score's breakdown as the trainee and the instructor read it: each component by a plain name,
// its points out of its weight, and, where it earned nothing because it did not count, why ("not
// reached": the run never got to what it measures; "not in this task": the task does not measure
// it and the others share its weight; docs/SCORING.md, "Score"). Draws into the current ImGui window.
#pragma once

#include <string>
#include <vector>

#include "training/scoring/score.hpp"

namespace needle::ui {

// A component's name in plain words ("tip to target" for tip_error); the name itself when unknown.
std::string component_label(const std::string& name);

// The breakdown as a table of `columns` pairs of columns (name, points).
void draw_score_breakdown(const std::vector<training::ScoreComponent>& components, int columns);

}  // namespace needle::ui
