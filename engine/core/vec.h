// Plain value types for host-side geometry, and the few operations on them
// that the host needs (brush frames, fitting). Each is written in one order
// of operations, so results do not depend on which caller computes them.
#pragma once

#include <array> // for std::array
#include <cmath> // for std::sqrt

namespace meshpaint {

using Vec3 = std::array<float, 3>;
//! One atlas texel as the device stores it (xyz, w unused).
using Float4 = std::array<float, 4>;

inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline float dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline float length(const Vec3& a) { return std::sqrt(dot(a, a)); }
//! a / |a|; not finite for a zero vector.
inline Vec3 normalized(const Vec3& a)
{
  const float l = length(a);
  return {a[0] / l, a[1] / l, a[2] / l};
}

} // namespace meshpaint
