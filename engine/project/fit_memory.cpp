#include "project/fit_memory.h"

#include <algorithm> // for std::min

namespace meshpaint {
namespace {

// Measured peaks of `meshpaint fit` at level 3 on the noisy femur series of
// `meshpaint bench fit`, 124,768 to 7,985,152 triangles, fitted as
// fixed + per triangle + per point by least squares (docs/benchmarks.md);
// with the margin, the plan is above every measured peak (291 to 4,258 MiB).
constexpr double kFixedBytes = 246.0 * 1048576;
constexpr double kBytesPerTriangle = 470.0;
constexpr double kBytesPerPoint = 464.0;
constexpr double kMargin = 1.2;

} // namespace

FitMemory plan_fit_memory(std::size_t scan_triangles, std::size_t base_faces, int level)
{
  FitMemory m;
  // fit decimates only a scan larger than its budget
  m.base_faces = std::min(scan_triangles, base_faces);
  // each base triangle becomes 3 patches of 4^(level-1) points
  m.points = 3 * m.base_faces << (2 * (level - 1));
  m.bytes = std::size_t(kMargin * (kFixedBytes + kBytesPerTriangle * double(scan_triangles) +
                                   kBytesPerPoint * double(m.points)));
  return m;
}

} // namespace meshpaint
