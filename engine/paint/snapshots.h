// Snapshots of a painting surface's layers: the tiles of some patches taken
// from the device (before a stroke changes them, or for a display that reads
// a few patches), and put back by undo and redo.
#pragma once

#include "cl/opencl.h"
#include "paint/paint_state.h"
#include "paint/undo_log.h"

#include <cstddef> // for std::size_t
#include <utility> // for std::pair
#include <vector>  // for std::vector

namespace meshpaint {

struct LayerKernels; // paint_device.h

//! Layers a snapshot may hold: the finest level's control points, the
//! channel layers, and the control points of a coarser edit level.
enum SnapshotLayer : int
{
  kPositions,
  kDiffuse,
  kSpecular,
  kMaterial,
  kInsideDiffuse,
  kInsideSpecular,
  kInsideMaterial,
  kLimitPositions, // read only (painted_vertices): the limit surface at the painting level
  kLimitNormals,
  kEditPositions // the control points of a snapshot's edit_level
};

//! Layer `id`'s memory, and the kernels built for its storage path.
std::pair<LayerKernels*, const cl::Memory*> snapshot_layer(const PaintState& state, int id, int edit_level = 0);
//! The given layers' tiles of `patches`, from the device, and the state of
//! the multiresolution details.
Snapshot take_snapshot(const PaintState& state, const std::vector<int>& patches, const std::vector<int>& layers,
                       int edit_level = 0);
//! Puts the snapshot's `k`-th layer back on its patches' tiles; `list`
//! holds the patches on the device.
void put_back_layer(const PaintState& state, const Snapshot& snapshot, std::size_t k, const cl::Buffer& list);

} // namespace meshpaint
