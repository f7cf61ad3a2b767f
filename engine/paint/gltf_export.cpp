#include "paint/gltf_export.h"

#include "core/errors.h"

#include <tiny_gltf.h> // for tinygltf::Model, tinygltf::TinyGLTF

#include <algorithm>     // for std::min, std::max
#include <cstdint>       // for std::uint32_t, std::uint64_t
#include <cstring>       // for std::memcpy
#include <sstream>       // for std::ostringstream
#include <unordered_map> // for std::unordered_map

namespace meshpaint {
namespace {

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;

//! The model's one buffer, filled view by view (each 4-byte aligned).
class BufferBuilder
{
public:
  explicit BufferBuilder(tinygltf::Model& model) : model_(model) { model_.buffers.resize(1); }

  //! A view of `bytes` bytes at `data`; returns its index.
  int view(const void* data, std::size_t bytes, int target)
  {
    std::vector<unsigned char>& buffer = model_.buffers[0].data;
    buffer.resize((buffer.size() + 3) / 4 * 4, 0);
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = buffer.size();
    v.byteLength = bytes;
    v.target = target;
    const auto* from = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), from, from + bytes);
    model_.bufferViews.push_back(v);
    return int(model_.bufferViews.size()) - 1;
  }

  //! An accessor over a new view of `values` (`width` floats per element, or
  //! uint32 indices when `width` is 0); returns its index.
  template <typename T>
  int accessor(const std::vector<T>& values, int width, int target)
  {
    tinygltf::Accessor a;
    a.bufferView = view(values.data(), values.size() * sizeof(T), target);
    a.componentType = width == 0 ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT : kFloat;
    a.type = width == 0 ? TINYGLTF_TYPE_SCALAR : width == 2 ? TINYGLTF_TYPE_VEC2 : TINYGLTF_TYPE_VEC3;
    a.count = values.size() / std::size_t(std::max(width, 1));
    model_.accessors.push_back(a);
    return int(model_.accessors.size()) - 1;
  }

  tinygltf::Accessor& last_accessor() { return model_.accessors.back(); }

private:
  tinygltf::Model& model_;
};

//! Adds image, texture (with sampler 0) for one map; returns the texture.
int add_texture(tinygltf::Model& model, BufferBuilder& buffer, const GltfImage& image, const std::string& name)
{
  tinygltf::Image i;
  i.name = name;
  if (!image.uri.empty())
    i.uri = image.uri;
  else {
    i.bufferView = buffer.view(image.png.data(), image.png.size(), 0);
    i.mimeType = "image/png";
  }
  model.images.push_back(i);
  tinygltf::Texture t;
  t.sampler = 0;
  t.source = int(model.images.size()) - 1;
  model.textures.push_back(t);
  return int(model.textures.size()) - 1;
}

//! The PBR material of one side; returns its index.
int add_material(tinygltf::Model& model, BufferBuilder& buffer, const GltfMaterialImages& images,
                 const std::string& name)
{
  tinygltf::Material m;
  m.name = name;
  m.pbrMetallicRoughness.baseColorTexture.index = add_texture(model, buffer, images.base_colour, name + "_diffuse");
  m.pbrMetallicRoughness.metallicRoughnessTexture.index =
    add_texture(model, buffer, images.metallic_roughness, name + "_metallic_roughness");
  m.pbrMetallicRoughness.metallicFactor = 0.0;
  m.pbrMetallicRoughness.roughnessFactor = 1.0;
  tinygltf::Value::Object texture{{"index", tinygltf::Value(add_texture(model, buffer, images.specular,
                                                                          name + "_specular"))}};
  // glTF's dielectric F0 is 0.04 * specularColor: 25 makes F0 the painted colour.
  tinygltf::Value::Array factor(3, tinygltf::Value(25.0));
  tinygltf::Value::Object specular{{"specularFactor", tinygltf::Value(1.0)},
                                   {"specularColorFactor", tinygltf::Value(factor)},
                                   {"specularColorTexture", tinygltf::Value(texture)}};
  m.extensions["KHR_materials_specular"] = tinygltf::Value(specular);
  model.materials.push_back(m);
  return int(model.materials.size()) - 1;
}

//! Corners welded by texture coordinate: within a tile every corner with
//! one coordinate is one model vertex.
struct Corners
{
  std::vector<float> positions, normals, uvs; //!< 3, 3 and 2 per vertex
  std::vector<std::uint32_t> outer, inner;    //!< triangles, and the same turned round
  std::vector<int> vertex;                    //!< the model vertex of each corner vertex
};

