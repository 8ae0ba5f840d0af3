// The application's messages (app/messages.hpp) as needle-sim prints them: each line on stdout,
// flushed at once (a window's run goes on after its score: whoever reads the output sees it now);
// each warning on stderr after "needle-sim COMMAND: "; a headless run's progress as a bar on a
// terminal, a line every quarter on a pipe (CI, logs).
#pragma once

#include <string>

#include "app/messages.hpp"

namespace needle::cli {

// `command`: the words that name the command in a warning ("needle-sim report").
app::Messages printed_messages(const std::string& command);

}  // namespace needle::cli
