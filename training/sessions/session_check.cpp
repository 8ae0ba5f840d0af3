#include "training/sessions/session_check.hpp"

#include <cstdio>
#include <cstring>

#include "haptics/recording/crc32.hpp"
#include "training/scoring/metric_fields.hpp"
#include "training/sessions/session_store.hpp"

namespace needle::training {
namespace {

// Equal bit for bit, NaN (does not apply) equal to NaN.
bool same(double a, double b) { return std::isnan(a) ? std::isnan(b) : std::memcmp(&a, &b, sizeof a) == 0; }

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

void compare_number(std::vector<std::string>& out, const std::string& what, double stored, double replay) {
  if (!same(stored, replay)) out.push_back(what + ": stored " + number(stored) + ", replay " + number(replay));
}

void compare_metrics(std::vector<std::string>& out, const std::string& of, const Metrics& stored,
                     const Metrics& replay) {
  for_each_metric(stored, [&](const char* name, const auto& s) {
    for_each_metric(replay, [&](const char* other, const auto& r) {
      if (std::strcmp(name, other) == 0)
        compare_number(out, std::string("metric ") + name + " of " + of, double(s), double(r));
    });
  });
}

}  // namespace

const char* check_outcome_name(CheckOutcome outcome) {
  switch (outcome) {
    case CheckOutcome::kVerified:
      return "verified";
    case CheckOutcome::kMismatch:
      return "mismatch";
    case CheckOutcome::kUnverifiable:
      return "unverifiable";
  }
  return "unverifiable";
}

bool check_outcome_from_name(const std::string& name, CheckOutcome& outcome) {
  for (const CheckOutcome o : {CheckOutcome::kVerified, CheckOutcome::kMismatch, CheckOutcome::kUnverifiable})
    if (name == check_outcome_name(o)) {
      outcome = o;
      return true;
    }
  return false;
}

std::vector<std::string> result_differences(const StoredSession& stored, const SessionResult& replay) {
  std::vector<std::string> out;
  compare_number(out, "score", stored.info.score, replay.score.total);
  if (stored.info.passed != replay.score.passed)
    out.push_back(std::string("passed: stored ") + (stored.info.passed ? "yes" : "no") + ", replay " +
                  (replay.score.passed ? "yes" : "no"));
  compare_number(out, "duration_s", stored.info.duration_s, replay.overall.duration_s);
  if (stored.steps.size() != replay.steps.size())
    out.push_back("steps: stored " + std::to_string(stored.steps.size()) + ", replay " +
                  std::to_string(replay.steps.size()));
  for (size_t k = 0; k < std::min(stored.steps.size(), replay.steps.size()); ++k) {
    const StepResult &s = stored.steps[k], &r = replay.steps[k];
    const std::string step = "step " + std::to_string(k + 1) + " (" + r.id + ")";
    if (s.id != r.id) out.push_back(step + " id: stored \"" + s.id + "\", replay \"" + r.id + "\"");
    if (s.record.outcome != r.record.outcome)
      out.push_back(step + " outcome: stored " + step_outcome_name(s.record.outcome) + ", replay " +
                    step_outcome_name(r.record.outcome));
    compare_number(out, step + " start_s", s.record.start_s, r.record.start_s);
    compare_number(out, step + " end_s", s.record.end_s, r.record.end_s);
    compare_metrics(out, step, s.metrics, r.metrics);
  }
  compare_metrics(out, "the session", stored.overall, replay.overall);
  const std::vector<ScoreComponent>& rc = replay.score.components;
  if (stored.components.size() != rc.size())
    out.push_back("score components: stored " + std::to_string(stored.components.size()) + ", replay " +
                  std::to_string(rc.size()));
  for (size_t k = 0; k < std::min(stored.components.size(), rc.size()); ++k) {
    const ScoreComponent& s = stored.components[k];
    if (s.name != rc[k].name)
      out.push_back("score component " + std::to_string(k + 1) + ": stored \"" + s.name + "\", replay \"" + rc[k].name +
                    "\"");
    compare_number(out, "score component " + rc[k].name + " value", s.value, rc[k].value);
    compare_number(out, "score component " + rc[k].name + " weight", s.weight, rc[k].weight);
  }
  return out;
}

std::string result_digest(const StoredSession& stored) {
  const SessionInfo& i = stored.info;
  std::string text = number(i.score) + (i.passed ? " passed " : " failed ") + number(i.duration_s) + " " +
                     (i.complete ? "complete" : "incomplete") + "\n";
  const auto metrics = [&](const Metrics& m) {
    for_each_metric(
        m, [&](const char* name, const auto& value) { text += std::string(name) + "=" + number(double(value)) + " "; });
    text += "\n";
  };
  for (const StepResult& s : stored.steps) {
    text += s.id + " " + step_outcome_name(s.record.outcome) + " " + number(s.record.start_s) + " " +
            number(s.record.end_s) + "\n";
    metrics(s.metrics);
  }
  metrics(stored.overall);
  for (const ScoreComponent& c : stored.components)
    text += c.name + " " + number(c.value) + " " + number(c.weight) + "\n";
  char hex[9];
  std::snprintf(hex, sizeof hex, "%08x", unsigned(haptics::crc32(text.data(), text.size())));
  return hex;
}

Verification verification(const SessionInfo& info) {
  if (!info.check || *info.check == CheckOutcome::kUnverifiable) return Verification::kUnverified;
  if (*info.check == CheckOutcome::kMismatch || !same(info.checked_score, info.score)) return Verification::kMismatch;
  return Verification::kVerified;
}

VerificationStatus verification_status(const StoredSession& stored) {
  if (!stored.check)
    return {Verification::kUnverified, "unverified: never checked against its recording (needle-sim verify)"};
  const SessionCheck& c = *stored.check;
  const std::string when = " (checked " + c.checked_at + (c.checked_by.empty() ? "" : " by " + c.checked_by) + ")";
  const std::string first = c.detail.substr(0, c.detail.find('\n'));
  switch (c.outcome) {
    case CheckOutcome::kUnverifiable:
      return {Verification::kUnverified, "unverified: its recording could not be replayed" + when + ": " + first};
    case CheckOutcome::kMismatch:
      return {Verification::kMismatch, "MISMATCH with its recording" + when + ": " + first};
    case CheckOutcome::kVerified:
      if (c.digest != result_digest(stored))
        return {Verification::kMismatch, "MISMATCH: its stored results changed since they were verified" + when};
      return {Verification::kVerified, "verified against its recording" + when};
  }
  return {};
}

const char* verification_word(Verification v) {
  switch (v) {
    case Verification::kVerified:
      return "verified";
    case Verification::kMismatch:
      return "mismatch";
    case Verification::kUnverified:
      return "unverified";
  }
  return "unverified";
}

}  // namespace needle::training
