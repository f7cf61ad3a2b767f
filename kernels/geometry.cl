/* Brushes that move geometry or filter a layer: weights, smoothing
 * (Laplacian; Taubin is two passes), sculpt, inflate, flatten. They change a
 * layer of one level on a set of patches. Moves read `src` and write `dst`:
 * with images (which one kernel cannot read and write) another layer, whose
 * tiles the host copies back; with buffers the same one, each texel read
 * and written by its own work item. Smoothing runs on the welded mesh, so each stored copy of a
 * side or corner texel gets one value. Weights are per texel, patch-major,
 * computed from the limit surface, in the brush spaces of brush_space.cl. */

#define WEIGHT_INDEX(g, p, ij) PATCH_MAJOR_INDEX(g, p, ij)

/* The layers a move reads and writes: without restrict for buffers, which
 * may be one. */
#ifdef ATLAS_IMAGE
#define MOVED_IN ATLAS_IN
#define MOVED_OUT ATLAS_OUT
#else
#define MOVED_IN __global const float4 *
#define MOVED_OUT __global float4 *
#endif

/* Weight of texel ij of p, the a-th listed patch:
 * falloff x strength x (1 - mask), 0 outside the radius. The mask lives at
 * the finest level (grid gm): texel ij of grid g is texel ij * stride there;
 * `masked` 0 says no mask is set anywhere, and its reads are skipped.
 * unfold: as for paint_dab, one per listed patch; its maps hold at any level.
 * outside (or null): per listed patch, the sides and corners it shares with
 * unlisted patches (bits as texel_border); their texels weigh 0, since their
 * copies there would not move with them (held()). */
TEXEL_INLINE int held(__global const uchar *restrict outside, int a, int2 ij, int n)
{
  return outside && (outside[a] & texel_border(ij, n));
}

TEXEL_INLINE float dab_weight(ATLAS_IN limit_pos, ATLAS_IN limit_nrm, int2 g, int p, int2 ij, int a,
                              __global const BrushDab *restrict dab, __global const PatchUnfolding *restrict unfold,
                              __global const float *restrict stamp, __global const float4 *restrict material,
                              int masked, int2 gm, int stride, __global const uchar *restrict outside)
{
  const float3 x = ATLAS_LOAD(limit_pos, g, p, ij).xyz;
  float2 plane;
  const float t = brush_t(dab, unfold, a, x, BRUSH_NORMAL(dab, limit_nrm, g, p, ij), ij, g.x - 1, &plane);
  return t <= 1.0f && !held(outside, a, ij, g.x - 1) ? falloff_weight(dab->falloff, t) * dab->strength *
                                (masked ? 1.0f - material[WEIGHT_INDEX(gm, p, ij * stride)].w : 1.0f) *
                                stamp_weight(dab, stamp, plane)
                            : 0.0f;
}

/* Range: (tile, tile * count); the weights of the listed patches' texels. */
__kernel void dab_weights(ATLAS_IN limit_pos, ATLAS_IN limit_nrm, int2 g, __global const int *restrict list,
                          int count, __global const BrushDab *restrict dab,
                          __global const PatchUnfolding *restrict unfold, __global const float *restrict stamp,
                          __global const float4 *restrict material, int masked, int2 gm, int stride,
                          __global const uchar *restrict outside, __global float *restrict weights)
{
  int p;
  int2 ij;
  if (!tile_texel(g, list, count, &p, &ij))
    return;
  const int a = get_global_id(1) / g.x; /* p's entry in the list, and in unfold */
  weights[WEIGHT_INDEX(g, p, ij)] =
    dab_weight(limit_pos, limit_nrm, g, p, ij, a, dab, unfold, stamp, material, masked, gm, stride, outside);
}

/* Range: count; the same with a work item per patch (see
 * FOR_EACH_PATCH_TEXEL): at a coarse edit level a tile has 4 or 9 texels,
 * and a work item per texel spent more on its indices than on its weight. */
