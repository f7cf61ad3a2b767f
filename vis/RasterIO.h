// Reading images and voxel arrays for pattern paint and brush stamps.
#ifndef RasterIO_h
#define RasterIO_h

#include "meshpaintVisModule.h" // for MESHPAINTVIS_EXPORT

#include "paint/raster.h" // for meshpaint::Raster
#include "paint/stroke.h" // for meshpaint::StrokeScript

#include <string> // for std::string

namespace meshpaint {

//! PNG, JPEG, TIFF, BMP, PNM (2D) or VTK XML image data .vti (2D or 3D), as
//! floats in 0..1: integer samples divided by their type's maximum, float
//! samples clamped.
//! \throw IOError when the file is missing or unreadable.
MESHPAINTVIS_EXPORT Raster load_raster(const std::string& path);

//! Loads every pattern and stamp file a script names into its strokes.
//! \throw InputError naming the stroke when a file cannot be used.
MESHPAINTVIS_EXPORT void load_stroke_rasters(StrokeScript& script);

} // namespace meshpaint

#endif
