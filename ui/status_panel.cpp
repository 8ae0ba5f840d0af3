#include "ui/status_panel.hpp"

#include <imgui.h>

#include <numeric>

namespace needle::ui {

float FrameClock::tick() {
  auto now = std::chrono::steady_clock::now();
  float dt = 0.0f;
  if (started_) {
    dt = std::chrono::duration<float>(now - last_).count();
    ms_[count_++ % kWindow] = dt * 1000.0;
  }
  started_ = true;
  last_ = now;
  return dt;
}

double FrameClock::mean_frame_ms() const {
  size_t n = std::min(count_, kWindow);
  return n ? std::accumulate(ms_.begin(), ms_.begin() + long(n), 0.0) / double(n) : 0.0;
}

void draw_status_panel(const StatusInfo& info) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.6f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
  if (ImGui::Begin("status", nullptr, flags)) {
    ImGui::TextUnformatted("needle-sim");
    ImGui::Separator();
    ImGui::Text("scene   %s", info.scene.c_str());
    ImGui::Text("device  %s", info.device.c_str());
    ImGui::Text("msaa    %dx", info.msaa);
    if (info.render_scale < 1.0f) ImGui::Text("scale   %.2f (3D view)", double(info.render_scale));
    if (info.frame_ms > 0.0) {
      ImGui::Text("frame   %.1f ms (%.0f fps)", info.frame_ms, 1000.0 / info.frame_ms);
    } else {
      ImGui::TextUnformatted("frame   -");
    }
  }
  ImGui::End();
}

}  // namespace needle::ui
