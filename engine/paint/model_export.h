// The painted surface as a model any renderer loads: a quad mesh of a
// coarse level whose corners carry texture coordinates into texture maps of
// the painting level (the atlas images of the paint channels).
#pragma once

#include "mesh/welded_surface.h"

#include <array>  // for std::array
#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint {

class PaintSurface;

//! Channel images, row 0 at the top. Each patch's tile is surrounded by a
//! one-pixel gutter repeating its border, so bilinear filtering at a tile's
//! rim reads only that patch's colours.
struct TextureMaps
{
  int width = 0, height = 0;
  std::vector<float> diffuse, specular;        //!< rgb per pixel, 0..1
  std::vector<float> roughness, displacement;  //!< one value per pixel
  float displacement_min = 0.f, displacement_max = 0.f;
  //! Two-sided surfaces: the inside's maps; empty otherwise.
  std::vector<float> inside_diffuse, inside_specular, inside_roughness;
  //! Means over every patch's pixels, for formats with one value per
  //! material (the MTL's Ks and Ns); [1] is the inside's.
  std::array<Vec3, 2> mean_specular{};
  std::array<float, 2> mean_roughness{};
};

struct ExportModel
{
  WeldedSurface mesh;                       //!< points on the limit surface, with normals
  std::vector<std::array<float, 2>> uvs;    //!< per quad corner (4 per quad), OBJ convention (v up)
};

//! The model at `model_level` (1 .. the painting level) and the texture
//! maps of the painting level. Model points are limit-surface points without
//! the displacement channel, which travels in its own map.
void build_export(PaintSurface& surface, int model_level, ExportModel& model, TextureMaps& maps);

//! The Phong exponent (an MTL's Ns, 0..1000) matching a roughness 0..1:
//! 2 / a^2 - 2 with a = roughness^2, the usual Blinn-Phong to GGX match.
float phong_exponent(float roughness);

//! Writes DIR/model.obj and DIR/model.mtl (atomically) naming the maps
//! diffuse.png, specular.png, roughness.png and displacement.png; the MTL
//! records how displacement pixels map back to world units. Ks is the mean
//! painted specular colour and Ns phong_exponent() of the mean roughness, so
//! renderers that read no maps but Kd's (VTK's OBJ importer) show the
//! painted shine. A two-sided surface gets a second material, `inside`, with
//! the inside_*.png maps, on a second copy of the faces turned the other way.
//! \throw IOError when a file cannot be written; StorageError on a full disk.
void write_obj_model(const ExportModel& model, const TextureMaps& maps, const std::string& dir);

} // namespace meshpaint