__kernel void dab_weights_patches(ATLAS_IN limit_pos, ATLAS_IN limit_nrm, int2 g, __global const int *restrict list,
                                  int count, __global const BrushDab *restrict dab,
                                  __global const PatchUnfolding *restrict unfold, __global const float *restrict stamp,
                                  __global const float4 *restrict material, int masked, int2 gm, int stride,
                                  __global const uchar *restrict outside, __global float *restrict weights)
{
  FOR_EACH_PATCH_TEXEL(g, list, count,
                       weights[WEIGHT_INDEX(g, p, ij)] = dab_weight(limit_pos, limit_nrm, g, p, ij, patch_item, dab,
                                                                    unfold, stamp, material, masked, gm, stride,
                                                                    outside));
}

/* Range: (tile, tile * count). Copies whole tiles of the listed patches. */
__kernel void copy_tiles(ATLAS_IN src, ATLAS_OUT dst, int2 g, __global const int *list, int count)
{
  int p;
  int2 ij;
  if (tile_texel(g, list, count, &p, &ij))
    ATLAS_STORE(dst, g, p, ij, ATLAS_LOAD(src, g, p, ij));
}

/* x + lambda * w * (mean of neighbours - x); xyz only, w kept. */
inline float4 umbrella(float4 x, float4 mean, float step)
{
  return (float4)(x.xyz + step * (mean.xyz - x.xyz), x.w);
}

/* Smoothing on the welded quad mesh: the listed tiles are gathered into
 * arrays with one entry per vertex (welded_gather), passes read each
 * neighbour from there (welded_smooth), and every stored copy is written
 * back (welded_scatter). Patch corners and the other vertices take
 * work-groups of their own: a corner has a ring of any size, the others
 * four neighbours, which keeps their items free of its branches. */

/* Range: (tile, tile * count). Every copy of a vertex holds the same bits,
 * so copies write the same value; both arrays get it, so that vertices no
 * pass moves read alike from either. The weight is the vertex's own texel's;
 * with null `weights` they are left to welded_listed_weights. */
__kernel void welded_gather(ATLAS_IN layer, int2 g, __global const int *restrict list, int count,
                            __global const int *restrict vertex_of, __global const int *restrict texel,
                            __global const float *restrict weights, __global float4 *restrict a,
                            __global float4 *restrict b, __global float *restrict welded_weights)
{
  int p;
  int2 ij;
  if (!tile_texel(g, list, count, &p, &ij))
    return;
  const int t = PATCH_MAJOR_INDEX(g, p, ij);
  const int v = vertex_of[t];
  const float4 x = ATLAS_LOAD(layer, g, p, ij);
  a[v] = x;
  b[v] = x;
  if (weights && texel[v] == t)
    welded_weights[v] = weights[t];
}

/* Range: count; the weights of the listed vertices (list[k]), each its own
 * texel's, as welded_gather gives them. */
__kernel void welded_listed_weights(__global const int *restrict list, int count, __global const int *restrict texel,
                                    __global const float *restrict weights, __global float *restrict welded_weights)
{
  const int k = get_global_id(0);
  if (k < count)
    welded_weights[list[k]] = weights[texel[list[k]]];
}

/* Range: (tile, tile * count). */
__kernel void welded_scatter(__global const float4 *restrict welded, ATLAS_OUT layer, int2 g,
                             __global const int *restrict list, int count, __global const int *restrict vertex_of)
{
  int p;
  int2 ij;
  if (tile_texel(g, list, count, &p, &ij))
    ATLAS_STORE(layer, g, p, ij, welded[vertex_of[PATCH_MAJOR_INDEX(g, p, ij)]]);
}

/* Patch corner v: its ring's neighbours summed one after another; two
 * neighbours: a border corner, smoothed along the border; none: the corner
 * of a single face, which stays. Rings of three and four (the face and
 * edge points of a triangle base) are summed spelt out, in the loop's
 * order: the same bits. */
