// needle-sim patient: a patient file's generated lumbar patient written out: its fields (.nsdf),
// a mesh of each layer (.glb) and DIR/patient.json, the report of its dimensions (docs/PATIENTS.md).
#include <tiny_gltf.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "app/patient_look.hpp"
#include "app/patient_meshes.hpp"
#include "asset-gen/gltf_builder.hpp"
#include "command.hpp"
#include "haptics/anatomy/patient_report.hpp"
#include "haptics/anatomy/sdf_file.hpp"
#include "io/file_write.hpp"

namespace needle::cli {
namespace {

namespace fs = std::filesystem;
using haptics::anatomy::Patient;

struct PatientFlags {
  std::optional<std::string> patient, out;
};

// "erector spinae" => "erector_spinae".
std::string file_stem(std::string name) {
  for (char& c : name)
    if (c == ' ') c = '_';
  return name;
}

// One layer's region as a binary glTF: the mesh the window draws of it (app::patient_layer_model),
// in its colour, in the patient's model frame.
std::string layer_glb(const Patient& patient, size_t index) {
  const haptics::anatomy::PatientLayer& layer = patient.layers[index];
  const app::LayerLook look = app::patient_layer_look(layer.name);
  const engine::Primitive drawn = app::patient_layer_model(patient, index, Eigen::Vector3d::Zero()).primitives.at(0);
  asset_gen::MeshData data;
  for (const engine::MeshVertex& v : drawn.vertices) {
    data.positions.push_back(v.position);
    data.normals.push_back(v.normal);
    data.uvs.emplace_back(0.0f, 0.0f);
  }
  data.indices = drawn.indices;
  asset_gen::GltfBuilder builder("");
  const int material = builder.add_material(layer.name, look.color, 0.0f, look.roughness);
  builder.add_root_node(layer.name, builder.add_mesh(layer.name, data, material));
  tinygltf::Model model = builder.take();
  model.buffers[0].uri.clear();  // embedded: one .glb a layer
  std::ostringstream out;
  if (!tinygltf::TinyGLTF().WriteGltfSceneToStream(&model, out, false, true))
    throw std::runtime_error("cannot encode the mesh of " + layer.name);
  return out.str();
}

int run(const PatientFlags& f) {
  const auto start = std::chrono::steady_clock::now();
  const haptics::anatomy::PatientParams params = haptics::anatomy::load_patient(*f.patient);
  const Patient patient = haptics::anatomy::generate_patient(params);
  const double generation_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const fs::path out(*f.out);
  fs::create_directories(out / "fields");
  fs::create_directories(out / "meshes");
  nlohmann::json report = haptics::anatomy::patient_report(patient);
  nlohmann::json layers = nlohmann::json::array();
  std::map<const haptics::SdfGrid*, std::string> fields;
  for (size_t index = 0; index < patient.layers.size(); ++index) {
    const haptics::anatomy::PatientLayer& layer = patient.layers[index];
    const haptics::SdfGrid* grid = layer.shape.grid().get();
    if (!fields.count(grid)) {  // a shared grid under the first layer's name that uses it
      fields[grid] = "fields/" + file_stem(layer.name) + ".nsdf";
      haptics::anatomy::write_sdf_file((out / fields[grid]).string(), *grid);
    }
    const std::string mesh = "meshes/" + file_stem(layer.name) + ".glb";
    io::write_file(out / mesh, layer_glb(patient, index));
    layers.push_back({{"name", layer.name},
                      {"field", fields[grid]},
                      {"offset_m", layer.shape.grid_offset()},
                      {"mesh", mesh},
                      {"parameters", layer.parameters},
                      {"rigid", layer.rigid}});
  }
  report["layers"] = layers;
  io::write_file(out / "patient.json", report.dump(2) + "\n");
  const nlohmann::json& l34 = report["L3-L4"];
  std::printf(
      "%s: BMI %.1f, skin to epidural at L3-L4 %.1f mm, fat %.1f mm; %zu fields, %.1f MB; generated in %.2f s -> %s\n",
      f.patient->c_str(), params.bmi(),
      l34["skin_to_epidural_m"].is_number() ? l34["skin_to_epidural_m"].get<double>() * 1e3 : 0.0,
      patient.fat_thickness_m * 1e3, fields.size(), double(patient.field_bytes) / (1 << 20), generation_s,
      (out / "patient.json").string().c_str());
  return 0;
}

Runner declare(CLI::App& app) {
  auto f = std::make_shared<PatientFlags>();
  add_text(app, "--patient", f->patient, "FILE", "patient file (assets/patients/*.json, docs/PATIENTS.md)")->required();
  add_text(app, "--out", f->out, "DIR",
           "writes DIR/patient.json (the dimensions and the midline depths), DIR/fields/*.nsdf and DIR/meshes/*.glb")
      ->required();
  app.footer(
      "the patient's frame: x to its right, y cranial, z out of the back, the skin over L3-L4 on the midline at the "
      "origin");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{{"patient", "a generated lumbar patient: its fields, meshes and dimensions", declare}};

}  // namespace
}  // namespace needle::cli
