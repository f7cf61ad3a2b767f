// Projects (*.meshpaint): everything needed to continue painting, in one
// versioned, checksummed binary file (docs/project-format.md).
#pragma once

#include "mesh/base_mesh.h"
#include "paint/paint_surface.h"
#include "project/labels.h"

#include <cstdint> // for std::uint32_t, std::uint64_t
#include <string>  // for std::string
#include <vector>  // for std::vector

namespace meshpaint {

//! Format version this build writes; it reads every version up to it.
constexpr std::uint32_t kProjectVersion = 1;

//! The scan a project was fitted to: enough to notice when it changed.
struct ScanReference
{
  std::string path;         //!< as given when fitting; empty: no scan
  std::uint64_t bytes = 0;  //!< file size
  std::uint32_t crc32 = 0;  //!< zlib CRC-32 of the whole file
};

//! Which saved file a loaded project came from, so that a save over it can
//! tell whether another run has saved there since (not itself saved).
struct ProjectOrigin
{
  std::string path;            //!< as given to load_project(); empty: not loaded from a file
  std::uint32_t header_crc = 0; //!< the header's own CRC-32 (it covers the payload's)
};

//! The state of a painted surface, as saved.
struct Project
{
  BaseMesh mesh;                 //!< the base mesh in the atlas's (spatial) order
  int level = 0;                 //!< painting level, 1..kMaxLevel
  std::vector<Float4> positions; //!< finest-level control points, patch-major (LevelLayout::index)
  PaintChannels channels;        //!< same shape as positions
  //! Finest-level positions the surface started from (as fitted to its
  //! scan), same shape as positions; empty: the base mesh's subdivision.
  std::vector<Float4> reference;
  std::vector<LabelClass> labels;
  std::string history;           //!< the strokes applied so far, as a stroke script (JSON)
  ScanReference scan;
  ProjectOrigin origin; //!< set by load_project()
};

//! Whether a path names a project (extension .meshpaint, any case).
bool is_project_path(const std::string& path);

//! Writes the project atomically: a crash or kill while saving leaves the
//! previous file as it was.
//! Returns the header CRC-32 written (what ProjectOrigin holds).
//! \throw IOError when the file cannot be written.
std::uint32_t save_project(const Project& project, const std::string& path);

//! Reads and checks a project: magic, version, sizes, CRC-32 of the header
//! and of the payload, and the shape of every section. Nothing is returned
//! unless all of it is consistent.
//! \throw IOError when the file cannot be read; InputError with one line
//! naming the file and the problem (not a project, newer version, truncated,
//! corrupt).
Project load_project(const std::string& path);

//! The header CRC-32 of the project file now at `path` (what ProjectOrigin
//! holds), or 0 when there is none or it is not a readable project header.
std::uint32_t project_header_crc(const std::string& path);

//! Size and CRC-32 of a file, for ScanReference.
//! \throw IOError when it cannot be read.
ScanReference scan_reference(const std::string& path);

} // namespace meshpaint
