/* Brushes that move geometry or filter a layer: weights, smoothing
 * (Laplacian; Taubin is two passes), sculpt, inflate, flatten. They change a
 * layer of the finest level of a set of patches, reading `src` and writing
 * `dst` (images cannot be read and written by one kernel); the host copies
 * the tiles back. Smoothing follows the atlas's three batches, so each stored
 * copy of a side or corner texel gets one value. Weights are per texel,
 * patch-major, computed from the limit surface. Built after brush.cl, whose
 * falloff and stamp helpers it shares. */

#define WEIGHT_INDEX(g, p, ij) PATCH_MAJOR_INDEX(g, p, ij)

/* Range: (tile, tile * count). Weight of each texel of the listed patches:
 * falloff x strength x (1 - mask), 0 outside the radius. The mask lives at
 * the finest level (grid gm): texel ij of grid g is texel ij * stride there.
 * unfold: as for paint_dab, one per listed patch; its maps hold at any level. */
__kernel void dab_weights(ATLAS_IN limit_pos, ATLAS_IN limit_nrm, int2 g, __global const int *restrict list,
                          int count, __global const BrushDab *restrict dab,
                          __global const PatchUnfolding *restrict unfold, __global const float *restrict stamp,
                          __global const float4 *restrict material, int2 gm, int stride,
                          __global float *restrict weights)
{
  int p;
  int2 ij;
  if (!tile_texel(g, list, count, &p, &ij))
    return;
  const int a = get_global_id(1) / g.x; /* p's entry in the list, and in unfold */
  const float3 x = ATLAS_LOAD(limit_pos, g, p, ij).xyz;
  float2 plane;
  const float t = brush_t(dab, unfold, a, x, BRUSH_NORMAL(dab, limit_nrm, g, p, ij), ij, g.x - 1, &plane);
  const int k = WEIGHT_INDEX(g, p, ij);
  weights[k] = t <= 1.0f ? falloff_weight(dab->falloff, t) * dab->strength *
                             (1.0f - material[WEIGHT_INDEX(gm, p, ij * stride)].w) *
                             stamp_weight(dab, stamp, plane)
                         : 0.0f;
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

/* Range: (tile, tile * count); texels strictly inside the listed patches. */
__kernel void smooth_interior(ATLAS_IN src, ATLAS_OUT dst, int2 g, __global const int *list, int count,
                              __global const float *weights, float lambda)
{
  int p;
  int2 ij;
  if (!interior_texel(g, list, count, &p, &ij))
    return;
  const float w = weights[WEIGHT_INDEX(g, p, ij)];
  const float4 x = ATLAS_LOAD(src, g, p, ij);
  if (w == 0.0f) {
    ATLAS_STORE(dst, g, p, ij, x);
    return;
  }
  const float4 mean = 0.25f * ((ATLAS_LOAD(src, g, p, ij + (int2)(-1, 0)) + ATLAS_LOAD(src, g, p, ij + (int2)(1, 0))) +
                               (ATLAS_LOAD(src, g, p, ij + (int2)(0, -1)) + ATLAS_LOAD(src, g, p, ij + (int2)(0, 1))));
  ATLAS_STORE(dst, g, p, ij, umbrella(x, mean, lambda * w));
}

/* Range: count; per listed side, its texels. A mesh-boundary
 * side is smoothed along itself, so borders do not pull inwards. */
__kernel void smooth_edges(ATLAS_IN src, ATLAS_OUT dst, int2 g, __global const PatchEdge *edges,
                           __global const int *list, int count, __global const float *weights, float lambda)
{
  const int k = get_global_id(0);
  if (k >= count)
    return;
  const PatchEdge e = edges[LISTED(list, k)];
  EDGE_FRAMES(e, g);
  /* Along the side, the texel before, at and after t slide one step a time. */
  float4 before = EDGE_LOAD(src, g, 0, 0), x = EDGE_LOAD(src, g, 1, 0);
  for (int t = 1; t < g.x - 1; ++t) {
    const float4 after = EDGE_LOAD(src, g, t + 1, 0);
    const float w = weights[WEIGHT_INDEX(g, fp.patch, fp.o + t * fp.dt)];
    float4 mean;
    if (e.patch[1] >= 0)
      mean = 0.25f * ((before + after) + (EDGE_LOAD(src, g, t, 1) + EDGE_LOAD(src, g, t, -1)));
    else
      mean = 0.5f * (before + after);
    EDGE_STORE(dst, g, e, t, w == 0.0f ? x : umbrella(x, mean, lambda * w));
    before = x;
    x = after;
  }
}

/* Range: count; every copy of the listed patch corners. */
__kernel void smooth_corners(ATLAS_IN src, ATLAS_OUT dst, int2 g, __global const CornerRing *rings,
                             __global const CornerSlot *slots, __global const int *list, int count,
                             __global const float *weights, float lambda)
{
  const int k = get_global_id(0);
  if (k >= count)
    return;
  const CornerRing ring = rings[LISTED(list, k)];
  const CornerSlot first = slots[ring.first], last = slots[ring.first + ring.count - 1];
  const Frame f0 = side_frame(first.patch, first.corner, g.x - 1);
  const float w = weights[WEIGHT_INDEX(g, first.patch, f0.o)];
  const float4 x = CORNER_LOAD(src, g, first, 0, 0);
  float4 r = x;
  if (w != 0.0f) {
    if (ring.boundary) {
      if (ring.count > 1) /* a corner of one face stays where it is */
        r = umbrella(x, 0.5f * (CORNER_LOAD(src, g, first, 1, 0) + CORNER_LOAD(src, g, last, 0, 1)), lambda * w);
    } else {
      float4 sum = (float4)(0.0f);
      for (int m = 0; m < ring.count; ++m)
        sum += CORNER_LOAD(src, g, slots[ring.first + m], 1, 0);
      r = umbrella(x, sum / (float)ring.count, lambda * w);
    }
  }
  for (int m = 0; m < ring.count; ++m)
    CORNER_STORE(dst, g, slots[ring.first + m], r);
}

/* Range: (tile, tile * count). Moves control points: x + amount * w * dir,
 * dir by `mode` (MOVE_*); flatten moves by amount * w of the distance to the
 * plane. Every copy computes the same from the same inputs. */
__kernel void move_points(ATLAS_IN src, ATLAS_OUT dst, ATLAS_IN limit_nrm, int2 g, __global const int *list,
                          int count, __global const float *weights, int mode, float amount, float4 centre,
                          float4 centre_normal)
{
  int p;
  int2 ij;
  if (!tile_texel(g, list, count, &p, &ij))
    return;
  const float w = weights[WEIGHT_INDEX(g, p, ij)];
  float4 x = ATLAS_LOAD(src, g, p, ij);
  if (w != 0.0f) {
    if (mode == MOVE_INFLATE)
      x.xyz += (amount * w) * ATLAS_LOAD(limit_nrm, g, p, ij).xyz;
    else if (mode == MOVE_FLATTEN)
      x.xyz -= (amount * w * dot(x.xyz - centre.xyz, centre_normal.xyz)) * centre_normal.xyz;
    else
      x.xyz += (amount * w) * centre_normal.xyz;
  }
  ATLAS_STORE(dst, g, p, ij, x);
}

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
