// One session's review exported headless, for a session database on a machine without a display:
// the metrics as JSON and CSV, the plots and the review panels as PNG (docs/REVIEW.md, "report").
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>

#include "app/messages.hpp"
#include "ui/time_span.hpp"

namespace needle::app {

// Writes OUT/session_ID.{json,csv}, the plots and the panels; the replay picture shows the moment
// `at` (default: the end of the recording), the plots the time range `plots` (unchosen: the whole
// recording; a range reaching past the recording is cut to it and said, one outside it is an
// error). What it writes and notes go to `messages`. Returns 0, or 1 when a named recording cannot
// be read or the range is outside it (a warning); throws runtime_error naming the database or the
// session when they are missing.
int write_session_report(const std::filesystem::path& db, int64_t id, const std::filesystem::path& out,
                         std::optional<double> at, ui::TimeSpan plots, const Messages& messages);

}  // namespace needle::app
