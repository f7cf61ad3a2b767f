// The base mesh: an arbitrary polygon mesh as imported, checked and repaired.
#pragma once

#include "core/vec.h"
#include "mesh/polygon_soup.h"

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
  // The import steps every file goes through (not repairs: a clean file's
  // soup of separate faces, or its inward winding, is normal input).
  std::size_t vertices_welded = 0;             //!< merged into a coincident vertex
  double weld_tolerance = 0;                   //!< absolute; 0 when welding was off
  std::size_t faces_flipped = 0;               //!< turned to agree with their neighbours
  std::size_t components_turned_outward = 0;   //!< closed components that were wound inward
  std::size_t nonorientable_components = 0;    //!< cut open (or split at non-manifold vertices) to orient
  std::size_t vertices_cut = 0;                //!< vertex copies made for those cuts
  bool coloured = false;                       //!< the file's colours became the diffuse channel
  std::string colour_array;                    //!< the file's array that gave them, empty for byte colours
  //! Each array taken as another channel: the file's name, the channel.
  std::vector<std::pair<std::string, std::string>> channel_arrays;
  std::size_t array_vertices = 0;              //!< the file's vertices that those arrays (and colour_array) cover
  std::size_t named_label_classes = 0;         //!< label classes the file names (FileLabelClass)
  std::string label_array;                     //!< the file's array that became the label channel, or empty
  std::size_t label_classes = 0;               //!< distinct ids in it

  //! Whether a repair changed the file's mesh (the import steps do not count).
  bool changed() const;
  //! One line per repair, e.g. "removed 2 vertices used by no face".
  std::vector<std::string> lines() const;
  //! One line per import step that did something, e.g. "welded 960
  //! coincident vertices (within 1e-05; --no-weld keeps them)". `source`
  //! names where the mesh came from ("the file", "the polydata"), `weld_off`
  //! the switch that keeps coincident vertices apart.
  std::vector<std::string> step_lines(const std::string& source = "the file",
                                      const std::string& weld_off = "--no-weld") const;
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
  std::vector<Vec3> colours;      //!< #vertices RGB in [0, 1] from the file, or empty
  std::vector<int> labels;        //!< #vertices label ids from the file, or empty
  std::vector<ChannelArray> channels;        //!< other channels from the file, #vertices values each
  std::vector<FileLabelClass> label_classes; //!< classes the file names, or empty
  ImportReport report;

  std::size_t vertex_count() const { return points.size(); }
  std::size_t face_count() const { return face_sizes.size(); }
  //! Triangles of the faces fanned (a face of n corners gives n - 2).
  std::size_t triangle_count() const;
  //! Length of the bounding-box diagonal.
  double diagonal() const;
};

//! Largest coordinate magnitude accepted: limit normals (cross products of
//! tangents, then their squared length) overflow single precision near 1e19.
constexpr float kMaxCoordinate = 1e15f;

//! Smallest bounding-box diagonal accepted: below it the tangents' cross
//! products at the finest levels underflow single precision, and limit
//! normals become zero (1e-22 across already at level 3).
constexpr double kMinDiagonal = 1e-12;

//! Builds a base mesh from points and faces, checking and repairing as
//! load_mesh does.
//! Faces with fewer than three distinct vertices are dropped and counted.
//! \throw InputError naming the first problem (no faces, non-finite
//! coordinate or one beyond kMaxCoordinate, index out of range).
BaseMesh make_base_mesh(std::vector<Vec3> points, const std::vector<std::vector<int>>& faces,
                        const std::string& name = "mesh", const std::vector<Vec3>& colours = {});

//! The checked reading every mesh file goes through, without the import
//! steps: the census first (take_census(); text OFF through
//! read_off_text()), then OpenMesh's readers; vertices and faces as listed.
//! \throw IOError when the file is missing or unreadable.
//! \throw InputError, one line naming the file (and the line where there
//! is one), when the format is unknown or the file is malformed, truncated,
//! non-finite, or disagrees with its header.
PolygonSoup read_mesh_file(const std::string& path);

//! How load_mesh() imports.
struct ImportOptions
{
  bool weld = true; //!< merge coincident vertices (--no-weld keeps them)
  std::vector<ArrayImport> arrays; //!< --import-array NAME:CHANNEL, in the order given
};

//! Reads OBJ, OFF, PLY or STL through read_mesh_file(), then the import steps of import_soup() and the checks and repairs of
//! make_base_mesh(). Vertex or face colours become `colours`, an integer
//! vertex property named as label_array_names() says `labels`, and PLY
//! properties named as channels, or as `options.arrays` says, the channels
//! take_channel_arrays() chooses.
//! \throw IOError when the file is missing or unreadable.
//! \throw InputError when the format is unknown or the file is malformed,
//! truncated, or disagrees with its header, or the mesh is unusable, or an
//! array for a channel is missing or out of range.
BaseMesh load_mesh(const std::string& path, const ImportOptions& options = {});

//! The import steps and checks of load_mesh() for polygons read elsewhere
//! (VTK's readers in vis/); messages start with `where`.
//! \throw InputError when the mesh is unusable.
BaseMesh import_mesh(PolygonSoup soup, const std::string& name, const std::string& where,
                     const ImportOptions& options = {});

//! File extensions load_mesh reads, lower case with the dot.
const std::vector<std::string>& readable_mesh_extensions();

} // namespace meshpaint
