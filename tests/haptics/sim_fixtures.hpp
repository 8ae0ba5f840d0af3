// The two thesis scenarios, each run once per test executable and shared by the tests reading it.
#pragma once

#include <map>

#include "haptics/sim/closed_loop.hpp"
#include "robot_fixtures.hpp"

namespace needle::haptics::test {

inline const Scenario& scenario(const std::string& name) {
  static std::map<std::string, Scenario> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, load_scenario(asset("assets/scenarios/" + name + ".json"))).first;
  return it->second;
}

inline const SimResult& scenario_run(const std::string& name) {
  static std::map<std::string, SimResult> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, run_closed_loop(scenario(name), true)).first;
  return it->second;
}

}  // namespace needle::haptics::test
