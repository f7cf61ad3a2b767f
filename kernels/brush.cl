/* The brush pipeline of one dab (Ritschel et al. Sec. 5; Hanrahan and
 * Haeberli's paint equation). Positions: the limit surface of the atlas's
 * finest level, in either storage. Paint channels: float4 buffers, patch-major
 * (texel (p, i, j) at (p * tile + j) * tile + i), in both storage modes,
 * because a dab reads and writes them in place.
 *   diffuse, specular: rgb (w unused)
 *   material:          (roughness, displacement, label, mask) */

#define CHANNEL_INDEX(tile, p, ij) (((p) * (tile) + (ij).y) * (tile) + (ij).x)

/* Distance from c to the closest texel of patch p (its tile index in
 * *texel), and in component s of *side to the closest texel on side s (a
 * vector, not an array: PoCL keeps private arrays in memory). */
inline float patch_distances(ATLAS_IN pos, int2 g, int p, float3 c, float4 *side, int *texel)
{
  const int n = g.x - 1;
  float best = INFINITY;
  float4 sides = (float4)(INFINITY);
  *texel = 0;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float d = distance(ATLAS_LOAD(pos, g, p, (int2)(i, j)).xyz, c);
      if (d < best) {
        best = d;
        *texel = j * g.x + i;
      }
      if (j == 0) sides.x = fmin(sides.x, d);
      if (i == n) sides.y = fmin(sides.y, d);
      if (j == n) sides.z = fmin(sides.z, d);
      if (i == 0) sides.w = fmin(sides.w, d);
    }
  *side = sides;
  return best;
}

/* brush_cull (range: #patches; cull_patch() is its work on patch p) finds
 * the texel nearest to `centre` within `radius`, in one pass over the
 * patches: counters[1] holds the nearest distance found
 * so far (float bits, which order as ints for distances >= 0; the host sets
 * it to `radius`), and a patch appends a record of its closest texel when
 * that comes no further than it. The nearest patches are among the records
 * (ties included); the host picks from them. A patch whose bounding sphere
 * lies beyond the nearest distance costs one test: a stale read of it is
 * only larger. counters[0] counts records and may pass `capacity`; the host
 * then grows the record buffer and runs again. */
TEXEL_INLINE void cull_patch(ATLAS_IN pos, ATLAS_IN nrm, int2 g, int p, __global const float4 *bounds, float4 centre,
                             __global CullRecord *records, volatile __global int *counters, int capacity)
{
  const float4 b = bounds[p];
  const float3 d = b.xyz - centre.xyz;
  const float nearest = as_float(counters[1]);
  /* Only a filter: the slack covers its rounding, the texels decide. */
  if (sqrt(dot(d, d)) - b.w > nearest + 1e-5f * (b.w + nearest))
    return;
  CullRecord r;
  float4 side; /* the flood's business (brush_reach), not the snap's */
  r.distance = patch_distances(pos, g, p, centre.xyz, &side, &r.closest_texel);
  if (r.distance > as_float(atomic_min(&counters[1], as_int(r.distance))))
    return;
  const int k = atomic_inc(&counters[0]);
  if (k >= capacity)
    return;
  r.patch = p;
  r.pad = 0;
  const int2 ij = (int2)(r.closest_texel % g.x, r.closest_texel / g.x);
  vstore4(ATLAS_LOAD(pos, g, p, ij), 0, r.closest_position);
  vstore4(ATLAS_LOAD(nrm, g, p, ij), 0, r.closest_normal);
  records[k] = r;
}

__kernel void brush_cull(ATLAS_IN pos, ATLAS_IN nrm, int2 g, int patches, __global const float4 *bounds,
                         float4 centre, __global CullRecord *records, volatile __global int *counters, int capacity)
{
  const int p = get_global_id(0);
  if (p < patches)
    cull_patch(pos, nrm, g, p, bounds, centre, records, counters, capacity);
}

