// convert_gltf: validated conversion of a tinygltf::Model to the renderer's Model.
#include <tiny_gltf.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "engine/gltf/gltf_accessor.hpp"
#include "engine/gltf/gltf_errors.hpp"
#include "engine/gltf/image_decode.hpp"
#include "engine/gltf/mesh_normals.hpp"
#include "engine/gltf_loader.hpp"

namespace needle::engine {
namespace {

using tinygltf::Model;
constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
constexpr int kU8 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr int kU16 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
constexpr int kU32 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;

// ---- textures -------------------------------------------------------------------------

// tinygltf decodes images given by URI while loading; images in a bufferView are decoded
// here, after their bufferView has been bounds-checked (load_gltf defers them).
tinygltf::Image decoded_image(const Model& gltf, size_t index, const std::string& file) {
  const tinygltf::Image& image = gltf.images[index];
  const std::string name = element_name("images", index);
  if (!image.image.empty()) return image;
  if (image.bufferView < 0)
    asset_fail(file, name, "no pixel data: uri \"" + image.uri + "\" could not be read or decoded");
  const ByteSpan bytes = view_buffer_view(gltf, image.bufferView, file, name);
  if (bytes.size == 0 || bytes.size > static_cast<size_t>(INT_MAX))
    asset_fail(file, name, "bufferView size " + std::to_string(bytes.size) + " is not a valid image size");
  tinygltf::Image decoded;
  std::string err, warn;
  if (!decode_image(&decoded, static_cast<int>(index), &err, &warn, bytes.data, static_cast<int>(bytes.size)))
    asset_fail(file, name, "cannot decode the image (" + image.mimeType + "): " + err);
  return decoded;
}

Texture to_rgba8(const tinygltf::Image& image, const std::string& file, const std::string& name) {
  const int channels = image.component;
  if (image.width < 1 || image.height < 1 || channels < 1 || channels > 4 || (image.bits != 8 && image.bits != 16))
    asset_fail(file, name,
               "unsupported image " + std::to_string(image.width) + "x" + std::to_string(image.height) + ", " +
                   std::to_string(channels) + " channels of " + std::to_string(image.bits) + " bits");
  const uint64_t texels = uint64_t(image.width) * uint64_t(image.height);
  const uint64_t bytes_per_value = uint64_t(image.bits / 8);
  if (image.image.size() != texels * uint64_t(channels) * bytes_per_value)
    asset_fail(file, name,
               "pixel data has " + std::to_string(image.image.size()) +
                   " bytes, expected width x height x channels x bytes per channel");
  Texture texture{static_cast<uint32_t>(image.width), static_cast<uint32_t>(image.height), {}};
  texture.rgba8.resize(texels * 4);
  auto value = [&](uint64_t i) -> uint8_t {  // channel value i, reduced to 8 bits
    if (bytes_per_value == 1) return image.image[i];
    const unsigned v = image.image[2 * i] | (unsigned(image.image[2 * i + 1]) << 8);
    return static_cast<uint8_t>((v * 255u + 32767u) / 65535u);
  };
  for (uint64_t t = 0; t < texels; ++t) {
    const uint64_t in = t * uint64_t(channels);
    uint8_t* out = &texture.rgba8[t * 4];
    const bool grey = channels <= 2;
    out[0] = value(in);
    out[1] = grey ? out[0] : value(in + 1);
    out[2] = grey ? out[0] : value(in + 2);
    out[3] = channels == 2 ? value(in + 1) : channels == 4 ? value(in + 3) : 255;
  }
  return texture;
}

std::vector<Texture> convert_textures(const Model& gltf, const std::string& file) {
  std::vector<Texture> textures;
  for (size_t t = 0; t < gltf.textures.size(); ++t) {
    const int source = gltf.textures[t].source;
    if (source < 0 || static_cast<size_t>(source) >= gltf.images.size())
      asset_fail(file, element_name("textures", t), "source image " + std::to_string(source) + " does not exist");
    const size_t s = static_cast<size_t>(source);
    textures.push_back(to_rgba8(decoded_image(gltf, s, file), file, element_name("images", s)));
  }
  return textures;
}

// ---- materials ------------------------------------------------------------------------

Material convert_material(const Model& gltf, size_t index, const std::string& file) {
  const tinygltf::Material& in = gltf.materials[index];
  const std::string name = element_name("materials", index);
  const tinygltf::PbrMetallicRoughness& pbr = in.pbrMetallicRoughness;
  Material out;
  if (pbr.baseColorFactor.size() != 4)
    asset_fail(file, name,
               "baseColorFactor has " + std::to_string(pbr.baseColorFactor.size()) + " numbers, expected 4");
  out.base_color_factor =
      glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2], pbr.baseColorFactor[3]);
  if (pbr.baseColorTexture.index >= 0) {
    if (static_cast<size_t>(pbr.baseColorTexture.index) >= gltf.textures.size())
      asset_fail(file, name, "baseColorTexture " + std::to_string(pbr.baseColorTexture.index) + " does not exist");
    if (pbr.baseColorTexture.texCoord != 0)
      asset_fail(file, name,
                 "baseColorTexture uses TEXCOORD_" + std::to_string(pbr.baseColorTexture.texCoord) +
                     ", only TEXCOORD_0 is supported");
    out.base_color_texture = pbr.baseColorTexture.index;
  }
  out.metallic_factor = static_cast<float>(pbr.metallicFactor);
  out.roughness_factor = static_cast<float>(pbr.roughnessFactor);
  if (in.alphaMode == "OPAQUE")
    out.alpha_mode = AlphaMode::Opaque;
  else if (in.alphaMode == "MASK")
    out.alpha_mode = AlphaMode::Mask;
  else if (in.alphaMode == "BLEND")
    out.alpha_mode = AlphaMode::Blend;
  else
    asset_fail(file, name, "alphaMode \"" + in.alphaMode + "\", expected OPAQUE, MASK or BLEND");
  out.alpha_cutoff = static_cast<float>(in.alphaCutoff);
  out.double_sided = in.doubleSided;
  return out;
}

