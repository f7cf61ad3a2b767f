// Polygons as a file lists them, before import joins and orients them: the
// common form every reader produces.
#pragma once

#include "core/vec.h"
#include "mesh/channel_arrays.h"

#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint {

//! A label class a file names (VTK field data label_ids, label_names,
//! label_colors, as meshpaint writes them).
struct FileLabelClass
{
  int id = 0;
  std::string name;
  Vec3 colour{0, 0, 0}; //!< RGB 0 to 1
};

//! Points, faces and optional colours exactly as read; nothing checked
//! beyond what the reader itself guarantees (finite numbers, indices in range).
struct PolygonSoup
{
  std::vector<Vec3> points;             //!< #vertices
  std::vector<std::vector<int>> faces;  //!< #faces, vertex indices each
  std::vector<Vec3> colours;            //!< #vertices RGB in [0, 1], or empty
  std::vector<Vec3> face_colours;       //!< #faces RGB in [0, 1], or empty
  std::vector<int> labels;              //!< #vertices label ids from the file, or empty
  std::string label_array;              //!< the file's name for `labels` (label_array_names(), --import-array)
  std::string colour_array;             //!< the file's array that gave `colours`, empty for its byte colours
  std::vector<VertexArray> arrays;      //!< the file's numeric vertex arrays, until take_channel_arrays()
  std::vector<ChannelArray> channels;   //!< arrays taken as specular, roughness, displacement or mask
  std::vector<FileLabelClass> label_classes; //!< classes the file names, or empty
  std::size_t faces_skipped = 0;        //!< OBJ faces the reader could not use (repeated vertices)
};

//! Names of an integer vertex property (PLY) or point array (VTK) taken as
//! the label channel, in the order they are looked for.
const std::vector<std::string>& label_array_names();

//! Checks label ids read from a file (0..kMaxLabelId); `where` starts the
//! message. \throw InputError naming the first vertex outside.
void check_label_ids(const std::vector<int>& labels, const std::string& where);

//! Per-vertex colours from face colours where the file gave only those:
//! each vertex takes the mean of its faces' colours.
void colours_from_faces(PolygonSoup& soup);

//! Length of the bounding-box diagonal of `points` (at least one).
double diagonal_of(const std::vector<Vec3>& points);

} // namespace meshpaint
