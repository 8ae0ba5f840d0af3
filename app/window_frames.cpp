#include "app/window_frames.hpp"

namespace needle::app {

GpuWindow::GpuWindow(const std::string& title, engine::Extent size, const Messages& messages)
    : window(title, int(size.width), int(size.height)), device(window), target(device, window) {
  messages.say("Window: " + target.presentation_note());
}

void WindowFrames::draw(engine::Window& window, const std::function<bool(engine::RgbaImage*)>& draw_frame) {
  const bool last = frames_ > 0 && drawn_ + 1 == frames_;
  engine::RgbaImage shot;
  if (!draw_frame(last && screenshot_ ? &shot : nullptr)) {
    window.wait_events();
    return;
  }
  ++drawn_;
  if (!last) return;
  if (screenshot_) {
    engine::write_png(*screenshot_, shot);
    messages_.say(formatted("wrote %s (%ux%u)", screenshot_->c_str(), shot.width, shot.height));
  }
  window.request_close();
}

}  // namespace needle::app
