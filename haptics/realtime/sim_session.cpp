#include "haptics/realtime/sim_session.hpp"

#include "haptics/realtime/haptic_loop.hpp"

namespace needle::haptics {
namespace {

double checked_period(double rate_hz) {
  check_loop_rate(rate_hz);
  return 1.0 / rate_hz;
}

}  // namespace

SimSession::SimSession(const std::string& scenario_path, double rate_hz)
    : SimSession(load_scenario(scenario_path), rate_hz) {}

SimSession::SimSession(Scenario scenario, double rate_hz)
    : scenario_(std::move(scenario)), device_(scenario_, checked_period(rate_hz)), step_(scenario_, 1.0 / rate_hz) {}

}  // namespace needle::haptics
