// Runs needle-sim (or any command line) in a shell and captures its exit code and output.
// (One header for every command-line test: two helpers of one name in two headers broke the
// one-definition rule, and the program.)
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

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

struct SplitResult {
  int exit_code = -1;
  std::string out;  // stdout alone (JSON a command prints)
  std::string err;  // stderr alone
};

// needle-sim with its stdout and stderr kept apart.
inline SplitResult run_needle_sim_split(const std::string& arguments) {
  const std::filesystem::path err_file = test::output_dir() / ("stderr_" + std::to_string(::getpid()) + ".txt");
  std::filesystem::create_directories(err_file.parent_path());
  const ProcessResult stdout_only =
      run_command("(" + test::needle_sim_exe().string() + " " + arguments + " 2>'" + err_file.string() + "')");
  SplitResult r{stdout_only.exit_code, stdout_only.output, ""};
  std::ifstream in(err_file);
  r.err.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  std::filesystem::remove(err_file);
  return r;
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
