// Device memory of painting: what the paint layers add to the atlas, checked
// before anything is allocated.
#pragma once

#include "atlas/atlas_storage.h"
#include "atlas/atlas_topology.h"
#include "cl/runtime.h"

#include <cstddef> // for std::size_t
#include <string>  // for std::string

namespace meshpaint {

class Atlas;

//! Device bytes of an atlas up to `level` with its paint layers: what
//! painting at that level needs.
std::size_t painting_bytes(const AtlasTopology& topology, int level, AtlasStorage storage);
//! painting_bytes() with the multiresolution layers that edits below the
//! painting level add (Multires::device_bytes()) on `device`.
std::size_t coarse_edits_bytes(const AtlasTopology& topology, int level, AtlasStorage storage, const DeviceInfo& device);

//! Refuses a painting level whose paint layers would not fit beside the
//! atlas (which has checked its own), before they are allocated.
//! \throw ResourceError naming the largest level that fits for painting.
void check_paint_fits(Atlas& atlas, int level, const std::string& name);

//! Refuses the first edit below the painting level where the
//! multiresolution layers (Multires::device_bytes()) would not fit beside
//! the atlas and its paint layers, before they are allocated.
//! \throw ResourceError
void check_coarse_edits_fit(const Atlas& atlas);

} // namespace meshpaint