/* Whether sphere b (a cluster's: cluster_bounds()) lies farther than
 * `limit` from c, by a margin beyond the rounding of the tests of the
 * spheres inside it (cull_patch(), reach_patch()) and of c's coordinates. */
inline int cluster_beyond(float4 b, float3 c, float limit)
{
  const float3 a = fabs(c);
  return distance(b.xyz, c) - b.w > limit + 1e-5f * (b.w + limit + max(max(a.x, a.y), a.z));
}

/* The first and the end of cluster c's patches, false past the last. */
inline bool cluster_range(int c, int patches, int *first, int *end)
{
  *first = c * PATCH_CLUSTER;
  *end = min(*first + PATCH_CLUSTER, patches);
  return *first < patches;
}

/* Range: clusters (CPUs). brush_cull a cluster of patches per work item: a
 * cluster whose bound lies beyond the nearest distance so far costs one
 * test. The records are those brush_cull can give (the nearest patches and
 * their ties among them), in another order. */
__kernel void brush_cull_clusters(ATLAS_IN pos, ATLAS_IN nrm, int2 g, int patches, __global const float4 *bounds,
                                  __global const float4 *clusters, float4 centre, __global CullRecord *records,
                                  volatile __global int *counters, int capacity)
{
  int first, end;
  const int c = get_global_id(0);
  if (!cluster_range(c, patches, &first, &end) || cluster_beyond(clusters[c], centre.xyz, as_float(counters[1])))
    return;
  for (int p = first; p < end; ++p)
    cull_patch(pos, nrm, g, p, bounds, centre, records, counters, capacity);
}

/* Range: 1. Lowers brush_cull's starting distance (counters[1]) to that of
 * texel `texel` of patch `p`, a texel the host expects near `centre` (the
 * previous dab's centre, or the picked one). Any texel gives brush_cull the
 * same records to choose from: the nearest is no further than this one, so
 * it and its ties still append. The distance is patch_distances' own, plus
 * a few units in the last place so that no rounding can leave it short. */
__kernel void brush_cull_seed(ATLAS_IN pos, int2 g, int p, int texel, float4 centre, volatile __global int *counters)
{
  if (get_global_id(0) != 0)
    return;
  const float d = distance(ATLAS_LOAD(pos, g, p, (int2)(texel % g.x, texel / g.x)).xyz, centre.xyz);
  atomic_min(&counters[1], as_int(d) + 4);
}

/* Range: 1. The record the host will snap the brush to (the nearest,
 * ties to the lowest patch: the host's test, in the host's order), so
 * that brush_reach can run before the host has read the records. `snap`:
 * its closest position; `chosen`: its index, -1 without records. */
__kernel void brush_snap(__global const CullRecord *records, __global const int *counters, int capacity,
                         __global float4 *snap, __global int *chosen)
{
  const int n = min(counters[0], capacity);
  int best = -1;
  for (int k = 0; k < n; ++k)
    if (best < 0 || records[k].distance < records[best].distance ||
        (records[k].distance == records[best].distance && records[k].patch < records[best].patch))
      best = k;
  *chosen = best;
  if (best >= 0)
    *snap = vload4(0, records[best].closest_position);
}

/* brush_reach (range: #patches; reach_patch() is its work on patch p).
 * Per patch, in `open`: the sides that come within
 * `reach` of `*at` (bits 0-3) when a texel of it does, else
 * REACH_NONE; from these the host finds the patches connected to the
 * centre along the surface. A patch whose bounding sphere lies inside the
 * ball has all four sides open without a look at its texels. A byte per
 * patch rather than appended records: a big brush reaches most of the
 * atlas, and appending made both cores take turns on one counter. */
