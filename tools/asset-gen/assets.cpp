#include "asset-gen/assets.hpp"

#include <stdexcept>

#include "asset-gen/gltf_builder.hpp"

namespace needle::asset_gen {
namespace {

// Skin tone with a faint deterministic mottling, so the texture path is visibly exercised.
std::vector<unsigned char> skin_texels(int size) {
  std::vector<unsigned char> rgba;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      uint32_t h = uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u;  // integer hash: same on every run
      h = (h ^ (h >> 13)) * 0x5bd1e995u;
      const int noise = static_cast<int>((h >> 24) % 17) - 8;
      const int pore = (x % 8 == 3 && y % 8 == 5) ? -18 : 0;
      rgba.insert(rgba.end(),
                  {static_cast<unsigned char>(222 + noise + pore), static_cast<unsigned char>(170 + noise + pore),
                   static_cast<unsigned char>(148 + noise + pore), 255});
    }
  return rgba;
}

}  // namespace

tinygltf::Model make_sphere(int parallels, int meridians, const std::vector<int>& lod_steps) {
  const std::string name =
      "sphere_" + std::to_string(parallels) + (parallels == meridians ? "" : "x" + std::to_string(meridians));
  GltfBuilder b(name + ".bin");
  const int tissue = b.add_material("tissue", {0.85f, 0.52f, 0.48f, 1.0f}, 0.0f, 0.55f);
  MeshData mesh = sphere_mesh(kThesisSphereRadius, parallels, meridians);
  for (int step : lod_steps) mesh.coarser_indices.push_back(sphere_indices(parallels, meridians, step));
  b.add_root_node("thesis_sphere", b.add_mesh(name, mesh, tissue), {kThesisSphereCenterX, 0.0, 0.0});
  return b.take();
}

tinygltf::Model make_needle() {
  constexpr double tip_length = 0.004, shaft_end = -0.08, hub_end = -0.095;  // m
  constexpr double shaft_radius = 0.0008, hub_radius = 0.003;
  GltfBuilder b("needle.bin");
  const int steel = b.add_material("steel", {0.78f, 0.78f, 0.80f, 1.0f}, 1.0f, 0.25f);
  const int hub = b.add_material("hub", {0.15f, 0.55f, 0.85f, 1.0f}, 0.0f, 0.45f);
  const int tip_mesh = b.add_mesh("tip", revolution_mesh({{0.0, 0.0}, {-tip_length, shaft_radius}}, 24), steel);
  const int shaft_mesh =
      b.add_mesh("shaft", revolution_mesh({{-tip_length, shaft_radius}, {shaft_end, shaft_radius}}, 24), steel);
  const int hub_mesh = b.add_mesh(
      "hub",
      revolution_mesh({{shaft_end, shaft_radius}, {shaft_end, hub_radius}, {hub_end, hub_radius}, {hub_end, 0.0}}, 24),
      hub);
  b.add_root_node("needle_tip", tip_mesh);
  b.add_root_node("needle_shaft", shaft_mesh);
  b.add_root_node("needle_hub", hub_mesh);
  return b.take();
}

tinygltf::Model make_tissue_block() {
  constexpr float half = 0.05f;  // m: a 10 cm square block
  // The layers dimple under the needle (docs/DEFORMATION.md): quads of at most 2 mm, so that a
  // dimple of a few millimetres has vertices. The bone plate too, although rigid: faces that touch
  // are triangulated alike, so the deformation moves them alike and neither shows through the other.
  constexpr float cell = 0.002f;
  GltfBuilder b("tissue_block.bin");
  const int skin_texture = b.add_texture("tissue_block_skin.png", 64, 64, skin_texels(64));
  struct Layer {
    const char* name;
    float top, bottom;  // z, m
    glm::vec4 color;
    float roughness;
    int texture;
  };
  const Layer layers[] = {{"skin", 0.0f, -0.002f, {1.0f, 1.0f, 1.0f, 1.0f}, 0.6f, skin_texture},
                          {"fat", -0.002f, -0.012f, {0.98f, 0.88f, 0.55f, 1.0f}, 0.5f, -1},
                          {"muscle", -0.012f, -0.040f, {0.62f, 0.14f, 0.14f, 1.0f}, 0.45f, -1},
                          {"bone", -0.040f, -0.050f, {0.92f, 0.90f, 0.82f, 1.0f}, 0.7f, -1}};
  for (const Layer& layer : layers) {
    const int material = b.add_material(layer.name, layer.color, 0.0f, layer.roughness, layer.texture);
    b.add_root_node(
        layer.name,
        b.add_mesh(layer.name, box_mesh({-half, -half, layer.bottom}, {half, half, layer.top}, cell), material));
  }
  return b.take();
}

