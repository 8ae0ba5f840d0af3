#include "printed_messages.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <memory>

namespace needle::cli {
namespace {

// A progress bar on a terminal; on a pipe, a line every quarter.
class ProgressBar {
 public:
  void show(double done, double total) {
    const int percent = total > 0.0 ? int(100.0 * std::min(done / total, 1.0)) : 100;
    if (percent == shown_ || (!tty_ && percent % 25 != 0)) return;
    shown_ = percent;
    const int filled = percent / 5;
    std::fprintf(stderr, "%s  [%.*s%*s] %3d%%  %.1f of %.1f s simulated%s", tty_ ? "\r" : "", filled,
                 "####################", 20 - filled, "", percent, done, total, tty_ ? "" : "\n");
    if (tty_ && percent == 100) std::fputc('\n', stderr);
    if (percent == 100) shown_ = -1;  // the next run's bar starts afresh
  }

 private:
  bool tty_ = isatty(STDERR_FILENO);
  int shown_ = -1;
};

}  // namespace

app::Messages printed_messages(const std::string& command) {
  auto bar = std::make_shared<ProgressBar>();
  return {[](const std::string& line) {
            std::printf("%s\n", line.c_str());
            std::fflush(stdout);
          },
          [command](const std::string& warning) { std::fprintf(stderr, "%s: %s\n", command.c_str(), warning.c_str()); },
          [bar](double done, double total) { bar->show(done, total); }};
}

}  // namespace needle::cli
