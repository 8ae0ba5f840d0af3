// The instructor's review window over the session database: the table of sessions, the chosen
// session's detail with plots, its replay in the 3D view, and a second session to compare it with;
// in its Class tab the instructor's class view (ui/cohort_panel.hpp) (docs/REVIEW.md). It reads while runs write (the
// store's WAL), and picks up new and finished sessions every couple of seconds.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "app/messages.hpp"
#include "engine/extent.hpp"

namespace needle::app {

struct ReviewOptions {
  std::filesystem::path db;
  engine::Extent size{1600, 900};
  int64_t session = 0;      // the session to open first
  bool class_view = false;  // open on the Class tab
  long frames = 0;          // close after this many frames (0: when the user closes it)
  std::optional<std::string> screenshot;
  Messages messages;  // what the window tells its user (how frames reach it, the frames presented, ...)
};

// Needs a display and an existing database (runtime_error naming it otherwise). Returns 0.
int run_review_window(const ReviewOptions& options);

}  // namespace needle::app
