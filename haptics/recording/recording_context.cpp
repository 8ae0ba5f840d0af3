#include "haptics/recording/recording_context.hpp"

#include "io/strict_json.hpp"

namespace needle::haptics {
namespace {

using nlohmann::json;

// What a recording made before each key existed ran with: its absence's meaning, fixed for good.
void migrate(json& context) {
  json& scenario = context["scenario"];
  if (scenario.is_object() && scenario.contains("gains") && scenario["gains"].is_object()) {
    json& gains = scenario["gains"];
    if (!gains.contains("law")) gains["law"] = "thesis";  // before the tool law
    // Before the tool law's springs and its passivity controller: without them.
    for (const char* key : {"lateral_stiffness_N_per_m", "axial_stiffness_N_per_m", "passivity_max_damping_per_tick"})
      if (!gains.contains(key)) gains[key] = 0.0;
  }
  json& coupling = context["coupling"];
  if (coupling.is_object() && !coupling.contains("wrist")) coupling["wrist"] = false;  // before the desk devices' wrist
}

}  // namespace

json read_recording_context(const std::string& path, const SessionHeader& header) {
  auto fail = [&path](const std::string& what) { return RecordingError(path + ": header: context: " + what); };
  if (header.version < 3)
    throw RecordingError(path + ": header: format version " + std::to_string(header.version) +
                         " has no checksums and does not keep its task: it can be reviewed (needle-sim report, "
                         "review) but not replayed");
  if (header.context.empty()) throw fail("none (recorded by another program): cannot rebuild its task");
  json context;
  try {
    context = io::parse_json_text(header.context);
  } catch (const io::JsonTextError& e) {
    throw fail(e.located());
  }
  if (!context.is_object() || !context.contains("version") || context["version"] != kRecordingContextVersion)
    throw fail("expected version " + std::to_string(kRecordingContextVersion));
  for (const char* key : {"task", "task_text", "scenario", "safety_limits"})
    if (!context.contains(key)) throw fail(std::string("missing \"") + key + "\"");
  if (!context["task"].is_string() || !context["task_text"].is_string()) throw fail("task and task_text are not text");
  if (!context.contains("coupling")) context["coupling"] = nullptr;
  if (!context.contains("practice")) context["practice"] = false;  // before practice sessions
  if (!context["practice"].is_boolean()) throw fail("practice is not true or false");
  migrate(context);
  return context;
}

}  // namespace needle::haptics
