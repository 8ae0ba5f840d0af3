// What the store's command-line tests share: a scripted run of the rigid sphere (44 s of session,
// seconds of wall time) as station-01 against a store, its station file and output in a folder of
// the test's own.
#pragma once

#include <filesystem>
#include <string>

#include "tests/support/test_paths.hpp"
#include "tests/tools/cli_process.hpp"

namespace needle::test {

// `run` of the rigid sphere against `uri`, the station's file and the output in `dir`.
inline std::string rigid_run_arguments(const std::string& uri, const std::filesystem::path& dir) {
  return "run --headless --size 160x120 --trainee ana --station station-01 --task " +
         quoted(source_dir() / "assets/tasks/rigid_sphere.json") + " --db '" + uri + "' --local " +
         quoted(dir / "station.db") + " --out " + quoted(dir / "out");
}

// An empty folder `name` of the store's command-line tests.
inline std::filesystem::path fresh_store_dir(const std::string& name) {
  const std::filesystem::path dir = test_output_dir("cli_store") / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace needle::test
