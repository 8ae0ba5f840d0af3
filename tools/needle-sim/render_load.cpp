// The rendering load of `needle-sim bench loop --render-load`: the 400x400 thesis sphere drawn
// offscreen at 1280x720, frame after frame, as fast as the device allows (on lavapipe: both
// CPU cores), as the window would draw it.
#include "asset-gen/assets.hpp"
#include "engine/gltf_loader.hpp"
#include "engine/gpu_device.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/offscreen.hpp"
#include "engine/render_target.hpp"
#include "render_load_hook.hpp"

namespace needle::cli {
namespace {

void draw_sphere_until(const std::atomic<bool>& stop) {
  engine::DeviceOptions options;
  options.announce_device = false;
  engine::GpuDevice device(options);
  const engine::Extent extent{1280, 720};
  engine::HeadlessTarget target(device, extent);
  engine::SceneRenderer renderer(device, target, {1});
  engine::Model sphere = engine::convert_gltf(asset_gen::make_sphere(400, 400), "sphere_400");
  engine::GpuScene scene(renderer, sphere, engine::framing_view(sphere, extent));
  while (!stop.load(std::memory_order_relaxed)) renderer.draw(target, scene.frame_params());
  renderer.wait_idle();
}

const bool registered = [] {
  set_render_load(draw_sphere_until);
  return true;
}();

}  // namespace
}  // namespace needle::cli
