// A task whose one step holds from the first tick (the tip starts out of the tissue, far from the
// sphere's centre): it ends at once, so a test can drive what comes after a task (the score
// panel's choices, the store) without running one.
#pragma once

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/test_paths.hpp"

namespace needle::test {

inline void write_quick_task(const std::filesystem::path& file, const std::string& name, const std::string& title) {
  const std::filesystem::path assets = source_dir() / "assets";
  const nlohmann::json task = {{"name", name},
                               {"title", title},
                               {"description", "ends at once"},
                               {"scene", (assets / "scenes/penetrable_sphere.json").string()},
                               {"scenario", (assets / "scenarios/nonholonomic_needle.json").string()},
                               {"markers", {{{"name", "centre"}, {"point", {0.4, 0.0, 0.0}}}}},
                               {"steps",
                                {{{"id", "out"},
                                  {"instruction", "Stay out."},
                                  {"condition", {{"type", "withdrawn"}, {"marker", "centre"}, {"within_m", 0.01}}}}}}};
  std::ofstream(file) << task.dump(2);
}

}  // namespace needle::test
