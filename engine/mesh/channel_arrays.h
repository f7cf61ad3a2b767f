// The paint channels as a mesh file carries them: their names, components
// and value ranges, the numeric vertex arrays a file holds, and which of
// those become which channel (by their name, or as --import-array says).
#pragma once

#include <cstddef> // for std::size_t
#include <string>  // for std::string
#include <vector>  // for std::vector

namespace meshpaint {

struct PolygonSoup;

//! Largest label id: the label channel stores floats, exact up to 2^24.
constexpr int kMaxLabelId = 1 << 24;

//! Components of a paint channel: diffuse and specular 3; roughness,
//! displacement, label and mask 1; 0 for any other name.
int channel_component_count(const std::string& name);

//! The channel names, comma-separated, for messages.
const std::string& channel_name_list();

//! Why `value` cannot be a value of the named channel (diffuse, specular,
//! roughness, mask: 0 to 1; displacement: finite, at most kMaxCoordinate in
//! magnitude; label: an integer 0..kMaxLabelId), or "" when it can.
std::string channel_value_problem(const std::string& channel, float value);

//! A numeric vertex array as a file holds it: a PLY property (or three
//! named NAME_r, NAME_g, NAME_b or NAME_x, NAME_y, NAME_z, joined as NAME),
//! a VTK point array.
struct VertexArray
{
  std::string name;
  int components = 1;
  bool integer = false;       //!< stored as integers in the file
  std::vector<double> values; //!< #vertices x components
};

//! A vertex array taken as a paint channel other than diffuse and label
//! (those travel as PolygonSoup::colours and labels).
struct ChannelArray
{
  std::string array;         //!< the file's name for it
  std::string channel;       //!< specular, roughness, displacement or mask
  int components = 1;        //!< channel_component_count(channel)
  std::vector<float> values; //!< #vertices x components
};

//! One `--import-array NAME:CHANNEL`.
struct ArrayImport
{
  std::string array;
  std::string channel;
};

//! Parses NAME:CHANNEL (split at the last colon).
//! \throw InputError when either part is empty or the channel is unknown.
ArrayImport parse_array_import(const std::string& text);

//! Joins PLY-style component properties (NAME_r, NAME_g, NAME_b or NAME_x,
//! NAME_y, NAME_z) into 3-component arrays named NAME, kept beside them.
void join_component_arrays(std::vector<VertexArray>& arrays);

//! Chooses which of `soup.arrays` become channels: first each of
//! `requested`, then every array named as a channel (but label, which
//! label_array_names() governs) that `requested` does not fill already.
//! A diffuse array becomes `colours` (over the file's byte colours), a
//! label array `labels`, the others `channels`; `arrays` is emptied.
//! Messages start with `where`.
//! \throw InputError when a requested array is missing or has the wrong
//! number of components, a channel is requested twice, or a chosen array
//! holds a value outside its channel's range (naming the array and vertex).
void take_channel_arrays(PolygonSoup& soup, const std::vector<ArrayImport>& requested, const std::string& where);

//! Empty arrays named as `arrays` are, for append_vertex().
std::vector<ChannelArray> without_values(const std::vector<ChannelArray>& arrays);

//! Appends vertex `v` of each of `from` to the matching array of `to`
//! (`to` may be `from`: a vertex copied).
void append_vertex(std::vector<ChannelArray>& to, const std::vector<ChannelArray>& from, std::size_t v);

} // namespace meshpaint
