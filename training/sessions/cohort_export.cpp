#include "training/sessions/cohort_export.hpp"

#include "io/file_write.hpp"
#include "training/sessions/export_format.hpp"

namespace needle::training {
using nlohmann::json;

json cohort_json(const CohortView& view) {
  const CohortFilter& f = view.filter;
  json out = {
      {"filter",
       {{"task", f.task}, {"trainee", f.trainee}, {"station", f.station}, {"since", f.since}, {"until", f.until}}},
      {"sessions", view.sessions},
      {"curves", json::array()},
      {"most_failed_steps", json::array()},
      {"percentiles", json::array()}};
  for (const LearningCurve& c : view.curves) {
    json attempts = json::array();
    for (size_t k = 0; k < c.attempts.size(); ++k) {
      const Attempt& a = c.attempts[k];
      attempts.push_back({{"attempt", k + 1},
                          {"session", a.session},
                          {"started_at", a.started_at},
                          {"station", a.station},
                          {"score", a.score},
                          {"passed", a.passed},
                          {"duration_s", a.duration_s},
                          {"time_to_target_s", json_number(a.time_to_target_s)}});
    }
    out["curves"].push_back({{"trainee", c.trainee},
                             {"task", c.task},
                             {"first_pass", c.first_pass},
                             {"attempts_to_pass", c.attempts_to_pass},
                             {"attempts", attempts}});
  }
  for (const StepFailures& s : view.most_failed)
    out["most_failed_steps"].push_back(
        {{"task", s.task}, {"step", s.step}, {"failed", s.failed}, {"attempts", s.attempts}});
  for (const Percentiles& p : view.percentiles)
    out["percentiles"].push_back({{"task", p.task},
                                  {"metric", p.metric},
                                  {"n", p.n},
                                  {"p10", json_number(p.p10)},
                                  {"p25", json_number(p.p25)},
                                  {"p50", json_number(p.p50)},
                                  {"p75", json_number(p.p75)},
                                  {"p90", json_number(p.p90)}});
  return out;
}

std::string learning_curves_csv(const CohortView& view) {
  std::string out = "trainee,task,attempt,session_id,started_at,station,score,passed,duration_s,time_to_target_s\n";
  for (const LearningCurve& c : view.curves)
    for (size_t k = 0; k < c.attempts.size(); ++k) {
      const Attempt& a = c.attempts[k];
      out += csv_field(c.trainee) + "," + csv_field(c.task) + "," + std::to_string(k + 1) + "," +
             std::to_string(a.session) + "," + a.started_at + "," + csv_field(a.station) + "," + csv_number(a.score) +
             "," + (a.passed ? "1" : "0") + "," + csv_number(a.duration_s) + "," + csv_number(a.time_to_target_s) +
             "\n";
    }
  return out;
}

std::string failed_steps_csv(const CohortView& view) {
  std::string out = "task,step,failed,attempts\n";
  for (const StepFailures& s : view.most_failed)
    out += csv_field(s.task) + "," + csv_field(s.step) + "," + std::to_string(s.failed) + "," +
           std::to_string(s.attempts) + "\n";
  return out;
}

std::string percentiles_csv(const CohortView& view) {
  std::string out = "task,metric,n,p10,p25,p50,p75,p90\n";
  for (const Percentiles& p : view.percentiles)
    out += csv_field(p.task) + "," + p.metric + "," + std::to_string(p.n) + "," + csv_number(p.p10) + "," +
           csv_number(p.p25) + "," + csv_number(p.p50) + "," + csv_number(p.p75) + "," + csv_number(p.p90) + "\n";
  return out;
}

void export_cohort(const CohortView& view, const std::filesystem::path& dir) {
  io::make_folder(dir);
  io::write_file(dir / "cohort.json", cohort_json(view).dump(2) + "\n");
  io::write_file(dir / "cohort_curves.csv", learning_curves_csv(view));
  io::write_file(dir / "cohort_failed_steps.csv", failed_steps_csv(view));
  io::write_file(dir / "cohort_percentiles.csv", percentiles_csv(view));
}

}  // namespace needle::training
