// Polygons with scalar properties per vertex and per face, as PLY.
#pragma once

#include "core/vec.h"

#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint {

//! One scalar property, a value per vertex (or per face).
struct PlyProperty
{
  std::string name;
  bool integer = false;       //!< written as int32, else float32
  bool byte = false;          //!< written as uchar (values 0..255), whatever `integer` says
  std::vector<double> values; //!< #vertices (#faces)
};

//! Writes points, polygons and their properties as binary little-endian PLY
//! through OpenMesh's writer (each property a persistent custom property),
//! keeping the vertex and face order; polygon f has the corners
//! face_corners[face_offsets[f]] to face_corners[face_offsets[f + 1] - 1]. Any
//! polygons are kept, non-manifold ones too. Atomic.
//! \throw InputError when a face names a vertex that is not there or a
//! property has the wrong count; IOError when writing fails.
void write_property_ply(const std::vector<Vec3>& points, const std::vector<int>& face_offsets,
                        const std::vector<int>& face_corners, const std::vector<PlyProperty>& vertex_properties,
                        const std::vector<PlyProperty>& face_properties, const std::string& path);

} // namespace meshpaint
