// The base mesh: an arbitrary polygon mesh as imported, checked and repaired.
#pragma once

#include "core/vec.h"

#include <cstddef> // for std::size_t
#include <string>  // for std::string
#include <vector>  // for std::vector

namespace meshpaint {

//! What import changed, so that nothing is dropped silently.
struct ImportReport
{
  std::size_t faces_skipped_by_reader = 0;     //!< listed in the file, never delivered
  std::size_t degenerate_faces_dropped = 0;    //!< faces naming one vertex twice
  std::size_t duplicate_faces_dropped = 0;     //!< faces with the corners of an earlier face (either orientation)
  std::size_t nonmanifold_faces_detached = 0;  //!< faces OpenMesh could not join to their neighbours
  std::size_t nonmanifold_vertices_split = 0;  //!< extra surface sheets at one vertex
  std::size_t isolated_vertices_removed = 0;   //!< vertices used by no face

  bool changed() const;
  //! One line per repair, e.g. "removed 2 vertices used by no face".
  std::vector<std::string> lines() const;
};

//! Polygons as a flat index list. Valid by construction: at least one face,
//! finite coordinates, every face with >= 3 distinct vertices in range, every
//! vertex used, manifold (each edge in at most two faces, one fan per vertex).
struct BaseMesh
{
  std::string name;               //!< file stem, or a given name
  std::vector<Vec3> points;       //!< #vertices
  std::vector<int> face_sizes;    //!< #faces, corners per face
  std::vector<int> face_offsets;  //!< #faces + 1, into face_vertices
  std::vector<int> face_vertices; //!< sum(face_sizes), counter-clockwise
  ImportReport report;

  std::size_t vertex_count() const { return points.size(); }
  std::size_t face_count() const { return face_sizes.size(); }
  //! Length of the bounding-box diagonal.
  double diagonal() const;
};

//! Largest coordinate magnitude accepted: limit normals (cross products of
//! tangents, then their squared length) overflow single precision near 1e19.
constexpr float kMaxCoordinate = 1e15f;

//! Builds a base mesh from points and faces, checking and repairing as
//! load_mesh does.
//! Faces with fewer than three distinct vertices are dropped and counted.
//! \throw InputError naming the first problem (no faces, non-finite
//! coordinate or one beyond kMaxCoordinate, index out of range).
BaseMesh make_base_mesh(std::vector<Vec3> points, const std::vector<std::vector<int>>& faces,
                        const std::string& name = "mesh");

//! Reads OBJ, OFF, PLY or STL through OpenMesh.
//! \throw IOError when the file is missing or unreadable.
//! \throw InputError when the format is unknown or the mesh is unusable.
BaseMesh load_mesh(const std::string& path);

//! File extensions load_mesh reads, lower case with the dot.
const std::vector<std::string>& readable_mesh_extensions();

} // namespace meshpaint