// ---- primitives -----------------------------------------------------------------------

std::vector<uint32_t> triangle_list(const std::vector<uint32_t>& v, int mode, const std::string& file,
                                    const std::string& name) {
  switch (mode) {
    case TINYGLTF_MODE_TRIANGLES:
      if (v.size() % 3 != 0) asset_fail(file, name, std::to_string(v.size()) + " indices is not a multiple of 3");
      return v;
    case TINYGLTF_MODE_TRIANGLE_STRIP:
    case TINYGLTF_MODE_TRIANGLE_FAN: {
      if (v.size() < 3) asset_fail(file, name, std::to_string(v.size()) + " indices, a strip or fan needs 3");
      std::vector<uint32_t> out;
      out.reserve(3 * (v.size() - 2));
      for (size_t i = 0; i + 2 < v.size(); ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {  // spec: {v[i+1], v[i+2], v[0]}
          out.insert(out.end(), {v[i + 1], v[i + 2], v[0]});
        } else {  // spec: {v[i], v[i+1+i%2], v[i+2-i%2]}, which keeps the winding
          const size_t odd = i % 2;
          out.insert(out.end(), {v[i], v[i + 1 + odd], v[i + 2 - odd]});
        }
      }
      return out;
    }
    default:
      asset_fail(file, name,
                 "mode " + std::to_string(mode) +
                     " (points or lines) is not supported: only triangles, "
                     "triangle strips and triangle fans");
  }
}

std::vector<uint32_t> read_indices(const Model& gltf, int accessor, size_t vertices, const std::string& file,
                                   const std::string& what) {
  const AccessorView view = view_accessor(gltf, accessor, file, what, {{TINYGLTF_TYPE_SCALAR}, {kU8, kU16, kU32}});
  std::vector<uint32_t> indices(view.count());
  for (size_t i = 0; i < indices.size(); ++i) {
    indices[i] = view.index(i);
    if (indices[i] >= vertices)
      asset_fail(file, what,
                 "index " + std::to_string(i) + " is " + std::to_string(indices[i]) + ", not below the " +
                     std::to_string(vertices) + " vertices");
  }
  return indices;
}