TEXEL_INLINE uchar reach_patch(ATLAS_IN pos, int2 g, int p, __global const float4 *bounds, float4 centre, float reach)
{
  const float4 b = bounds[p];
  const float to_sphere = distance(b.xyz, centre.xyz);
  uchar sides = REACH_NONE;
  if (to_sphere + b.w <= reach) {
    sides = 15;
  } else if (!(to_sphere - b.w > reach)) {
    float4 side;
    int texel;
    if (!(patch_distances(pos, g, p, centre.xyz, &side, &texel) > reach)) {
      const int4 in = -(side <= (float4)(reach)); /* a vector compare gives -1 for true */
      sides = (uchar)(in.x | in.y << 1 | in.z << 2 | in.w << 3);
    }
  }
  return sides;
}

__kernel void brush_reach(ATLAS_IN pos, int2 g, int patches, __global const float4 *bounds,
                          __global const float4 *at, float reach, __global uchar *open)
{
  const int p = get_global_id(0);
  if (p < patches)
    open[p] = reach_patch(pos, g, p, bounds, *at, reach);
}

/* Range: clusters (CPUs). brush_reach a cluster of patches per work item:
 * every patch of a cluster whose bound lies beyond the reach gets
 * REACH_NONE at once, as each would from its own sphere. */
__kernel void brush_reach_clusters(ATLAS_IN pos, int2 g, int patches, __global const float4 *bounds,
                                   __global const float4 *clusters, __global const float4 *at, float reach,
                                   __global uchar *open)
{
  int first, end;
  if (!cluster_range(get_global_id(0), patches, &first, &end))
    return;
  const float4 centre = *at;
  if (cluster_beyond(clusters[get_global_id(0)], centre.xyz, reach)) {
    for (int p = first; p < end; ++p)
      open[p] = REACH_NONE;
    return;
  }
  for (int p = first; p < end; ++p)
    open[p] = reach_patch(pos, g, p, bounds, centre, reach);
}

/* Gradient noise in [-1, 1] from an integer hash: no tables to upload. */
inline uint hash3(int3 c)
{
  uint h = (uint)c.x * 0x8da6b343u ^ (uint)c.y * 0xd8163841u ^ (uint)c.z * 0xcb1ab31fu;
  h ^= h >> 15;
  h *= 0x2c1b3c6du;
  h ^= h >> 12;
  return h;
}

inline float grad_dot(int3 c, float3 d)
{
  const uint h = hash3(c) & 15u; /* one of 12 edge directions (4 repeated) */
  const float u = h < 8u ? d.x : d.y, v = h < 4u ? d.y : (h == 12u || h == 14u ? d.x : d.z);
  return ((h & 1u) ? -u : u) + ((h & 2u) ? -v : v);
}

inline float gradient_noise(float3 p)
{
  const float3 f = floor(p), d = p - f;
  const int3 c = convert_int3(f);
  const float3 s = d * d * d * (d * (d * 6.0f - 15.0f) + 10.0f);
  float n[2][2][2];
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x)
        n[z][y][x] = grad_dot(c + (int3)(x, y, z), d - (float3)((float)x, (float)y, (float)z));
  const float x00 = mix(n[0][0][0], n[0][0][1], s.x), x10 = mix(n[0][1][0], n[0][1][1], s.x);
  const float x01 = mix(n[1][0][0], n[1][0][1], s.x), x11 = mix(n[1][1][0], n[1][1][1], s.x);
  return clamp(mix(mix(x00, x10, s.y), mix(x01, x11, s.y), s.z), -1.0f, 1.0f);
}

inline float turbulence(float3 p, int octaves)
{
  float sum = 0.0f, amplitude = 1.0f, norm = 0.0f;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * fabs(gradient_noise(p));
    norm += amplitude;
    amplitude *= 0.5f;
    p *= 2.0f;
  }
  return sum / norm;
}

/* The pattern at pattern-space point q: rgb shades the pigment (opaque
 * matte), w is the matte (self matte). Procedural patterns are grey. */
