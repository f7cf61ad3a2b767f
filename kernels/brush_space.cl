/* Where a texel lies in a dab's brush: the brush spaces (object, tangent,
 * screen, parameter), the falloff profile and the stamp image, shared by the
 * colour brushes (brush.cl) and the geometry brushes (geometry.cl). Rasters
 * (pattern images, stamps) are float buffers of size.w channels per sample. */

/* Sample (x, y, z) of a raster as rgba: one channel is grey and its own
 * alpha, three are rgb with alpha 1. */
inline float4 raster_texel(__global const float *r, int4 size, int x, int y, int z)
{
  __global const float *s = r + ((z * size.y + y) * size.x + x) * size.w;
  if (size.w == 1)
    return (float4)(s[0]);
  return (float4)(s[0], s[1], s[2], size.w == 4 ? s[3] : 1.0f);
}

/* Bilinear (trilinear for depth > 1) at q in [0, 1)^3, sample centres at
 * (i + 0.5) / n; `repeat`: 2D patterns tile the plane, else the border
 * samples extend outwards. */
inline float4 raster_sample(__global const float *r, int4 size, float3 q, int repeat)
{
  const int volume = size.z > 1;
  repeat = repeat && !volume;
  if (repeat)
    q.xy = q.xy - floor(q.xy);
  const float3 g = clamp(q, 0.0f, 1.0f) * convert_float3(size.xyz) - 0.5f;
  const float3 f = floor(g), t = g - f;
  const int3 a = convert_int3(f);
  float4 acc = (float4)(0.0f);
  for (int dz = 0; dz <= volume; ++dz)
    for (int dy = 0; dy <= 1; ++dy)
      for (int dx = 0; dx <= 1; ++dx) {
        int x = a.x + dx, y = a.y + dy;
        if (repeat) {
          x = (x + size.x) % size.x;
          y = (y + size.y) % size.y;
        } else {
          x = clamp(x, 0, size.x - 1);
          y = clamp(y, 0, size.y - 1);
        }
        const int z = clamp(a.z + dz, 0, size.z - 1);
        const float w = (dx ? t.x : 1.0f - t.x) * (dy ? t.y : 1.0f - t.y) * (volume ? (dz ? t.z : 1.0f - t.z) : 1.0f);
        acc += w * raster_texel(r, size, x, y, z);
      }
  return acc;
}

/* Screen coordinates (x / z, y / z) of x and its depth z along the view. */
inline float2 screen_point(__global const BrushDab *dab, float3 x, float *z)
{
  const float3 v = x - vload3(0, dab->eye);
  *z = dot(v, vload3(0, dab->view_dir));
  return (float2)(dot(v, vload3(0, dab->view_right)), dot(v, vload3(0, dab->view_up))) / *z;
}

/* Where texel ij (position x, normal nx) of the a-th listed patch lies in
 * the dab's brush space: returns distance / radius, above 1 outside the
 * brush (also on faces the back-face policy skips), and in `plane` the offset
 * from the centre on the brush plane in world units, where the stamp lies.
 * unfold: the dab's PatchUnfolding per listed patch (parameter space). */
