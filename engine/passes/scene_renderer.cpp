#include "engine/scene_renderer.hpp"

#include <cmath>

#include "engine/gpu_device.hpp"
#include "engine/passes/scene_pass.hpp"
#include "engine/render_target.hpp"

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

void SceneRenderer::set_render_scale(const RenderTarget& target, float scale) {
  pass_->set_render_scale(target.images(), scale);
}

float SceneRenderer::render_scale() const { return pass_->render_scale(); }

void SceneRenderer::set_cull_cut_away(bool on) { pass_->set_cull_cut_away(on); }
void SceneRenderer::set_cull_inside(bool on) { pass_->set_cull_inside(on); }
void SceneRenderer::set_specialized_pipelines(bool on) { pass_->set_specialized_pipelines(on); }
void SceneRenderer::set_translucency(Translucency translucency) { pass_->set_translucency(translucency); }

std::string SceneRenderer::render_scale_unsupported(const RenderTarget& target) const {
  return ScaledScene::unsupported(pass_->context(), target.images(), pass_->samples());
}

void SceneRenderer::set_device_timings(bool on) { pass_->set_device_timings(on); }

const FrameCost& SceneRenderer::frame_cost() const { return pass_->frame_cost(); }

Section section_through_needle(const Camera& camera, const NeedleLoad* needle, Section::Mode mode) {
  Section section;
  section.mode = mode;
  if (needle == nullptr || needle->contact == NeedleContact::Free) {
    section.point = camera.target;
    const glm::vec3 view = camera.position - camera.target;
    section.normal = glm::length(view) > 0.0f ? glm::normalize(view) : glm::vec3(0.0f, -1.0f, 0.0f);
    return section;
  }
  const glm::vec3 tip(needle->tip), axis = glm::normalize(glm::vec3(needle->axis));
  // The camera's direction without its part along the axis: the plane holds the axis and faces the camera.
  glm::vec3 n = camera.position - tip;
  n -= glm::dot(n, axis) * axis;
  if (glm::length(n) < 1e-6f) {  // looking down the needle: any plane through it
    n = glm::cross(axis, std::abs(axis.z) < 0.9f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, 0.0f));
  }
  section.point = tip;
  section.normal = glm::normalize(n);
  return section;
}

}  // namespace needle::engine
