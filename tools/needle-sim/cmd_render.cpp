// needle-sim render: one frame of a scene file or a glTF model, offscreen, to a PNG.
#include <cstdio>

#include "arg_list.hpp"
#include "command.hpp"
#include "engine/gltf_loader.hpp"
#include "engine/gpu_device.hpp"
#include "engine/offscreen.hpp"

namespace needle::cli {
namespace {

int run_render(ArgList& args) {
  auto scene_file = args.value("--scene");
  auto gltf_file = args.value("--gltf");
  std::string out = args.required("--out");
  engine::Extent size = parse_size(args.value("--size").value_or("1280x720"), "--size");
  int msaa = parse_msaa(args.value("--msaa").value_or("4"), "--msaa");
  args.finish();
  if (bool(scene_file) == bool(gltf_file)) throw UsageError("give exactly one of --scene FILE or --gltf FILE");

  // Parse the input before starting Vulkan so a bad file fails fast and alone.
  std::optional<engine::Scene> scene;
  std::optional<engine::Model> model;
  if (scene_file) scene = engine::load_scene(*scene_file);
  if (gltf_file) model = engine::load_gltf(*gltf_file);

  engine::GpuDevice device;
  engine::RendererSettings settings{msaa};
  engine::RgbaImage image =
      scene ? engine::render_scene_offscreen(device, *scene, size, settings)
            : engine::render_model_offscreen(device, *model, size, engine::framing_view(*model, size), settings);
  engine::write_png(out, image);
  std::printf("wrote %s (%ux%u)\n", out.c_str(), image.width, image.height);
  return 0;
}

const CommandRegistrar reg{{"render",
                            "needle-sim render (--scene FILE | --gltf FILE) --out OUT.png [--size WxH] [--msaa N]\n"
                            "  --scene FILE   scene file (JSON): assets with roles, camera, lights\n"
                            "  --gltf FILE    a .gltf or .glb model, framed by an automatic camera\n"
                            "  --out OUT.png  where to write the image\n"
                            "  --size WxH     image size in pixels (default 1280x720)\n"
                            "  --msaa N       MSAA samples, 1/2/4/8, capped at the device's (default 4)",
                            run_render}};

}  // namespace
}  // namespace needle::cli
