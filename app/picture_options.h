// The picture options shared by paint and view: --camera az,el,zoom and --size WxH.
#pragma once

#include "args.h"

#include "SurfaceRendering.h" // for meshpaint::CameraView

namespace meshpaint::cli {

struct PictureOptions
{
  CameraView camera;
  int width = 800, height = 600;
};

//! --camera az,el,zoom (degrees, degrees, > 0) and --size WxH (16 to 8192).
//! \throw InputError naming the option when a value does not parse.
PictureOptions picture_options(const Args& args);

} // namespace meshpaint::cli
