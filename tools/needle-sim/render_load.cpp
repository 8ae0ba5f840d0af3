// The rendering load of `needle-sim bench loop --render-load`: the trainee's frame of the
// penetrable-sphere task as `run` draws it (app::TraineeFrame: the scene with its deformation
// pass under the scripted needle, the status panel, the trainee panel and the guidance),
// offscreen at 1280x720, frame after frame, as fast as the device allows (on lavapipe: both CPU
// cores). The task's session is built for its panel but its own loop never starts: the loop the
// bench times stands in for it.
#include <unistd.h>

#include <chrono>
#include <filesystem>

#include "app/task_session.hpp"
#include "app/trainee_frame.hpp"
#include "asset_path.hpp"
#include "engine/gpu_device.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/offscreen.hpp"
#include "printed_messages.hpp"
#include "render_load_hook.hpp"

namespace needle::cli {
namespace {

namespace fs = std::filesystem;

long draw_trainee_frames_until(const std::atomic<bool>& stop) {
  const fs::path scratch = fs::temp_directory_path() / ("needle_render_load_" + std::to_string(::getpid()));
  fs::create_directories(scratch);
  long frames = 0;
  {
    app::TaskSessionOptions task;
    task.task = asset_dir() / "tasks" / "penetrable_sphere.json";
    task.trainee = "bench";
    task.db = scratch / "sessions.db";
    task.out_dir = scratch;
    task.messages = printed_messages("needle-sim bench loop");
    app::TaskSession session(task);
    engine::DeviceOptions options;
    options.announce_device = false;
    engine::GpuDevice device(options);
    engine::HeadlessTarget target(device, {1280, 720});
    app::TraineeFrame frame(device, target, {1, true, std::nullopt, true});  // with the status panel, as measured
    engine::GpuScene scene(frame.renderer(), session.scene());
    app::FrameContent content = app::scripted_content(scene);
    content.panel = [&session] { session.draw_panel(); };
    const auto start = std::chrono::steady_clock::now();
    for (; !stop.load(std::memory_order_relaxed); ++frames)
      frame.draw(target, scene, content,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    frame.renderer().wait_idle();
  }
  fs::remove_all(scratch);
  return frames;
}

const bool registered = [] {
  set_render_load(draw_trainee_frames_until);
  return true;
}();

}  // namespace
}  // namespace needle::cli
