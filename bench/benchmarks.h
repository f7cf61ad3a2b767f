// The benchmarks of meshpaint-bench, one file each.
#pragma once

#include "command_support.h"

namespace meshpaint::cli {

//! bench subdivide: the atlas kernels against OpenSubdiv's evaluators.
int bench_subdivide(const Args& args);
//! bench paint: brush steps as the paper's Table 1, smoothing against VTK
//! and OpenMesh, multiresolution edits.
int bench_paint(const Args& args);
//! bench view: the window's frame times while painting.
int bench_view(const Args& args);
//! bench view --studio: the studio's own frame times while painting.
int bench_view_studio(const Args& args);
//! bench fit: `meshpaint fit`'s time, peak memory and error on every scan and
//! against scan size; its decimation against VTK's and CGAL's.
int bench_fit(const Args& args);

} // namespace meshpaint::cli