// An asset's levels of detail: primitive extras {"needle_coarser_indices": [accessor, ...]}, triangle
// lists over the primitive's own vertices, finest first.
std::vector<std::vector<uint32_t>> coarser_indices(const Model& gltf, const tinygltf::Primitive& in, size_t vertices,
                                                   const std::string& file, const std::string& name) {
  constexpr const char* kKey = "needle_coarser_indices";
  if (!in.extras.IsObject() || !in.extras.Has(kKey)) return {};
  const tinygltf::Value& list = in.extras.Get(kKey);
  const std::string where = name + ".extras." + kKey;
  if (!list.IsArray()) asset_fail(file, where, "expected an array of accessor indices");
  std::vector<std::vector<uint32_t>> levels;
  for (size_t k = 0; k < list.ArrayLen(); ++k) {
    const std::string what = where + "[" + std::to_string(k) + "]";
    if (!list.Get(int(k)).IsInt()) asset_fail(file, what, "expected an accessor index");
    levels.push_back(read_indices(gltf, list.Get(int(k)).GetNumberAsInt(), vertices, file, what));
    if (levels.back().size() % 3 != 0)
      asset_fail(file, what, std::to_string(levels.back().size()) + " indices is not a multiple of 3");
  }
  return levels;
}

Primitive convert_primitive(const Model& gltf, size_t mesh, size_t index, const std::string& file) {
  const tinygltf::Primitive& in = gltf.meshes[mesh].primitives[index];
  const std::string name = element_name("meshes", mesh) + "." + element_name("primitives", index);
  auto attribute = [&](const char* semantic) {
    const auto it = in.attributes.find(semantic);
    return it == in.attributes.end() ? -1 : it->second;
  };
  auto usage = [&](const std::string& what) { return what + " of " + name; };

  const int position_accessor = attribute("POSITION");
  if (position_accessor < 0) asset_fail(file, name, "has no POSITION attribute");
  const AccessorView positions =
      view_accessor(gltf, position_accessor, file, usage("POSITION"), {{TINYGLTF_TYPE_VEC3}, {kFloat}});
  const size_t n = positions.count();
  auto same_count = [&](const AccessorView& view, const char* semantic) {
    if (view.count() != n)
      asset_fail(file, name,
                 std::string(semantic) + " has " + std::to_string(view.count()) + " elements but POSITION has " +
                     std::to_string(n));
    return view;
  };

  Primitive out;
  out.vertices.resize(n);
  for (size_t i = 0; i < n; ++i) {
    glm::vec3& p = out.vertices[i].position;
    p = {positions.component(i, 0), positions.component(i, 1), positions.component(i, 2)};
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      asset_fail(file, usage("POSITION"), "vertex " + std::to_string(i) + " is not finite");
  }
  if (const int a = attribute("TEXCOORD_0"); a >= 0) {
    const AccessorView uv =
        same_count(view_accessor(gltf, a, file, usage("TEXCOORD_0"), {{TINYGLTF_TYPE_VEC2}, {kFloat, kU8, kU16}, true}),
                   "TEXCOORD_0");
    for (size_t i = 0; i < n; ++i) out.vertices[i].uv = {uv.component(i, 0), uv.component(i, 1)};
  }
  if (const int a = attribute("COLOR_0"); a >= 0) {
    const AccessorView color =
        same_count(view_accessor(gltf, a, file, usage("COLOR_0"),
                                 {{TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, {kFloat, kU8, kU16}, true}),
                   "COLOR_0");
    for (size_t i = 0; i < n; ++i)
      for (int c = 0; c < color.components(); ++c) out.vertices[i].color[c] = color.component(i, c);
  }

  std::vector<uint32_t> indices;
  if (in.indices >= 0) {
    indices = read_indices(gltf, in.indices, n, file, usage("indices"));
  } else {
    indices.resize(n);
    for (size_t i = 0; i < n; ++i) indices[i] = static_cast<uint32_t>(i);
  }
  out.indices = triangle_list(indices, in.mode, file, name);
  out.coarser_indices = coarser_indices(gltf, in, n, file, name);

  if (const int a = attribute("NORMAL"); a >= 0) {
    const AccessorView normals =
        same_count(view_accessor(gltf, a, file, usage("NORMAL"), {{TINYGLTF_TYPE_VEC3}, {kFloat}}), "NORMAL");
    for (size_t i = 0; i < n; ++i)
      out.vertices[i].normal = {normals.component(i, 0), normals.component(i, 1), normals.component(i, 2)};
  } else {
    generate_normals(out.vertices, out.indices);
  }

  if (in.material >= static_cast<int>(gltf.materials.size()))
    asset_fail(file, name, "material " + std::to_string(in.material) + " does not exist");
  out.material = in.material < 0 ? -1 : in.material;
  return out;
}

// ---- node hierarchy -------------------------------------------------------------------

glm::mat4 local_transform(const tinygltf::Node& node, const std::string& file, const std::string& name) {
  if (!node.matrix.empty()) {
    if (node.matrix.size() != 16)
      asset_fail(file, name, "matrix has " + std::to_string(node.matrix.size()) + " numbers, expected 16");
    glm::dmat4 m;  // glTF matrices are column-major, as glm's
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) m[c][r] = node.matrix[static_cast<size_t>(4 * c + r)];
    return glm::mat4(m);
  }
  auto check_size = [&](const std::vector<double>& v, size_t size, const char* what) {
    if (!v.empty() && v.size() != size)
      asset_fail(file, name,
                 std::string(what) + " has " + std::to_string(v.size()) + " numbers, expected " + std::to_string(size));
    return !v.empty();
  };
  glm::dmat4 m(1.0);
  if (check_size(node.translation, 3, "translation"))
    m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
  if (check_size(node.rotation, 4, "rotation"))  // glTF stores x, y, z, w
    m *= glm::mat4_cast(
        glm::normalize(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2])));
  if (check_size(node.scale, 3, "scale")) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  return glm::mat4(m);
}

