// needle-sim render: one frame of a scene file or a glTF model, offscreen, to a PNG.
#include <cstdio>

#include "command.hpp"
#include "engine/gltf_loader.hpp"
#include "engine/gpu_device.hpp"
#include "engine/offscreen.hpp"

namespace needle::cli {
namespace {

struct RenderFlags {
  std::optional<std::string> scene, gltf, out;
  engine::Extent size{1280, 720};
  std::optional<int> msaa;
};

int run(const RenderFlags& f) {
  if (bool(f.scene) == bool(f.gltf)) throw UsageError("give exactly one of --scene FILE or --gltf FILE");
  // Parse the input before starting Vulkan so a bad file fails fast and alone.
  std::optional<engine::Scene> scene;
  std::optional<engine::Model> model;
  if (f.scene) scene = engine::load_scene(*f.scene);
  if (f.gltf) model = engine::load_gltf(*f.gltf);

  engine::GpuDevice device;
  const engine::RendererSettings settings{f.msaa.value_or(4)};
  const engine::RgbaImage image =
      scene ? engine::render_scene_offscreen(device, *scene, f.size, settings)
            : engine::render_model_offscreen(device, *model, f.size, engine::framing_view(*model, f.size), settings);
  engine::write_png(*f.out, image);
  std::printf("wrote %s (%ux%u)\n", f.out->c_str(), image.width, image.height);
  return 0;
}

// The options of render, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<RenderFlags>();
  CLI::Option* scene =
      add_text(app, "--scene", f->scene, "FILE", "scene file (JSON): assets with roles, camera, lights");
  add_text(app, "--gltf", f->gltf, "FILE", "a .gltf or .glb model, framed by an automatic camera")->excludes(scene);
  add_output_file(app, "--out", f->out, "OUT.png", "where to write the image")->required();
  add_size(app, "--size", f->size, "image size in pixels");
  add_msaa(app, "--msaa", f->msaa, "MSAA samples, capped at the device's; by default 4");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{{"render", "one frame of a scene file or a glTF model, offscreen, to a PNG", declare}};

}  // namespace
}  // namespace needle::cli
