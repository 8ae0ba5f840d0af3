// What the application has to tell its user as it works: what it did ("wrote out/run/score.json"),
// a warning about something that did not stop the work, the progress of a headless run. app/
// prints nothing itself: whoever runs it (needle-sim) hands it a Messages that prints, and a
// caller that gives none (a test) hears nothing.
#pragma once

#include <cstdarg>
#include <cstdio>
#include <functional>
#include <string>

namespace needle::app {

struct Messages {
  std::function<void(const std::string&)> line;                 // a line of what is happening or was done
  std::function<void(const std::string&)> warning;              // something wrong that did not stop the work
  std::function<void(double done_s, double total_s)> progress;  // simulated seconds of a headless run

  void say(const std::string& text) const {
    if (line) line(text);
  }
  void warn(const std::string& text) const {
    if (warning) warning(text);
  }
  void advance(double done_s, double total_s) const {
    if (progress) progress(done_s, total_s);
  }
};

// printf's formatting into a string, for a message's line.
[[gnu::format(printf, 1, 2)]] inline std::string formatted(const char* format, ...) {
  va_list args, again;
  va_start(args, format);
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  std::string out(size_t(n > 0 ? n : 0), '\0');
  std::vsnprintf(out.data(), out.size() + 1, format, again);
  va_end(again);
  return out;
}

}  // namespace needle::app
