// Runs needle-sim (or any command line) in a shell and captures its exit code and output.
#pragma once

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>
#include <sys/wait.h>
#include "tests/support/test_paths.hpp"

namespace needle::test {

struct ProcessResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

inline ProcessResult run_command(const std::string& command) {
  ProcessResult result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  while (size_t n = fread(buffer.data(), 1, buffer.size(), pipe)) result.output.append(buffer.data(), n);
  int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

inline ProcessResult run_needle_sim(const std::string& arguments) {
  return run_command(std::string("NEEDLE_VALIDATION=1 ") + test::needle_sim_exe().string() + " " + arguments);
}

// A shell script on a virtual X display (xvfb-run), Vulkan validation on. Escape `$` as `\$` in
// the script: the outer shell would expand it first.
inline ProcessResult run_on_virtual_display(const std::string& script) {
  return run_command("NEEDLE_VALIDATION=1 xvfb-run -a -s '-screen 0 1024x768x24' sh -c \"" + script + "\"");
}

inline std::filesystem::path test_output_dir(const std::string& name) {
  auto dir = test::output_dir() / name;
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

}  // namespace needle::test