Corners corners_of(const ExportModel& model)
{
  Corners c;
  std::unordered_map<std::uint64_t, std::uint32_t> index;
  std::vector<std::uint32_t> quad(4);
  for (std::size_t q = 0; q < model.mesh.quads.size(); ++q) {
    for (int k = 0; k < 4; ++k) {
      const auto& uv = model.uvs[4 * q + std::size_t(k)];
      std::uint32_t u, v;
      std::memcpy(&u, &uv[0], 4);
      std::memcpy(&v, &uv[1], 4);
      const auto [at, added] = index.emplace((std::uint64_t(u) << 32) | v, std::uint32_t(c.vertex.size()));
      if (added) {
        const int mv = model.mesh.quads[q][std::size_t(k)];
        c.vertex.push_back(mv);
        for (int a = 0; a < 3; ++a) {
          c.positions.push_back(model.mesh.points[std::size_t(mv)][a]);
          c.normals.push_back(model.mesh.normals[std::size_t(mv)][a]);
        }
        c.uvs.push_back(uv[0]);
        c.uvs.push_back(1.f - uv[1]); // glTF's v runs down the image
      }
      quad[std::size_t(k)] = at->second;
    }
    for (const std::uint32_t i : {quad[0], quad[1], quad[2], quad[0], quad[2], quad[3]})
      c.outer.push_back(i);
    for (const std::uint32_t i : {quad[0], quad[2], quad[1], quad[0], quad[3], quad[2]})
      c.inner.push_back(i);
  }
  return c;
}

} // namespace

std::vector<float> metallic_roughness_map(const std::vector<float>& roughness)
{
  std::vector<float> rgb(3 * roughness.size(), 0.f);
  for (std::size_t p = 0; p < roughness.size(); ++p) {
    rgb[3 * p] = 1.f;
    rgb[3 * p + 1] = roughness[p];
  }
  return rgb;
}

std::string gltf_bytes(const ExportModel& model, const TextureMaps& maps, const GltfImages& images, bool binary)
{
  tinygltf::Model gltf;
  gltf.asset.version = "2.0";
  gltf.asset.generator = "meshpaint";
  gltf.extensionsUsed.push_back("KHR_materials_specular");
  BufferBuilder buffer(gltf);
  const Corners c = corners_of(model);

  const int positions = buffer.accessor(c.positions, 3, TINYGLTF_TARGET_ARRAY_BUFFER);
  {
    tinygltf::Accessor& a = buffer.last_accessor();
    a.minValues.assign(3, c.positions.empty() ? 0.0 : 1e300);
    a.maxValues.assign(3, c.positions.empty() ? 0.0 : -1e300);
    for (std::size_t k = 0; k < c.positions.size(); ++k) {
      a.minValues[k % 3] = std::min(a.minValues[k % 3], double(c.positions[k]));
      a.maxValues[k % 3] = std::max(a.maxValues[k % 3], double(c.positions[k]));
    }
  }
  const int normals = buffer.accessor(c.normals, 3, TINYGLTF_TARGET_ARRAY_BUFFER);
  const int uvs = buffer.accessor(c.uvs, 2, TINYGLTF_TARGET_ARRAY_BUFFER);

  gltf.samplers.resize(1);
  gltf.samplers[0].magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
  gltf.samplers[0].minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
  gltf.samplers[0].wrapS = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
  gltf.samplers[0].wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;

  tinygltf::Mesh mesh;
  mesh.name = "painted";
  tinygltf::Primitive outside;
  outside.attributes = {{"POSITION", positions}, {"NORMAL", normals}, {"TEXCOORD_0", uvs}};
  outside.indices = buffer.accessor(c.outer, 0, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  outside.material = add_material(gltf, buffer, images.outside, "painted");
  outside.mode = TINYGLTF_MODE_TRIANGLES;
  mesh.primitives.push_back(outside);
  if (!maps.inside_diffuse.empty()) { // the inside: its own normals, faces turned round
    std::vector<float> flipped(c.normals.size());
    for (std::size_t k = 0; k < flipped.size(); ++k)
      flipped[k] = -c.normals[k];
    tinygltf::Primitive inside;
    inside.attributes = {{"POSITION", positions},
                         {"NORMAL", buffer.accessor(flipped, 3, TINYGLTF_TARGET_ARRAY_BUFFER)},
                         {"TEXCOORD_0", uvs}};
    inside.indices = buffer.accessor(c.inner, 0, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    inside.material = add_material(gltf, buffer, images.inside, "inside");
    inside.mode = TINYGLTF_MODE_TRIANGLES;
    mesh.primitives.push_back(inside);
  }
  gltf.meshes.push_back(mesh);
  tinygltf::Node node;
  node.mesh = 0;
  node.name = "painted";
  gltf.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  gltf.scenes.push_back(scene);
  gltf.defaultScene = 0;

  tinygltf::TinyGLTF writer;
  writer.SetImageWriter(nullptr, nullptr); // images are PNG already: files beside the model, or views
  std::ostringstream out(std::ios::binary);
  if (!writer.WriteGltfSceneToStream(&gltf, out, !binary, binary))
    throw IOError("tinygltf could not write the model");
  return out.str();
}

} // namespace meshpaint
