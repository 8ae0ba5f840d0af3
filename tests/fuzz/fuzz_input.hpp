// What every fuzz target shares: a working folder that mirrors assets/ (each entry a link to the
// real one, but the folders an input is written into), so an input's relative references resolve
// as a shipped file's do ("../scenes/thesis_sphere.json", "needle.bin"); and the write of one
// input into it. The folder is made once per process, in $TMPDIR (default /tmp), and removed at
// exit.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/test_paths.hpp"

namespace needle::fuzz {

inline const std::filesystem::path& workdir() {
  namespace fs = std::filesystem;
  static const fs::path dir = [] {
    const char* tmp = std::getenv("TMPDIR");
    const fs::path d = fs::path(tmp && *tmp ? tmp : "/tmp") / ("needle-fuzz-" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    const fs::path assets = test::source_dir() / "assets";
    for (const auto& entry : fs::directory_iterator(assets)) {
      const std::string name = entry.path().filename().string();
      if (name == "scenes" || name == "tasks" || name == "scenarios") {  // inputs go in these: real folders of links
        fs::create_directories(d / name);
        for (const auto& inner : fs::directory_iterator(entry.path()))
          fs::create_symlink(inner.path(), d / name / inner.path().filename());
      } else {
        fs::create_symlink(entry.path(), d / name);
      }
    }
    std::atexit([] {
      std::error_code ignored;
      fs::remove_all(workdir(), ignored);
    });
    return d;
  }();
  return dir;
}

// Writes the input as workdir()/`relative` and returns its path.
inline std::filesystem::path write_input(const std::string& relative, const uint8_t* data, size_t size) {
  const std::filesystem::path file = workdir() / relative;
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  out.close();
  if (!out) {  // a reader given a file other than the input would test nothing
    std::fprintf(stderr, "fuzz: cannot write the input to %s\n", file.c_str());
    std::abort();
  }
  return file;
}

}  // namespace needle::fuzz