inline float4 welded_corner(__global const float4 *restrict src, int v, __global const int *restrict first,
                            __global const int *restrict ring, __global const float *restrict weights, float lambda)
{
  const float4 x = src[v];
  const float w = weights[v];
  const int f = first[v], m = first[v + 1] - f;
  if (w == 0.0f || m == 0)
    return x;
  float4 mean;
  if (m == 2) {
    mean = 0.5f * (src[ring[f]] + src[ring[f + 1]]);
  } else if (m == 3) {
    mean = ((((float4)(0.0f) + src[ring[f]]) + src[ring[f + 1]]) + src[ring[f + 2]]) / 3.0f;
  } else if (m == 4) {
    mean = (((((float4)(0.0f) + src[ring[f]]) + src[ring[f + 1]]) + src[ring[f + 2]]) + src[ring[f + 3]]) / 4.0f;
  } else {
    float4 sum = (float4)(0.0f);
    for (int i = 0; i < m; ++i)
      sum += src[ring[f + i]];
    mean = sum / (float)m;
  }
  return umbrella(x, mean, lambda * w);
}

/* Vertex v inside a patch or on a patch side: its four neighbours (entry
 * v - base of `around`) summed in pairs; on a mesh-boundary side they are
 * its two along the side, each twice, which gives their mean exactly. */
inline float4 welded_texel(__global const float4 *restrict src, int v, int base, __global const int4 *restrict around,
                           __global const float *restrict weights, float lambda)
{
  const int4 nb = around[v - base];
  const float4 x = src[v];
  const float w = weights[v];
  const float4 mean = 0.25f * ((src[nb.x] + src[nb.y]) + (src[nb.z] + src[nb.w]));
  return w != 0.0f ? umbrella(x, mean, lambda * w) : x;
}

/* Range: (corner_groups + groups of others) x local size. One pass: the
 * first corner_groups work-groups take the `corners` patch corners
 * (list[k], or k with a null list), the others the `others` vertices after
 * them (list[corners + k], or base + k). One launch a pass, not one per
 * kind: a launch costs about as much as a small level's corners
 * themselves. Whole work-groups take one kind, so neither kind's items
 * wait on the other's branch. */
__kernel void welded_smooth(__global const float4 *restrict src, __global float4 *restrict dst,
                            __global const int *restrict list, int corners, int others, int corner_groups, int base,
                            __global const int *restrict first, __global const int *restrict ring,
                            __global const int4 *restrict around, __global const float *restrict weights,
                            float lambda)
{
  if ((int)get_group_id(0) < corner_groups) {
    const int k = get_global_id(0);
    if (k < corners) {
      const int v = LISTED(list, k);
      dst[v] = welded_corner(src, v, first, ring, weights, lambda);
    }
  } else {
    const int k = get_global_id(0) - corner_groups * (int)get_local_size(0);
    if (k < others) {
      const int v = list ? list[corners + k] : base + k;
      dst[v] = welded_texel(src, v, base, around, weights, lambda);
    }
  }
}

/* Range: (tile, tile * count). Moves control points: x + amount * w * dir,
 * dir by `mode` (MOVE_*); flatten moves by amount * w of the distance to the
 * plane. Every copy computes the same from the same inputs. */
TEXEL_INLINE float4 moved_point(float4 x, float w, ATLAS_IN limit_nrm, int2 g, int p, int2 ij, int mode, float amount,
                                float4 centre, float4 centre_normal)
{
  if (w != 0.0f) {
    if (mode == MOVE_INFLATE)
      x.xyz += (amount * w) * ATLAS_LOAD(limit_nrm, g, p, ij).xyz;
    else if (mode == MOVE_FLATTEN)
      x.xyz -= (amount * w * dot(x.xyz - centre.xyz, centre_normal.xyz)) * centre_normal.xyz;
    else
      x.xyz += (amount * w) * centre_normal.xyz;
  }
  return x;
}

/* Texel ij of p moved by its stored weight. */
TEXEL_INLINE void move_by_weight(MOVED_IN src, MOVED_OUT dst, ATLAS_IN limit_nrm, int2 g, int p, int2 ij,
                                 __global const float *weights, int mode, float amount, float4 centre,
                                 float4 centre_normal)
{
  ATLAS_STORE(dst, g, p, ij,
              moved_point(ATLAS_LOAD(src, g, p, ij), weights[WEIGHT_INDEX(g, p, ij)], limit_nrm, g, p, ij, mode,
                          amount, centre, centre_normal));
}

