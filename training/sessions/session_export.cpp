#include "training/sessions/session_export.hpp"

#include "io/file_write.hpp"
#include "training/scoring/metric_fields.hpp"
#include "training/sessions/export_format.hpp"

namespace needle::training {
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

json metrics_json(const Metrics& m) {
  json out = json::object();
  for_each_metric(m, [&](const char* name, const auto& value) {
    if constexpr (std::is_floating_point_v<std::decay_t<decltype(value)>>)
      out[name] = json_number(value);
    else
      out[name] = value;
  });
  return out;
}

json steps_json(const std::vector<StepResult>& steps) {
  json out = json::array();
  for (const StepResult& s : steps)
    out.push_back({{"id", s.id},
                   {"outcome", step_outcome_name(s.record.outcome)},
                   {"start_s", json_number(s.record.start_s)},
                   {"end_s", json_number(s.record.end_s)},
                   {"failure", s.failure},
                   {"metrics", metrics_json(s.metrics)}});
  return out;
}

json punctures_json(const std::vector<PunctureResult>& punctures) {
  json out = json::array();
  for (const PunctureResult& p : punctures)
    out.push_back({{"layer", p.layer}, {"t_s", p.t_s}, {"depth_m", p.depth_m}, {"peak_force_N", p.peak_force_N}});
  return out;
}

json components_json(const std::vector<ScoreComponent>& components) {
  json out = json::array();
  for (const ScoreComponent& c : components)
    out.push_back({{"name", c.name},
                   {"value", c.value},
                   {"weight", c.weight},
                   {"points", c.points()},
                   {"applied", c.status == ComponentStatus::kApplied},
                   {"status", component_status_name(c.status)}});
  return out;
}

}  // namespace

json result_json(const SessionResult& result) {
  return {{"score", result.score.total},
          {"passed", result.score.passed},
          {"reasons_failed", result.score.reasons_failed},
          {"components", components_json(result.score.components)},
          {"metrics", metrics_json(result.overall)},
          {"punctures", punctures_json(result.punctures)},
          {"steps", steps_json(result.steps)}};
}

json session_json(const StoredSession& s) {
  const SessionInfo& i = s.info;
  return {{"session",
           {{"id", i.id},
            {"trainee", i.trainee},
            {"task", i.task},
            {"device", i.device},
            {"started_at", i.started_at},
            {"ended_at", i.ended_at},
            {"complete", i.complete},
            {"duration_s", i.duration_s},
            {"recording_path", i.recording_path},
            {"station", i.station},
            {"uid", i.uid}}},
          // An incomplete session was never scored: no score and no verdict, not 0 and failed.
          {"score", i.complete ? json(i.score) : json(nullptr)},
          {"passed", i.complete ? json(i.passed) : json(nullptr)},
          {"components", components_json(s.components)},
          {"metrics", metrics_json(s.overall)},
          {"steps", steps_json(s.steps)}};
}

std::string session_csv(const StoredSession& s) {
  std::string out = "session_id,step_index,step_id,outcome,start_s,end_s,metric,value\n";
  const std::string id = std::to_string(s.info.id);
  const auto rows = [&](const std::string& prefix, const Metrics& m) {
    for_each_metric(m, [&](const char* name, const auto& value) {
      out += prefix + name + "," + csv_number(static_cast<double>(value)) + "\n";
    });
  };
  for (size_t k = 0; k < s.steps.size(); ++k) {
    const StepResult& step = s.steps[k];
    rows(id + "," + std::to_string(k) + "," + csv_field(step.id) + "," + step_outcome_name(step.record.outcome) + "," +
             csv_number(step.record.start_s) + "," + csv_number(step.record.end_s) + ",",
         step.metrics);
  }
  rows(id + ",-1,session," + (s.info.complete ? "complete" : "incomplete") + ",,,", s.overall);
  return out;
}

std::string punctures_csv(int64_t session_id, const std::vector<PunctureResult>& punctures) {
  std::string out = "session_id,index,layer,t_s,depth_m,peak_force_N\n";
  for (size_t k = 0; k < punctures.size(); ++k) {
    const PunctureResult& p = punctures[k];
    out += std::to_string(session_id) + "," + std::to_string(k) + "," + csv_field(p.layer) + "," + csv_number(p.t_s) +
           "," + csv_number(p.depth_m) + "," + csv_number(p.peak_force_N) + "\n";
  }
  return out;
}

fs::path export_session(const StoredSession& session, const fs::path& dir,
                        const std::vector<PunctureResult>* punctures) {
  io::make_folder(dir);
  const std::string stem = "session_" + std::to_string(session.info.id);
  const fs::path json_file = dir / (stem + ".json");
  json j = session_json(session);
  if (punctures) j["punctures"] = punctures_json(*punctures);
  io::write_file(json_file, j.dump(2) + "\n");
  io::write_file(dir / (stem + ".csv"), session_csv(session));
  if (punctures) io::write_file(dir / (stem + "_punctures.csv"), punctures_csv(session.info.id, *punctures));
  return json_file;
}

}  // namespace needle::training
