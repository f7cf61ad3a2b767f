// The painted model as glTF 2.0 (through tinygltf): the model of
// build_export() with a PBR material per side: base colour from diffuse,
// metallic-roughness from roughness, specular through KHR_materials_specular.
#pragma once

#include "paint/model_export.h"

#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint {

//! A texture of the glTF model: a PNG file beside it (`uri`, relative to the
//! model), or the PNG's bytes carried inside it (`png`).
struct GltfImage
{
  std::string uri;
  std::string png;
};

//! The three textures of one material.
struct GltfMaterialImages
{
  GltfImage base_colour;        //!< diffuse, RGB
  GltfImage metallic_roughness; //!< metallic_roughness_map()
  GltfImage specular;           //!< specular colour, RGB
};

//! The textures of both sides; `inside` is used only by two-sided models.
struct GltfImages
{
  GltfMaterialImages outside, inside;
};

//! The metallic-roughness map glTF expects from a roughness map (one value
//! per pixel): RGB with R = 1 (no occlusion), G = roughness, B = 0 (no metal).
std::vector<float> metallic_roughness_map(const std::vector<float>& roughness);

//! The model as glTF 2.0: `binary` gives a .glb (JSON and one binary chunk),
//! otherwise a .gltf whose buffer is a base64 data URI. Vertices are the
//! quad corners (welded where they share a texture coordinate), each quad
//! two triangles; a two-sided model gets a second primitive, turned the other
//! way with its own normals and the material `inside`. The specular colour
//! texture is the painted F0 (specularColorFactor 25 against glTF's 0.04).
//! \throw IOError when tinygltf cannot serialise the model.
std::string gltf_bytes(const ExportModel& model, const TextureMaps& maps, const GltfImages& images, bool binary);

} // namespace meshpaint