inline float4 pattern_sample(__global const BrushDab *dab, __global const float *raster, float3 q)
{
  switch (dab->pattern) {
  case PATTERN_NOISE: return (float4)(0.5f + 0.5f * gradient_noise(q));
  case PATTERN_TURBULENCE: return (float4)(turbulence(q, dab->octaves));
  case PATTERN_MARBLE: return (float4)(0.5f + 0.5f * sin(6.2831853f * (q.x + 2.0f * turbulence(q, dab->octaves))));
  case PATTERN_BATH: return (float4)(clamp(0.5f - q.z, 0.0f, 1.0f));
  case PATTERN_IMAGE:
  case PATTERN_VOLUME: {
    const int4 size = vload4(0, dab->raster_size);
    const float4 s = raster_sample(raster, size, q, 1);
    /* an rgb image mattes by its luminance */
    return size.w == 3 ? (float4)(s.xyz, dot(s.xyz, (float3)(0.2126f, 0.7152f, 0.0722f))) : s;
  }
  default: return (float4)(1.0f);
  }
}

/* Where texel (i, j) of a patch sits in pattern space. */
inline float3 pattern_point(__global const BrushDab *dab, float3 x, int2 ij, int n)
{
  float3 c = x;
  if (dab->pattern_coord == PATTERN_COORD_UV) {
    c = (float3)((float)ij.x / n, (float)ij.y / n, 0.0f);
  } else if (dab->pattern_coord == PATTERN_COORD_SCREEN) {
    float z;
    c = (float3)(dab->focal * screen_point(dab, x, &z), 0.0f);
  }
  __global const float *m = dab->pattern_transform;
  return (float3)(m[0] * c.x + m[1] * c.y + m[2] * c.z + m[3], m[4] * c.x + m[5] * c.y + m[6] * c.z + m[7],
                  m[8] * c.x + m[9] * c.y + m[10] * c.z + m[11]);
}

/* paint OP surface, per component: paint_op() for a texel's float4,
 * paint_op_lanes() for a component of eight texels (paint_patches), from
 * one text so that both perform the same operations. */
#define DEFINE_PAINT_OP(name, T, Coverage)                                                                   \
  inline T name(int op, T paint, Coverage coverage, T surface)                                                         \
  {                                                                                                                    \
    switch (op) {                                                                                                      \
    case PAINT_OP_OVER: return paint * coverage + surface * (1.0f - coverage);                                         \
    case PAINT_OP_MAX: return fmax(paint, surface);                                                                    \
    case PAINT_OP_ADD: return surface + paint;                                                                         \
    case PAINT_OP_SUBTRACT: return surface - paint;                                                                    \
    default: return paint;                                                                                             \
    }                                                                                                                  \
  }
DEFINE_PAINT_OP(paint_op, float4, float)
DEFINE_PAINT_OP(paint_op_lanes, float8, float8)
#undef DEFINE_PAINT_OP

/* surface = lerp(surface, paint OP surface, a): the paint equation, with
 * paint = pigment in pattern: an opaque matte shades the pigment by the
 * pattern value `shade`, a self matte is folded into `a` by the caller. */
inline float4 paint_blend(__global const BrushDab *dab, int c, float4 surface, float a, float3 shade)
{
  float4 paint = vload4(0, dab->value[c]);
  paint.xyz *= shade;
  return mix(surface, paint_op(dab->op, paint, paint.w, surface), a);
}

/* Whether a dab may overwrite class `label`: not locked (locked: the
 * dab's list of locked classes), and the chosen class if one is. */
inline int label_open(__global const BrushDab *dab, __global const int *locked, float label)
{
  if (dab->only_over_label >= 0 && label != (float)dab->only_over_label)
    return 0;
  for (int k = 0; k < dab->locked_labels; ++k)
    if (label == (float)locked[k])
      return 0;
  return 1;
}

/* The arguments of paint_dab and paint_patches. */
#define PAINT_DAB_ARGUMENTS                                                                                            \
  ATLAS_IN pos, ATLAS_IN nrm, int2 g, __global const int *restrict active, int active_count,                           \
    __global const BrushDab *restrict dab, __global const PatchUnfolding *restrict unfold,                             \
    __global const float *restrict raster, __global const float *restrict stamp, __global float4 *restrict diffuse,    \
    __global float4 *restrict specular, __global float4 *restrict material, __global const int *restrict locked

