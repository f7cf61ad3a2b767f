#include "paint/brush_space.h"

#include <cmath> // for std::fabs, std::sqrt, std::tan

namespace meshpaint {

void stamp_axes(const Vec3& n, const Vec3& heading, BrushDab& dab)
{
  const auto project = [&](const Vec3& a) {
    const float k = dot(a, n);
    return Vec3{a[0] - k * n[0], a[1] - k * n[1], a[2] - k * n[2]};
  };
  Vec3 u = project(heading);
  if (dot(u, u) < 1e-12f) {
    const int axis = std::fabs(n[0]) <= std::fabs(n[1]) && std::fabs(n[0]) <= std::fabs(n[2]) ? 0
                     : std::fabs(n[1]) <= std::fabs(n[2])                                  ? 1
                                                                                            : 2;
    Vec3 e{0.f, 0.f, 0.f};
    e[axis] = 1.f;
    u = project(e);
  }
  u = normalized(u);
  const Vec3 v = cross(n, u);
  for (int k = 0; k < 3; ++k) {
    dab.stamp_u[k] = u[k];
    dab.stamp_v[k] = v[k];
  }
}

void camera_frame(const Camera& c, BrushDab& dab)
{
  const Vec3 dir = normalized(sub(c.focal_point, c.position)), right = normalized(cross(dir, c.view_up)),
             up = cross(right, dir);
  const Vec3 v = sub(Vec3{dab.centre[0], dab.centre[1], dab.centre[2]}, c.position);
  const float z = dot(v, dir);
  for (int k = 0; k < 3; ++k) {
    dab.eye[k] = c.position[k];
    dab.view_dir[k] = dir[k];
    dab.view_right[k] = right[k];
    dab.view_up[k] = up[k];
  }
  dab.focal = float(1.0 / std::tan(0.5 * double(c.view_angle) * M_PI / 180.0));
  dab.centre_depth = z;
  dab.screen_centre[0] = dot(v, right) / z;
  dab.screen_centre[1] = dot(v, up) / z;
}

bool at_silhouette(const BrushDab& dab, const Vec3& normal)
{
  const Vec3 v = sub(Vec3{dab.centre[0], dab.centre[1], dab.centre[2]}, Vec3{dab.eye[0], dab.eye[1], dab.eye[2]});
  return !(dab.centre_depth > 0.f) || dab.side_sign * dot(normal, v) >= 0.f;
}

bool aim(const PaintState& state, const Brush& brush, const Vec3& normal, const Vec3& heading,
         const CullRecord& closest, BrushDab& dab)
{
  dab.space = brush.space;
  dab.paint_backfaces = brush.paint_backfaces ? 1 : 0;
  for (int k = 0; k < 3; ++k)
    dab.centre_normal[k] = normal[k];
  stamp_axes(normal, heading, dab);
  if (brush.has_camera) {
    camera_frame(brush.camera, dab);
    if (brush.space == SPACE_SCREEN && at_silhouette(dab, normal))
      return false;
  }
  if (brush.space == SPACE_PARAMETER) {
    const LevelLayout l = state.layout();
    cl_float4 bound;
    state.atlas.runtime().queue().enqueueReadBuffer(state.atlas.limit_bounds(), CL_TRUE,
                                                    sizeof(cl_float4) * closest.patch, sizeof bound, &bound);
    dab.centre_texel[0] = float(closest.closest_texel % l.tile);
    dab.centre_texel[1] = float(closest.closest_texel / l.tile);
    dab.texel_size = float(std::sqrt(2.0) * bound.s[3] / l.n); // the tile's side over its texels
  }
  return true;
}


} // namespace meshpaint
