// What the session store tests write and compare: a small task, a two-step result with NaN
// metrics where they do not apply and a score breakdown, and a field-by-field metric comparison.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <type_traits>

#include "training/scoring/metric_fields.hpp"
#include "training/sessions/session_store.hpp"

namespace needle::test {

inline training::Task small_task() {
  training::Task t;
  t.name = "pivot_drill";
  t.title = "Pivot drill";
  t.source = "/tasks/pivot_drill.json";
  return t;
}

inline training::SessionResult a_result() {
  using namespace training;
  SessionResult r;
  StepResult a{"insert", {StepOutcome::kCompleted, 0.5, 7.25}, {}};
  a.metrics.duration_s = 6.75, a.metrics.lateral_load_Ns = 1.125, a.metrics.path_length_m = 0.0625;
  a.metrics.withdrawals = 2, a.metrics.first_fault = 3;
  StepResult b{"pivot", {StepOutcome::kTipMoved, 7.25, 9.0}, {}};
  b.metrics.tip_error_m = 0.003, b.metrics.normalized_jerk = 123.5;
  r.steps = {a, b};
  r.overall = combine_metrics(r.steps);
  r.score.total = 61.5;
  r.score.passed = false;
  r.score.components = {{"completion", 0.5, 30.0}, {"tip_error", 0.7, 15.0}};
  r.finished = true;
  return r;
}

inline void expect_same_metrics(const training::Metrics& got, const training::Metrics& want) {
  training::for_each_metric(got, [&](const char* name, const auto& g) {
    training::for_each_metric(want, [&](const char* other, const auto& w) {
      if (std::string(name) != other) return;
      if constexpr (std::is_floating_point_v<std::decay_t<decltype(w)>>) {
        if (std::isnan(w))
          EXPECT_TRUE(std::isnan(g)) << name;
        else
          EXPECT_DOUBLE_EQ(g, w) << name;
      } else {
        EXPECT_EQ(g, w) << name;
      }
    });
  });
}

}  // namespace needle::test
