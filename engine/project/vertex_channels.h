// One paint channel per welded vertex: how scripts (Python, numpy) read and
// write the channel layers without knowing the atlas.
#pragma once

#include "paint/paint_surface.h"

#include <string> // for std::string
#include <vector> // for std::vector

namespace meshpaint {

//! Components of a channel: diffuse and specular 3; roughness,
//! displacement, label and mask 1.
//! \throw InputError for another name, listing the names.
int channel_components(const std::string& name);

//! The channel at every vertex of the welded painting level (the vertices of
//! painted_surface()), vertex after vertex, `channel_components` values each.
//! \throw InputError for an unknown name.
std::vector<float> vertex_channel(PaintSurface& surface, const std::string& name);

//! Sets the channel at every welded vertex (every stored copy of it). Not a
//! stroke: no undo step, no history entry. Labels are rounded to integers.
//! \throw InputError for an unknown name or a count that is not vertices x
//! components.
void set_vertex_channel(PaintSurface& surface, const std::string& name, const std::vector<float>& values);

} // namespace meshpaint
