// The scenarios, each run once per test executable and law and shared by the tests reading it.
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

// The run with the scenario's own law (the default, ControlLaw::Tool, unless it names one).
inline const SimResult& scenario_run(const std::string& name) {
  static std::map<std::string, SimResult> cache;
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, run_closed_loop(scenario(name), true)).first;
  return it->second;
}

// The run with the given law.
inline const SimResult& scenario_run(const std::string& name, ControlLaw law) {
  if (law == scenario(name).gains.law) return scenario_run(name);
  static std::map<std::string, SimResult> cache;
  auto it = cache.find(name);
  if (it == cache.end()) {
    Scenario s = scenario(name);
    s.gains.law = law;
    it = cache.emplace(name, run_closed_loop(s, true)).first;
  }
  return it->second;
}

}  // namespace needle::haptics::test