__kernel void move_points(MOVED_IN src, MOVED_OUT dst, ATLAS_IN limit_nrm, int2 g, __global const int *list,
                          int count, __global const float *weights, int mode, float amount, float4 centre,
                          float4 centre_normal)
{
  int p;
  int2 ij;
  if (tile_texel(g, list, count, &p, &ij))
    move_by_weight(src, dst, limit_nrm, g, p, ij, weights, mode, amount, centre, centre_normal);
}

/* Range: count; move_points with a work item per patch. */
__kernel void move_points_patches(MOVED_IN src, MOVED_OUT dst, ATLAS_IN limit_nrm, int2 g, __global const int *list,
                                  int count, __global const float *weights, int mode, float amount, float4 centre,
                                  float4 centre_normal)
{
  FOR_EACH_PATCH_TEXEL(g, list, count,
                       move_by_weight(src, dst, limit_nrm, g, p, ij, weights, mode, amount, centre, centre_normal));
}

/* Range: (tile, tile * count). dab_weights and move_points in one pass,
 * for a move whose weights nothing else reads (sculpt, inflate, flatten;
 * at a coarse edit level too, with dab_weights' gm, stride and outside):
 * the weights are not stored. The same bits as the two.
 * `plain` (a ball with no stamp and no mask, the usual sculpt) takes the
 * weight from the arguments after it, without dab_weight's reads of the
 * dab: a third of the kernel's time. */
TEXEL_INLINE void move_texel(MOVED_IN src, MOVED_OUT dst, ATLAS_IN limit_pos, ATLAS_IN limit_nrm, int2 g, int p,
                             int2 ij, int a, __global const BrushDab *restrict dab,
                             __global const PatchUnfolding *restrict unfold, __global const float *restrict stamp,
                             __global const float4 *restrict material, int masked, int2 gm, int stride,
                             __global const uchar *restrict outside, int mode, float amount, float4 centre,
                             float4 centre_normal, int plain, float radius, int falloff, float strength)
{
  float w;
  if (plain) {
    /* dab_weight's own sums for a ball with no stamp or mask: the same bits */
    const float3 d = ATLAS_LOAD(limit_pos, g, p, ij).xyz - centre.xyz;
    const float t = sqrt(dot(d, d)) / radius;
    w = t <= 1.0f && !held(outside, a, ij, g.x - 1) ? falloff_weight(falloff, t) * strength : 0.0f;
  } else {
    w = dab_weight(limit_pos, limit_nrm, g, p, ij, a, dab, unfold, stamp, material, masked, gm, stride, outside);
  }
  ATLAS_STORE(dst, g, p, ij,
              moved_point(ATLAS_LOAD(src, g, p, ij), w, limit_nrm, g, p, ij, mode, amount, centre, centre_normal));
}

/* The arguments of move_dab and its forms per patch. */
#define MOVE_DAB_ARGUMENTS                                                                                             \
  MOVED_IN src, MOVED_OUT dst, ATLAS_IN limit_pos, ATLAS_IN limit_nrm, int2 g, __global const int *restrict list,      \
    int count, __global const BrushDab *restrict dab, __global const PatchUnfolding *restrict unfold,                  \
    __global const float *restrict stamp, __global const float4 *restrict material, int masked, int2 gm,               \
    int stride, __global const uchar *restrict outside, int mode, float amount, float4 centre,                         \
    float4 centre_normal, int plain, float radius, int falloff, float strength

__kernel void move_dab(MOVE_DAB_ARGUMENTS)
{
  int p;
  int2 ij;
  if (tile_texel(g, list, count, &p, &ij))
    move_texel(src, dst, limit_pos, limit_nrm, g, p, ij, get_global_id(1) / g.x, dab, unfold, stamp, material,
               masked, gm, stride, outside, mode, amount, centre, centre_normal, plain, radius, falloff, strength);
}