/* Range: (tile, tile * #active). Every texel of the active patches, all
 * stored copies included, so copies stay identical. unfold: a parameter
 * dab's maps, one per active patch (dab->unfolded; one unused entry for the
 * other spaces). */
__kernel void paint_dab(PAINT_DAB_ARGUMENTS)
{
  const int i = get_global_id(0), y = get_global_id(1);
  const int a = y / g.x, j = y - a * g.x;
  if (a >= active_count)
    return;
  const int p = active[a];
  const int2 ij = (int2)(i, j);
  const float3 x = ATLAS_LOAD(pos, g, p, ij).xyz;
  float2 plane;
  const float t = brush_t(dab, unfold, a, x, BRUSH_NORMAL(dab, nrm, g, p, ij), ij, g.x - 1, &plane);
  if (!(t <= 1.0f))
    return;
  const int k = CHANNEL_INDEX(g.x, p, ij);
  float4 m = material[k];
  float w = falloff_weight(dab->falloff, t) * dab->strength * (1.0f - m.w) * stamp_weight(dab, stamp, plane);
  float3 shade = (float3)(1.0f);
  if (dab->pattern != PATTERN_NONE) {
    const float4 v = pattern_sample(dab, raster, pattern_point(dab, x, ij, g.x - 1));
    if (dab->matte == MATTE_SELF)
      w *= v.w;
    else
      shade = v.xyz;
  }
  if (dab->alpha[CHANNEL_DIFFUSE] > 0.0f)
    diffuse[k] = clamp(paint_blend(dab, CHANNEL_DIFFUSE, diffuse[k], w * dab->alpha[CHANNEL_DIFFUSE], shade), 0.0f, 1.0f);
  if (dab->alpha[CHANNEL_SPECULAR] > 0.0f) {
    const float4 s = specular[k];
    float4 target = vload4(0, dab->value[CHANNEL_SPECULAR]);
    if (dab->specular_coefficient >= 0.0f) /* polish, sandpaper: the coefficient, not the hue */
    {
      const float top = fmax(s.x, fmax(s.y, s.z));
      target.xyz = top > 1e-6f ? s.xyz * (dab->specular_coefficient / top) : (float3)(dab->specular_coefficient);
    }
    specular[k] = clamp(mix(s, paint_op(dab->op, (float4)(target.xyz * shade, target.w), target.w, s),
                            w * dab->alpha[CHANNEL_SPECULAR]), 0.0f, 1.0f);
  }
  if (dab->alpha[CHANNEL_ROUGHNESS] > 0.0f)
    m.x = clamp(paint_blend(dab, CHANNEL_ROUGHNESS, (float4)(m.x), w * dab->alpha[CHANNEL_ROUGHNESS], shade).x, 0.0f, 1.0f);
  if (dab->alpha[CHANNEL_DISPLACEMENT] > 0.0f)
    m.y = paint_blend(dab, CHANNEL_DISPLACEMENT, (float4)(m.y), w * dab->alpha[CHANNEL_DISPLACEMENT], shade).x;
  /* Labels are class ids: they are set, never blended, and only where
   * the class there is open to the dab. */
  if (dab->alpha[CHANNEL_LABEL] > 0.0f && w * dab->alpha[CHANNEL_LABEL] >= 0.5f && label_open(dab, locked, m.z))
    m.z = dab->value[CHANNEL_LABEL][0];
  /* The mask protects the other channels, so it is painted without itself. */
  if (dab->alpha[CHANNEL_MASK] > 0.0f) {
    const float wm = falloff_weight(dab->falloff, t) * dab->strength * dab->alpha[CHANNEL_MASK];
    m.w = clamp(paint_blend(dab, CHANNEL_MASK, (float4)(m.w), wm, (float3)(1.0f)).x, 0.0f, 1.0f);
  }
  material[k] = m;
}

