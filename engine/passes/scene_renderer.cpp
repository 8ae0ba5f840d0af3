#include "engine/scene_renderer.hpp"

#include "engine/gpu_device.hpp"
#include "engine/render_target.hpp"
#include "engine/passes/scene_pass.hpp"

namespace needle::engine {

SceneRenderer::SceneRenderer(const GpuDevice& device, const RenderTarget& target, const RendererSettings& settings)
    : pass_(std::make_unique<ScenePass>(device.context(), target.images(), settings)) {}

SceneRenderer::~SceneRenderer() = default;

bool SceneRenderer::draw(RenderTarget& target, const FrameParams& params, RgbaImage* capture) {
  return pass_->draw(target.images(), params, capture);
}

void SceneRenderer::wait_idle() const { pass_->wait_idle(); }

int SceneRenderer::msaa_samples() const { return int(pass_->samples()); }

size_t SceneRenderer::triangles_drawn() const { return pass_->triangles_drawn(); }

void SceneRenderer::set_device_timings(bool on) { pass_->set_device_timings(on); }

const FrameCost& SceneRenderer::frame_cost() const { return pass_->frame_cost(); }

}  // namespace needle::engine