/* Range: count; the same with a work item per patch (see FOR_EACH_PATCH_TEXEL). */
__kernel void move_dab_patches(MOVE_DAB_ARGUMENTS)
{
  FOR_EACH_PATCH_TEXEL(g, list, count,
                       move_texel(src, dst, limit_pos, limit_nrm, g, p, ij, patch_item, dab, unfold, stamp,
                                  material, masked, gm, stride, outside, mode, amount, centre, centre_normal, plain,
                                  radius, falloff, strength));
}

/* move_dab_patches for a plain dab, eight listed patches per work item, a
 * patch per lane (lanes.cl; CPU devices): each lane performs move_texel()'s
 * operations in their order, so the points get the same bits. Lanes past
 * the end repeat the last patch, whose points then get the same values
 * twice. Range: count / PATCH_LANES rounded up. */
__kernel void move_dab_lanes(MOVE_DAB_ARGUMENTS)
{
  const int first = get_global_id(0) * PATCH_LANES;
  if (first >= count)
    return;
  const int8 at = min(first + (int8)(0, 1, 2, 3, 4, 5, 6, 7), (int8)(count - 1));
  const int8 patch =
    list ? (int8)(list[at.s0], list[at.s1], list[at.s2], list[at.s3], list[at.s4], list[at.s5], list[at.s6], list[at.s7])
         : at;
  const int8 sides = outside ? (int8)(outside[at.s0], outside[at.s1], outside[at.s2], outside[at.s3], outside[at.s4],
                                      outside[at.s5], outside[at.s6], outside[at.s7])
                             : (int8)(0);
  const int n = g.x - 1;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const int2 ij = (int2)(i, j);
      Lanes d = load_lanes(limit_pos, g, patch, ij);
      d.x -= centre.x;
      d.y -= centre.y;
      d.z -= centre.z;
      const float8 t = sqrt(lanes_dot(d, d)) / radius;
      const int8 held = (sides & texel_border(ij, n)) != 0;
      const float8 w = select((float8)(0.0f), falloff_weight_lanes(falloff, t) * strength, (t <= 1.0f) & ~held);
      const Lanes4 x = LANES4_LOADED(ATLAS_LOAD, src, g, patch, ij);
      /* moved_point() */
      const float8 s = amount * w;
      float8 mx, my, mz;
      if (mode == MOVE_INFLATE) {
        const Lanes nrm = load_lanes(limit_nrm, g, patch, ij);
        mx = x.x + s * nrm.x;
        my = x.y + s * nrm.y;
        mz = x.z + s * nrm.z;
      } else if (mode == MOVE_FLATTEN) {
        const float8 dx = x.x - centre.x, dy = x.y - centre.y, dz = x.z - centre.z;
        const float8 k = s * ((dx * centre_normal.x + dy * centre_normal.y) + dz * centre_normal.z);
        mx = x.x - k * centre_normal.x;
        my = x.y - k * centre_normal.y;
        mz = x.z - k * centre_normal.z;
      } else {
        mx = x.x + s * centre_normal.x;
        my = x.y + s * centre_normal.y;
        mz = x.z + s * centre_normal.z;
      }
      const int8 moves = w != 0.0f;
      mx = select(x.x, mx, moves);
      my = select(x.y, my, moves);
      mz = select(x.z, mz, moves);
      atlas_store_lanes4(dst, g, patch, ij, mx, my, mz, x.w);
    }
}

#undef MOVE_DAB_ARGUMENTS

/* Range: (tile, tile * count). Copies the listed patches' tiles of a layer
 * into a compact buffer (tile after tile), for undo; and back. */
__kernel void gather_tiles(ATLAS_IN layer, int2 g, __global const int *list, int count, __global float4 *out)
{
  int p;
  int2 ij;
  if (tile_texel(g, list, count, &p, &ij))
    out[(get_global_id(1) / g.x * g.x + ij.y) * g.x + ij.x] = ATLAS_LOAD(layer, g, p, ij);
}

__kernel void scatter_tiles(ATLAS_OUT layer, int2 g, __global const int *list, int count,
                            __global const float4 *in)
{
  int p;
  int2 ij;
  if (tile_texel(g, list, count, &p, &ij))
    ATLAS_STORE(layer, g, p, ij, in[(get_global_id(1) / g.x * g.x + ij.y) * g.x + ij.x]);
}
