#include <algorithm>
#include <cmath>

#include "engine/gpu_device.hpp"
#include "engine/ultrasound.hpp"
#include "engine/ultrasound/echo_model.hpp"
#include "engine/ultrasound/ultrasound_display.hpp"
#include "engine/ultrasound/ultrasound_pass.hpp"
#include "engine/vulkan/command_buffer.hpp"
#include "engine/vulkan/vulkan_context.hpp"

namespace needle::engine {

UltrasoundView::UltrasoundView(const GpuDevice& device, EchoScene scene, const UltrasoundSettings& settings)
    : pass_(std::make_unique<UltrasoundPass>(device.context(), std::move(scene), settings)) {}

UltrasoundView::~UltrasoundView() = default;

const EchoScene& UltrasoundView::scene() const { return pass_->scene(); }
const UltrasoundSettings& UltrasoundView::settings() const { return pass_->settings(); }

CommandRecorder UltrasoundView::record(const UltrasoundProbe& probe, const NeedleLoad* needle) {
  auto recorder = pass_->update(probe, needle, true);
  if (!recorder) return {};
  return [recorder](const CommandBuffer& cmd) { recorder(cmd.handle); };
}

void UltrasoundView::render(const UltrasoundProbe& probe, const NeedleLoad* needle) {
  pass_->context().submit_and_wait(pass_->update(probe, needle));
}

CommandRecorder UltrasoundView::draw(const SceneRenderer& renderer, ScreenRect rect, Extent frame) {
  if (!display_ || &display_->scene_pass() != &renderer.pass())
    display_ = std::make_unique<UltrasoundDisplay>(renderer.pass(), *pass_);
  if (!pass_->has_image()) return {};
  return [display = display_.get(), rect, frame](const CommandBuffer& cmd) {
    display->record(cmd.handle, rect, {frame.width, frame.height});
  };
}

RgbaImage UltrasoundView::image() const { return pass_->read_image(); }

std::vector<ScanLine> UltrasoundView::scan_lines() const { return pass_->read_lines(); }

void UltrasoundView::set_sweep_frames(uint32_t frames) { pass_->set_sweep_frames(frames); }

void UltrasoundView::set_device_timings(bool on) { pass_->set_device_timings(on); }

std::vector<std::pair<std::string, double>> UltrasoundView::pass_ms() const {
  std::vector<std::pair<std::string, double>> out;
  if (const auto ms = pass_->read_pass_ms())
    for (size_t p = 0; p < ms->size(); ++p) out.emplace_back(UltrasoundPass::kPassNames[p], (*ms)[p]);
  return out;
}

UltrasoundProbe probe_following(const UltrasoundProbe& probe, const NeedleLoad& needle) {
  const glm::dvec3 d = probe.direction;
  const glm::dvec3 along = needle.axis - glm::dot(needle.axis, d) * d;
  if (glm::length(along) < 1e-6) return probe;
  UltrasoundProbe out = probe;
  out.lateral = glm::normalize(along);
  const glm::dvec3 to_tip = needle.tip - probe.position;
  out.position = probe.position + to_tip - glm::dot(to_tip, d) * d;
  return out;
}

UltrasoundProbe probe_on_skin(const EchoScene& scene, const UltrasoundProbe& probe, const glm::dvec3& above) {
  const auto inside = [&](double s) { return echo::layer_at(scene, above + s * probe.direction) >= 0; };
  constexpr double kStep = 1e-4, kReach = 1.0;
  for (double s = 0.0; s <= kReach; s += kStep) {
    if (!inside(s)) continue;
    double lo = std::max(0.0, s - kStep), hi = s;
    while (hi - lo > 1e-6) (inside(0.5 * (lo + hi)) ? hi : lo) = 0.5 * (lo + hi);
    UltrasoundProbe out = probe;
    out.position = above + hi * probe.direction;
    return out;
  }
  return probe;
}

RgbaImage to_picture(const RgbaImage& image, const UltrasoundProbe& probe) {
  const uint32_t height = image.height;
  const uint32_t width = std::max(1u, uint32_t(std::lround(double(height) * probe.width_m / probe.depth_m)));
  RgbaImage out{width, height, std::vector<uint8_t>(size_t(width) * height * 4)};
  for (uint32_t u = 0; u < width; ++u) {
    const double s = std::clamp((u + 0.5) / width * image.width - 0.5, 0.0, double(image.width - 1));
    const uint32_t i0 = uint32_t(s), i1 = std::min(i0 + 1, image.width - 1);
    const double f = s - i0;
    for (uint32_t y = 0; y < height; ++y)
      for (int c = 0; c < 4; ++c)
        out.pixels[(size_t(y) * width + u) * 4 + c] =
            uint8_t(std::lround((1.0 - f) * image.at(i0, y)[c] + f * image.at(i1, y)[c]));
  }
  return out;
}

}  // namespace needle::engine