tinygltf::Model make_lumbar_section() {
  constexpr float half = 0.05f;     // m: a 10 cm square section
  constexpr float window = 0.006f;  // half the interlaminar window along x (the spine's axis)
  GltfBuilder b("lumbar_section.bin");
  struct Part {
    const char* name;
    glm::vec3 min, max;
    glm::vec4 color;
    float roughness;
  };
  const glm::vec4 ligament{0.86f, 0.84f, 0.74f, 1.0f}, bone{0.93f, 0.91f, 0.83f, 1.0f};
  const Part parts[] = {
      {"skin", {-half, -half, -0.003f}, {half, half, 0.0f}, {0.93f, 0.76f, 0.66f, 1.0f}, 0.6f},
      {"subcutaneous fat", {-half, -half, -0.015f}, {half, half, -0.003f}, {0.98f, 0.88f, 0.55f, 1.0f}, 0.5f},
      {"supraspinous ligament", {-half, -half, -0.021f}, {half, half, -0.015f}, ligament, 0.45f},
      {"interspinous ligament",
       {-window, -half, -0.043f},
       {window, half, -0.021f},
       ligament * 0.9f + glm::vec4(0, 0, 0, 0.1f),
       0.45f},
      {"upper lamina", {-half, -half, -0.043f}, {-window, half, -0.021f}, bone, 0.7f},
      {"lower lamina", {window, -half, -0.043f}, {half, half, -0.021f}, bone, 0.7f},
      {"ligamentum flavum", {-half, -half, -0.048f}, {half, half, -0.043f}, {0.95f, 0.82f, 0.35f, 1.0f}, 0.4f},
      {"epidural space", {-half, -half, -0.053f}, {half, half, -0.048f}, {0.99f, 0.93f, 0.70f, 1.0f}, 0.5f},
      {"dura", {-half, -half, -0.0535f}, {half, half, -0.053f}, {0.70f, 0.78f, 0.92f, 1.0f}, 0.35f},
      {"cerebrospinal fluid", {-half, -half, -0.0685f}, {half, half, -0.0535f}, {0.55f, 0.75f, 0.95f, 1.0f}, 0.2f},
      {"vertebral body", {-half, -half, -0.0985f}, {half, half, -0.0685f}, bone, 0.7f}};
  for (const Part& part : parts) {
    const int material = b.add_material(part.name, part.color, 0.0f, part.roughness);
    b.add_root_node(part.name, b.add_mesh(part.name, box_mesh(part.min, part.max), material));
  }
  return b.take();
}

tinygltf::Model make_marker() {
  GltfBuilder b("marker.bin");
  const int green = b.add_material("marker", {0.1f, 0.85f, 0.2f, 1.0f}, 0.0f, 0.4f);
  b.add_root_node("marker", b.add_mesh("marker", sphere_mesh(0.003, 16, 16), green));
  return b.take();
}

std::vector<GeneratedAsset> committed_assets() {
  std::vector<GeneratedAsset> assets;
  assets.push_back({"sphere_100.gltf", make_sphere(100, 100)});
  assets.push_back({"needle.gltf", make_needle()});
  assets.push_back({"tissue_block.gltf", make_tissue_block()});
  assets.push_back({"marker.gltf", make_marker()});
  assets.push_back({"lumbar_section.gltf", make_lumbar_section()});
  return assets;
}

void write_asset(const GeneratedAsset& asset, const std::filesystem::path& folder) {
  tinygltf::TinyGLTF writer;
  // tinygltf's image writer needs file callbacks to write PNGs next to the glTF.
  tinygltf::FsCallbacks files{&tinygltf::FileExists, &tinygltf::ExpandFilePath, &tinygltf::ReadWholeFile,
                              &tinygltf::WriteWholeFile, nullptr};
  writer.SetImageWriter(&tinygltf::WriteImageData, &files);
  const std::string path = (folder / asset.file).string();
  if (!writer.WriteGltfSceneToFile(&asset.model, path, /*embedImages=*/false, /*embedBuffers=*/false,
                                   /*prettyPrint=*/true, /*writeBinary=*/false))
    throw std::runtime_error("cannot write " + path);
}

}  // namespace needle::asset_gen