template <typename T>
bool finite(const T& value) {
  const float* x = glm::value_ptr(value);
  return std::all_of(x, x + sizeof(T) / sizeof(float), [](float v) { return std::isfinite(v); });
}

// How deep a node hierarchy may nest: 256 levels. Design value: an animated character's skeleton
// is under 100 levels deep, a CAD assembly a few tens; a chain of 100,000 nodes is no model, and
// its transforms, multiplied in 32-bit floats, would have drifted long before its end.
constexpr size_t kMaxNodeDepth = 256;

// Every node under the roots, each once, with its world transform: depth first with a stack of
// its own, not the call stack, and at most kMaxNodeDepth deep.
struct NodeWalker {
  const Model& gltf;
  const std::string& file;
  const std::vector<uint32_t>& first_primitive;  // per mesh, index into Model::primitives
  std::vector<bool> visited;
  std::vector<MeshInstance>& instances;

  struct Pending {
    int index;
    glm::mat4 parent;
    size_t referrer;  // the node whose children list it (for messages), or SIZE_MAX: the scene
    size_t depth;     // 1 for a root
  };

  void walk(int root, const glm::mat4& parent) {
    std::vector<Pending> stack{{root, parent, SIZE_MAX, 1}};
    while (!stack.empty()) {
      const Pending p = stack.back();
      stack.pop_back();
      if (p.index < 0 || static_cast<size_t>(p.index) >= gltf.nodes.size())
        asset_fail(file, p.referrer == SIZE_MAX ? "scene.nodes" : element_name("nodes", p.referrer) + ".children",
                   "node " + std::to_string(p.index) + " does not exist");
      const size_t i = static_cast<size_t>(p.index);
      if (p.depth > kMaxNodeDepth)
        asset_fail(file, element_name("nodes", i),
                   "nested deeper than " + std::to_string(kMaxNodeDepth) + " levels of the node hierarchy");
      // glTF nodes form disjoint trees; a second visit means a cycle or a shared child.
      if (visited[i]) asset_fail(file, element_name("nodes", i), "is reached twice (a cycle or more than one parent)");
      visited[i] = true;
      const tinygltf::Node& node = gltf.nodes[i];
      const glm::mat4 world = p.parent * local_transform(node, file, element_name("nodes", i));
      if (!finite(world))
        asset_fail(file, element_name("nodes", i),
                   "its transform, with its parents', is beyond what 32-bit floats hold");
      if (node.mesh >= 0) {
        if (static_cast<size_t>(node.mesh) >= gltf.meshes.size())
          asset_fail(file, element_name("nodes", i), "mesh " + std::to_string(node.mesh) + " does not exist");
        const size_t mesh = static_cast<size_t>(node.mesh);
        for (size_t k = 0; k < gltf.meshes[mesh].primitives.size(); ++k)
          instances.push_back({first_primitive[mesh] + static_cast<uint32_t>(k), world, node.name});
      }
      // Children pushed last first, so they are walked in their order.
      for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
        stack.push_back({*child, world, i, p.depth + 1});
    }
  }
};