/* label_open() lane by lane (lanes.cl). */
inline int8 labels_open(__global const BrushDab *dab, __global const int *locked, float8 label)
{
  int8 open = (int8)(-1);
  if (dab->only_over_label >= 0)
    open = label == (float8)((float)dab->only_over_label);
  for (int k = 0; k < dab->locked_labels; ++k)
    open &= label != (float8)((float)locked[k]);
  return open;
}

/* paint_blend() of component c of channel `channel`, a lane per texel,
 * without a pattern (its shade of 1 changes no bits). */
inline float8 paint_blend_lanes(__global const BrushDab *dab, int channel, int c, float8 surface, float8 a)
{
  const float8 paint = (float8)(dab->value[channel][c]), coverage = (float8)(dab->value[channel][3]);
  return mix(surface, paint_op_lanes(dab->op, paint, coverage, surface), a);
}

/* paint_dab for eight listed patches per work item, a patch per lane
 * (CPU devices: Atlas::tile_launch()), for the dabs that need neither a
 * brush normal nor a raster: object space, no pattern, no stamp
 * (paint_patches_fits() on the host). Each lane performs paint_dab's
 * operations in their order, so the channels get the same bits; a texel
 * outside the brush keeps its value, and lanes past the end repeat the last
 * patch, whose texels then get the same values twice. Range: active_count
 * / PATCH_LANES rounded up. */
