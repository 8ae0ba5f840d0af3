#include "task_run.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "engine/gpu_scene.hpp"
#include "engine/headless_target.hpp"
#include "engine/ui_pass.hpp"
#include "engine/vulkan_context.hpp"
#include "ui/sessions/session_export.hpp"
#include "ui/tasks/scripted_operator.hpp"

namespace needle::cli {
namespace fs = std::filesystem;

namespace {

// The store's folder is made before SQLite opens the file in it.
const fs::path& with_folder(const fs::path& file) {
  if (file.has_parent_path()) fs::create_directories(file.parent_path());
  return file;
}

// A progress bar on a terminal; on a pipe (CI, logs), a line every quarter.
class ProgressBar {
 public:
  explicit ProgressBar(double total) : total_(total), tty_(isatty(STDERR_FILENO)) {}
  void show(double done) {
    const int percent = int(100.0 * std::min(done / total_, 1.0));
    if (percent == shown_ || (!tty_ && percent % 25 != 0)) return;
    shown_ = percent;
    const int filled = percent / 5;
    std::fprintf(stderr, "%s  [%.*s%*s] %3d%%  %.1f of %.1f s simulated%s", tty_ ? "\r" : "", filled,
                 "####################", 20 - filled, "", percent, done, total_, tty_ ? "" : "\n");
    if (tty_ && percent == 100) std::fputc('\n', stderr);
  }

 private:
  double total_;
  bool tty_;
  int shown_ = -1;
};

}  // namespace

ScriptedTaskRun::ScriptedTaskRun(const TaskRunOptions& options)
    : options_(options),
      task_(ui::load_task(options.task)),
      store_(with_folder(options.db)),
      scorer_(task_) {
  const fs::path script = ui::operator_script_path(task_, options.operator_spec);
  fs::create_directories(options.out_dir);
  const haptics::Scenario scenario = ui::scenario_with_operator(task_, script, options.out_dir / "scenario.json");
  period_s_ = scenario.period_s;
  session_ = store_.begin_session(options.trainee, task_, "sim (" + script.stem().string() + ")", "");
  std::printf("task %s, operator %s, trainee %s: session %lld in %s\n", task_.name.c_str(), script.filename().c_str(),
              options.trainee.c_str(), static_cast<long long>(session_), options.db.c_str());
  std::fflush(stdout);  // before the progress bar on stderr
  ProgressBar progress(scenario.duration_s);
  const haptics::SimResult sim = haptics::run_closed_loop(scenario, false, [&](const haptics::TickRecord& r) {
    states_.push_back(ui::snapshot_of(r));
    progress.show(r.t);
  });
  progress.show(scenario.duration_s);
  sim_faults_ = sim.summary.faults;
}

void ScriptedTaskRun::advance_to(double t, const std::function<void(size_t)>& on_step_end) {
  haptics::TickSample sample;
  for (; next_ < states_.size() && states_[next_].time_s <= t; ++next_) {
    const size_t step = scorer_.progress().current_step();
    sample.state = states_[next_];
    scorer_.feed(sample);
    needle_ = tracker_.update(sample.state);
    if (on_step_end) {
      for (size_t k = step; k < scorer_.progress().current_step(); ++k) on_step_end(k);
    }
  }
}

const ui::SessionResult& ScriptedTaskRun::finish() {
  if (result_) return *result_;
  advance_to(duration_s());
  result_ = scorer_.result();
  store_.finish_session(session_, *result_);
  const fs::path score_file = options_.out_dir / "score.json";
  std::ofstream(score_file) << ui::result_json(*result_).dump(2) << "\n";
  for (const std::string& fault : sim_faults_) std::printf("simulation fault: %s\n", fault.c_str());
  std::printf("score %.0f / 100: %s\n", result_->score.total, result_->score.passed ? "passed" : "not passed");
  for (const std::string& why : result_->score.reasons_failed) std::printf("  %s\n", why.c_str());
  std::printf("wrote %s\n", score_file.c_str());
  return *result_;
}

ui::TraineeView ScriptedTaskRun::view(std::optional<size_t> step) const {
  ui::TraineeView view{&task_, &scorer_.progress()};
  view.step = step;
  view.step_metrics = scorer_.step_metrics(std::min(step.value_or(scorer_.progress().current_step()), task_.steps.size() - 1));
  if (next_ > 0) {
    const double* f = states_[next_ - 1].environment_force_n;
    view.force_N = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
  }
  view.loop_rate_hz = 1.0 / period_s_;
  if (result_) view.result = &*result_;
  return view;
}

int run_task_headless(const TaskRunOptions& options, Size2 size, int msaa) {
  ScriptedTaskRun run(options);
  engine::VulkanContext context(engine::ContextOptions{});
  engine::HeadlessTarget target(context, {size.width, size.height});
  engine::SceneRenderer renderer(context, target, {static_cast<VkSampleCountFlagBits>(msaa)});
  engine::GpuScene scene(renderer, engine::load_scene(run.task().scene));
  engine::UiPass ui(context, renderer, nullptr);
  auto shoot = [&](const std::string& name, std::optional<size_t> step = std::nullopt) {
    engine::RgbaImage image;
    for (int frame = 0; frame < 2; ++frame) {  // ImGui fits its auto-sized windows on the first frame
      ui.begin_frame(target.extent(), 1.0f / 60.0f);
      ui::draw_trainee_panel(run.view(step));
      engine::FrameParams params = scene.frame_params(&run.needle());
      params.overlay = ui.end_frame();
      renderer.draw(target, params, frame == 1 ? &image : nullptr);
    }
    engine::write_png(options.out_dir / (name + ".png"), image);
  };
  run.advance_to(run.duration_s(),
                 [&](size_t k) { shoot("step_" + std::to_string(k + 1) + "_" + run.task().steps[k].id, k); });
  shoot("final");
  run.finish();
  shoot("score_panel");
  std::printf("wrote the pictures of the run in %s\n", options.out_dir.c_str());
  return 0;
}

}  // namespace needle::cli
