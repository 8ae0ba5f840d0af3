// glTF 2.0 loading: files (.gltf + external files, .glb, data URIs) and in-memory models,
// validated before any read and converted to the renderer's Model (model.hpp).
#pragma once

#include <filesystem>
#include <string>

#include "engine/model.hpp"

namespace tinygltf {
class Model;
}

namespace needle::engine {

// Loads and converts a .gltf or .glb file. External URIs must stay inside the file's folder.
// Throws AssetError "FILE: ELEMENT: what is wrong" on any fault.
Model load_gltf(const std::filesystem::path& file);

// Validates and converts a model already in memory (e.g. built by the asset generator).
// source_name is the FILE part of error messages.
Model convert_gltf(const tinygltf::Model& gltf, const std::string& source_name);

}  // namespace needle::engine