__kernel void paint_patches(PAINT_DAB_ARGUMENTS)
{
  const int first = get_global_id(0) * PATCH_LANES;
  if (first >= active_count)
    return;
  const int8 at = min(first + (int8)(0, 1, 2, 3, 4, 5, 6, 7), (int8)(active_count - 1));
  const int8 patch = (int8)(active[at.s0], active[at.s1], active[at.s2], active[at.s3], active[at.s4],
                            active[at.s5], active[at.s6], active[at.s7]);
  const float3 centre = vload3(0, dab->centre);
  const float radius = dab->radius, strength = dab->strength;
  const float4 alpha = (float4)(dab->alpha[CHANNEL_DIFFUSE], dab->alpha[CHANNEL_SPECULAR],
                                dab->alpha[CHANNEL_ROUGHNESS], dab->alpha[CHANNEL_DISPLACEMENT]);
  const float alpha_label = dab->alpha[CHANNEL_LABEL], alpha_mask = dab->alpha[CHANNEL_MASK];
  for (int j = 0; j < g.x; ++j)
    for (int i = 0; i < g.x; ++i) {
      const int2 ij = (int2)(i, j);
      Lanes d = load_lanes(pos, g, patch, ij);
      d.x -= centre.x;
      d.y -= centre.y;
      d.z -= centre.z;
      const float8 t = sqrt(lanes_dot(d, d)) / radius; /* brush_t(), object space */
      const int8 inside = t <= 1.0f;
      if (!any(inside))
        continue;
      const float8 falloff = falloff_weight_lanes(dab->falloff, t);
      const Lanes4 m = load_lanes4(material, g, patch, ij);
      const float8 w = falloff * strength * (1.0f - m.w);
      if (alpha.x > 0.0f) {
        const Lanes4 c = load_lanes4(diffuse, g, patch, ij);
        const float8 a = w * alpha.x;
        store_lanes4(diffuse, g, patch, ij,
                     select(c.x, clamp(paint_blend_lanes(dab, CHANNEL_DIFFUSE, 0, c.x, a), 0.0f, 1.0f), inside),
                     select(c.y, clamp(paint_blend_lanes(dab, CHANNEL_DIFFUSE, 1, c.y, a), 0.0f, 1.0f), inside),
                     select(c.z, clamp(paint_blend_lanes(dab, CHANNEL_DIFFUSE, 2, c.z, a), 0.0f, 1.0f), inside),
                     select(c.w, clamp(paint_blend_lanes(dab, CHANNEL_DIFFUSE, 3, c.w, a), 0.0f, 1.0f), inside));
      }
      if (alpha.y > 0.0f) {
        const Lanes4 s = load_lanes4(specular, g, patch, ij);
        __global const float *v = dab->value[CHANNEL_SPECULAR];
        float8 tx = (float8)(v[0]), ty = (float8)(v[1]), tz = (float8)(v[2]);
        const float8 tw = (float8)(v[3]);
        const float k = dab->specular_coefficient;
        if (k >= 0.0f) {
          const float8 top = fmax(s.x, fmax(s.y, s.z));
          const int8 hue = top > 1e-6f;
          const float8 scale = k / top;
          tx = select((float8)(k), s.x * scale, hue);
          ty = select((float8)(k), s.y * scale, hue);
          tz = select((float8)(k), s.z * scale, hue);
        }
        const float8 a = w * alpha.y;
        store_lanes4(specular, g, patch, ij,
                     select(s.x, clamp(mix(s.x, paint_op_lanes(dab->op, tx, tw, s.x), a), 0.0f, 1.0f), inside),
                     select(s.y, clamp(mix(s.y, paint_op_lanes(dab->op, ty, tw, s.y), a), 0.0f, 1.0f), inside),
                     select(s.z, clamp(mix(s.z, paint_op_lanes(dab->op, tz, tw, s.z), a), 0.0f, 1.0f), inside),
                     select(s.w, clamp(mix(s.w, paint_op_lanes(dab->op, tw, tw, s.w), a), 0.0f, 1.0f), inside));
      }
      float8 rough = m.x, shift = m.y, label = m.z, mask = m.w;
      if (alpha.z > 0.0f)
        rough = clamp(paint_blend_lanes(dab, CHANNEL_ROUGHNESS, 0, rough, w * alpha.z), 0.0f, 1.0f);
      if (alpha.w > 0.0f)
        shift = paint_blend_lanes(dab, CHANNEL_DISPLACEMENT, 0, shift, w * alpha.w);
      if (alpha_label > 0.0f)
        label = select(label, (float8)(dab->value[CHANNEL_LABEL][0]),
                       (w * alpha_label >= 0.5f) & labels_open(dab, locked, label));
      if (alpha_mask > 0.0f)
        mask = clamp(paint_blend_lanes(dab, CHANNEL_MASK, 0, mask, falloff * strength * alpha_mask), 0.0f, 1.0f);
      store_lanes4(material, g, patch, ij, select(m.x, rough, inside), select(m.y, shift, inside),
                   select(m.z, label, inside), select(m.w, mask, inside));
    }
}

#undef PAINT_DAB_ARGUMENTS

/* Range: count * tile^2 work items in groups of `get_local_size(0)`, one per
 * texel of the listed patches. Per work group: the weighted sums of diffuse
 * and specular under the dab and of the weights, for the smear brush's
 * pickup. partial: 3 float4 per group (diffuse * w, specular * w,
 * (w, 0, 0, 0)). unfold: as for paint_dab, one per listed patch. */