TEXEL_INLINE float brush_t(__global const BrushDab *dab, __global const PatchUnfolding *unfold, int a, float3 x, float3 nx,
                     int2 ij, int n, float2 *plane)
{
  const float3 d = x - vload3(0, dab->centre);
  nx *= dab->side_sign;
  switch (dab->space) {
  case SPACE_SCREEN: {
    if (!dab->paint_backfaces && dot(nx, x - vload3(0, dab->eye)) > 0.0f)
      return INFINITY;
    float z;
    const float2 s = screen_point(dab, x, &z);
    if (!(z > 0.0f))
      return INFINITY;
    *plane = (s - vload2(0, dab->screen_centre)) * dab->centre_depth;
    return sqrt(dot(*plane, *plane)) / dab->radius;
  }
  case SPACE_PARAMETER: {
    /* In the centre patch's texels, through the patch's unfolding: integer
     * maps, and one map for every copy of a side or corner texel, so copies
     * get the same bits. */
    if (a >= dab->unfolded)
      return INFINITY;
    __global const TexelMap *m = &unfold[a].part[tile_part(ij, n)];
    if (!m->valid)
      return INFINITY;
    const int2 at = ij.x * vload2(0, m->u) + ij.y * vload2(0, m->v) + n * vload2(0, m->offset);
    *plane = (convert_float2(at) - vload2(0, dab->centre_texel)) * dab->texel_size;
    return fmax(fabs((*plane).x), fabs((*plane).y)) / dab->radius;
  }
  case SPACE_TANGENT: /* both normals on the side painted: side_sign cancels */
    if (!dab->paint_backfaces && dab->side_sign * dot(nx, vload3(0, dab->centre_normal)) < 0.0f)
      return INFINITY;
    *plane = (float2)(dot(d, vload3(0, dab->stamp_u)), dot(d, vload3(0, dab->stamp_v)));
    return sqrt(dot(*plane, *plane)) / dab->radius;
  default:
    *plane = (float2)(dot(d, vload3(0, dab->stamp_u)), dot(d, vload3(0, dab->stamp_v)));
    return sqrt(dot(d, d)) / dab->radius;
  }
}

/* The normal brush_t needs at a texel: only tangent and screen brushes look
 * at it, so the others skip the load (the branch is the same for every
 * work item of a dab). */
#define BRUSH_NORMAL(dab, nrm, g, p, ij) \
  ((dab)->space == SPACE_TANGENT || (dab)->space == SPACE_SCREEN ? ATLAS_LOAD(nrm, g, p, ij).xyz : (float3)(0.0f))

/* The brush stamp's value at `plane` (brush_t): the image spanning the
 * brush's diameter; 1 without a stamp. */
inline float stamp_weight(__global const BrushDab *dab, __global const float *stamp, float2 plane)
{
  if (dab->stamp_size[0] == 0)
    return 1.0f;
  const float u = 0.5f + 0.5f * plane.x / dab->radius;
  const float v = 0.5f + 0.5f * plane.y / dab->radius;
  if (u < 0.0f || u >= 1.0f || v < 0.0f || v >= 1.0f)
    return 0.0f;
  const int4 size = (int4)(dab->stamp_size[0], dab->stamp_size[1], 1, 1);
  return raster_sample(stamp, size, (float3)(u, v, 0.0f), 0).x;
}

/* exp() of eight values lane by lane: a vector exp need not round as the
 * scalar one does. */
inline float8 exp_lanes(float8 e)
{
  return (float8)(exp(e.s0), exp(e.s1), exp(e.s2), exp(e.s3), exp(e.s4), exp(e.s5), exp(e.s6), exp(e.s7));
}

/* Brush profile at t = distance / radius in [0, 1]: falloff_weight() for a
 * texel, falloff_weight_lanes() for eight, a lane each (lanes.cl), from one
 * text so that both perform the same operations. */
#define DEFINE_FALLOFF_WEIGHT(name, T, EXP)                                     \
  inline T name(int falloff, T t)                                               \
  {                                                                             \
    switch (falloff) {                                                          \
    case FALLOFF_LINEAR: return 1.0f - t;                                       \
    case FALLOFF_SMOOTHSTEP: return 1.0f - t * t * (3.0f - 2.0f * t);           \
    case FALLOFF_GAUSSIAN: return EXP(-4.5f * t * t); /* 3 sigma at the rim */  \
    default: return (T)(1.0f);                                                  \
    }                                                                           \
  }
DEFINE_FALLOFF_WEIGHT(falloff_weight, float, exp)
DEFINE_FALLOFF_WEIGHT(falloff_weight_lanes, float8, exp_lanes)
#undef DEFINE_FALLOFF_WEIGHT
