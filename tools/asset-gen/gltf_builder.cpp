#include "asset-gen/gltf_builder.hpp"

#include <cstring>

namespace needle::asset_gen {

GltfBuilder::GltfBuilder(const std::string& bin_uri) {
  model_.asset.version = "2.0";
  model_.asset.generator = "needle-asset-gen";
  model_.buffers.emplace_back();
  model_.buffers[0].uri = bin_uri;
  model_.scenes.emplace_back();
  model_.defaultScene = 0;
}

int GltfBuilder::add_material(const std::string& name, const glm::vec4& base_color, float metallic, float roughness,
                              int base_color_texture) {
  tinygltf::Material material;
  material.name = name;
  material.pbrMetallicRoughness.baseColorFactor = {base_color.r, base_color.g, base_color.b, base_color.a};
  material.pbrMetallicRoughness.metallicFactor = metallic;
  material.pbrMetallicRoughness.roughnessFactor = roughness;
  material.pbrMetallicRoughness.baseColorTexture.index = base_color_texture;
  model_.materials.push_back(material);
  return static_cast<int>(model_.materials.size()) - 1;
}

int GltfBuilder::add_texture(const std::string& uri, int width, int height, std::vector<unsigned char> rgba8) {
  tinygltf::Image image;
  image.uri = uri;
  image.mimeType = "image/png";
  image.width = width;
  image.height = height;
  image.component = 4;
  image.bits = 8;
  image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  image.image = std::move(rgba8);
  model_.images.push_back(std::move(image));
  tinygltf::Sampler sampler;
  sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
  sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
  model_.samplers.push_back(sampler);
  tinygltf::Texture texture;
  texture.source = static_cast<int>(model_.images.size()) - 1;
  texture.sampler = static_cast<int>(model_.samplers.size()) - 1;
  model_.textures.push_back(texture);
  return static_cast<int>(model_.textures.size()) - 1;
}

int append_accessor(tinygltf::Model& model, const void* data, size_t bytes, size_t count, int type, int component_type,
                    int target) {
  if (model.buffers.empty()) model.buffers.emplace_back();
  std::vector<unsigned char>& buffer = model.buffers[0].data;
  buffer.resize((buffer.size() + 3) / 4 * 4, 0);  // every view starts 4-byte aligned
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = bytes;
  view.target = target;
  buffer.resize(buffer.size() + bytes);
  if (bytes) std::memcpy(buffer.data() + view.byteOffset, data, bytes);
  model.bufferViews.push_back(view);
  tinygltf::Accessor accessor;
  accessor.bufferView = static_cast<int>(model.bufferViews.size()) - 1;
  accessor.componentType = component_type;
  accessor.count = count;
  accessor.type = type;
  model.accessors.push_back(accessor);
  return static_cast<int>(model.accessors.size()) - 1;
}

namespace {

// An index accessor: u16 while the vertices fit, else u32.
int append_indices(tinygltf::Model& model, const std::vector<uint32_t>& indices, size_t vertices) {
  if (vertices <= 65536) {
    const std::vector<uint16_t> narrow(indices.begin(), indices.end());
    return append_accessor(model, narrow.data(), narrow.size() * 2, narrow.size(), TINYGLTF_TYPE_SCALAR,
                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  }
  return append_accessor(model, indices.data(), indices.size() * 4, indices.size(), TINYGLTF_TYPE_SCALAR,
                         TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
}

}  // namespace

int GltfBuilder::add_mesh(const std::string& name, const MeshData& mesh, int material) {
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.material = material;
  const size_t n = mesh.positions.size();
  const int position = append_accessor(model_, mesh.positions.data(), n * sizeof(glm::vec3), n, TINYGLTF_TYPE_VEC3,
                                       TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TARGET_ARRAY_BUFFER);
  glm::vec3 lo(mesh.positions[0]), hi(mesh.positions[0]);
  for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  model_.accessors[static_cast<size_t>(position)].minValues = {lo.x, lo.y, lo.z};  // required by glTF
  model_.accessors[static_cast<size_t>(position)].maxValues = {hi.x, hi.y, hi.z};
  primitive.attributes["POSITION"] = position;
  primitive.attributes["NORMAL"] =
      append_accessor(model_, mesh.normals.data(), n * sizeof(glm::vec3), n, TINYGLTF_TYPE_VEC3,
                      TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TARGET_ARRAY_BUFFER);
  primitive.attributes["TEXCOORD_0"] =
      append_accessor(model_, mesh.uvs.data(), n * sizeof(glm::vec2), n, TINYGLTF_TYPE_VEC2,
                      TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TARGET_ARRAY_BUFFER);
  primitive.indices = append_indices(model_, mesh.indices, n);
  if (!mesh.coarser_indices.empty()) {
    tinygltf::Value::Array levels;
    for (const auto& level : mesh.coarser_indices) levels.emplace_back(append_indices(model_, level, n));
    primitive.extras = tinygltf::Value(tinygltf::Value::Object{{"needle_coarser_indices", tinygltf::Value(levels)}});
  }
  tinygltf::Mesh out;
  out.name = name;
  out.primitives.push_back(primitive);
  model_.meshes.push_back(out);
  return static_cast<int>(model_.meshes.size()) - 1;
}

void GltfBuilder::add_root_node(const std::string& name, int mesh, const glm::dvec3& translation) {
  tinygltf::Node node;
  node.name = name;
  node.mesh = mesh;
  if (translation != glm::dvec3(0.0)) node.translation = {translation.x, translation.y, translation.z};
  model_.nodes.push_back(node);
  model_.scenes[0].nodes.push_back(static_cast<int>(model_.nodes.size()) - 1);
}

}  // namespace needle::asset_gen