__kernel void dab_pickup(ATLAS_IN pos, ATLAS_IN nrm, int2 g, __global const int *list, int count,
                         __global const BrushDab *dab, __global const PatchUnfolding *unfold,
                         __global const float *stamp, __global const float4 *diffuse,
                         __global const float4 *specular, __global float4 *partial, __local float4 *scratch)
{
  const int id = get_global_id(0), local_id = get_local_id(0), items = get_local_size(0);
  const int tile_texels = g.x * g.x, a = id / tile_texels, r = id - a * tile_texels;
  float4 d = (float4)(0.0f), s = (float4)(0.0f);
  float w = 0.0f;
  if (a < count) {
    const int p = list[a];
    const int2 ij = (int2)(r % g.x, r / g.x);
    const float3 x = ATLAS_LOAD(pos, g, p, ij).xyz;
    float2 plane;
    const float t = brush_t(dab, unfold, a, x, BRUSH_NORMAL(dab, nrm, g, p, ij), ij, g.x - 1, &plane);
    if (t <= 1.0f) {
      const int k = CHANNEL_INDEX(g.x, p, ij);
      w = falloff_weight(dab->falloff, t) * stamp_weight(dab, stamp, plane);
      d = w * diffuse[k];
      s = w * specular[k];
    }
  }
  __local float4 *ds = scratch, *ss = scratch + items, *ws = scratch + 2 * items;
  ds[local_id] = d;
  ss[local_id] = s;
  ws[local_id] = (float4)(w, 0.0f, 0.0f, 0.0f);
  barrier(CLK_LOCAL_MEM_FENCE);
  if (local_id == 0) {
    /* In order, so the result does not depend on scheduling. */
    float4 sa = (float4)(0.0f), sb = (float4)(0.0f), sc = (float4)(0.0f);
    for (int k = 0; k < items; ++k) {
      sa += ds[k];
      sb += ss[k];
      sc += ws[k];
    }
    const int group = get_group_id(0);
    partial[3 * group] = sa;
    partial[3 * group + 1] = sb;
    partial[3 * group + 2] = sc;
  }
}

/* Spray paint (Hanrahan and Haeberli): droplets at random points of the
 * brush's disc on the screen, each landing on the nearest surface seen
 * there. Three passes over the texels of the listed patches, front-facing
 * ones within a texel's width of a droplet's screen point (drops: screen
 * x / z, y / z): the least depth per droplet, then the least texel index at
 * that depth, then its position (w = 1; 0 where the droplet hit nothing). */
inline int spray_candidate(ATLAS_IN pos, ATLAS_IN nrm, int2 g, __global const BrushDab *dab,
                           __global const float4 *bounds, int p, int2 ij, float2 drop, float *depth)
{
  const float3 x = ATLAS_LOAD(pos, g, p, ij).xyz;
  if (dab->side_sign * dot(ATLAS_LOAD(nrm, g, p, ij).xyz, x - vload3(0, dab->eye)) > 0.0f)
    return 0;
  const float2 s = screen_point(dab, x, depth);
  const float reach = 1.5f * M_SQRT2_F * bounds[p].w / (float)(g.x - 1); /* about a texel */
  return *depth > 0.0f && distance(s, drop) * *depth <= reach;
}

/* Range: (tile, tile * count). Pass 0: in keys (one per droplet, preset
 * to UINT_MAX) the least depth; pass 1: in texels (preset to INT_MAX) the
 * least texel index at that depth. */
__kernel void spray_pick(ATLAS_IN pos, ATLAS_IN nrm, int2 g, __global const int *list, int count,
                         __global const BrushDab *dab, __global const float4 *bounds, __global const float2 *drops,
                         int drop_count, int pass, __global uint *keys, __global int *texels)
{
  int p;
  int2 ij;
  if (!tile_texel(g, list, count, &p, &ij))
    return;
  for (int k = 0; k < drop_count; ++k) {
    float z;
    if (!spray_candidate(pos, nrm, g, dab, bounds, p, ij, drops[k], &z))
      continue;
    if (pass == 0)
      atomic_min(&keys[k], as_uint(z)); /* positive floats order as their bits */
    else if (as_uint(z) == keys[k])
      atomic_min(&texels[k], (p * g.x + ij.y) * g.x + ij.x);
  }
}

/* Range: drop_count. */
__kernel void spray_points(ATLAS_IN pos, int2 g, __global const int *texels, int drop_count, __global float4 *points)
{
  const int k = get_global_id(0);
  if (k >= drop_count)
    return;
  const int t = texels[k];
  if (t == INT_MAX) {
    points[k] = (float4)(0.0f);
    return;
  }
  const int tile_texels = g.x * g.x, p = t / tile_texels, r = t - p * tile_texels;
  points[k] = (float4)(ATLAS_LOAD(pos, g, p, (int2)(r % g.x, r / g.x)).xyz, 1.0f);
}