std::vector<int> root_nodes(const Model& gltf, const std::string& file) {
  if (gltf.defaultScene >= 0) {
    if (static_cast<size_t>(gltf.defaultScene) >= gltf.scenes.size())
      asset_fail(file, "scene", "default scene " + std::to_string(gltf.defaultScene) + " does not exist");
    return gltf.scenes[static_cast<size_t>(gltf.defaultScene)].nodes;
  }
  std::vector<bool> is_child(gltf.nodes.size(), false);
  for (const tinygltf::Node& node : gltf.nodes)
    for (int child : node.children)
      if (child >= 0 && static_cast<size_t>(child) < is_child.size()) is_child[static_cast<size_t>(child)] = true;
  std::vector<int> roots;
  for (size_t i = 0; i < gltf.nodes.size(); ++i)
    if (!is_child[i]) roots.push_back(static_cast<int>(i));
  return roots;
}

Bounds world_bounds(const engine::Model& model) {
  Bounds b{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
  for (const MeshInstance& instance : model.instances)
    for (const MeshVertex& v : model.primitives[instance.primitive].vertices) {
      const glm::vec3 p(instance.world * glm::vec4(v.position, 1.0f));
      b.min = glm::min(b.min, p);
      b.max = glm::max(b.max, p);
    }
  return b;
}

}  // namespace

engine::Model convert_gltf(const tinygltf::Model& gltf, const std::string& file) {
  // A required extension changes what the data means (e.g. Draco-compressed meshes).
  for (const std::string& extension : gltf.extensionsRequired)
    asset_fail(file, "extensionsRequired", extension + " is not supported");
  engine::Model out;
  out.textures = convert_textures(gltf, file);
  for (size_t m = 0; m < gltf.materials.size(); ++m) out.materials.push_back(convert_material(gltf, m, file));
  std::vector<uint32_t> first_primitive;
  for (size_t m = 0; m < gltf.meshes.size(); ++m) {
    // glTF 2.0 requires at least one primitive a mesh (mesh.primitives: minItems 1).
    if (gltf.meshes[m].primitives.empty())
      asset_fail(file, element_name("meshes", m), "has no primitives (glTF requires at least one)");
    first_primitive.push_back(static_cast<uint32_t>(out.primitives.size()));
    for (size_t p = 0; p < gltf.meshes[m].primitives.size(); ++p)
      out.primitives.push_back(convert_primitive(gltf, m, p, file));
  }
  NodeWalker walker{gltf, file, first_primitive, std::vector<bool>(gltf.nodes.size(), false), out.instances};
  for (int root : root_nodes(gltf, file)) walker.walk(root, glm::mat4(1.0f));
  if (out.instances.empty()) asset_fail(file, "scene", "no node with a mesh: nothing to draw");
  out.world_bounds = world_bounds(out);
  if (!finite(out.world_bounds.min) || !finite(out.world_bounds.max))
    asset_fail(file, "scene", "its vertices, placed by the nodes' transforms, lie beyond what 32-bit floats hold");
  return out;
}

}  // namespace needle::engine
