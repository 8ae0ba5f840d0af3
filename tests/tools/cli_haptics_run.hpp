// Runs needle-sim with arguments and captures exit code and stdout (stderr to a file).
#pragma once

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>
#include "tests/support/test_paths.hpp"

namespace needle::test {

struct RunResult {
  int exit_code = -1;
  std::string out;
};

inline RunResult run_needle_sim(const std::string& args) {
  RunResult r;
  const std::string command = test::needle_sim_exe().string() + " " + args + " 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer{};
  size_t got = 0;
  while ((got = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) r.out.append(buffer.data(), got);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace needle::test
