/* Catmull-Clark refinement of the atlas, level l -> l+1 (n -> 2n quads per
 * patch side). Above level 1 every vertex off a patch corner is regular, so
 * the masks there are the tensor-product cubic B-spline ones; corners use the
 * ring tables. Each stored copy of an edge or corner texel is copied from
 * one computation, so the copies stay bit-identical.
 * sg, dg: grids (tile, tiles_x) of the source and destination levels. */

/* Weights of the old taps c-1, c, c+1 (c = (i+1)/2) for new index i along one
 * axis: even i is a vertex point (1,6,1)/8, odd i an edge midpoint (1,1)/2. */
inline float3 refine_weights(int i)
{
  return (i & 1) ? (float3)(0.5f, 0.5f, 0.0f) : (float3)(0.125f, 0.75f, 0.125f);
}

/* The side and corner kernels write compact arrays (border_entry()), and
 * subdivide_tiles writes whole destination tiles: it computes the texels
 * strictly inside and copies the rest, so each cache line of the level is
 * written once, by one kernel (as the limit's kernels do). */

/* Destination texel ij strictly inside patch p. */
TEXEL_INLINE void subdivide_inside(ATLAS_IN src, ATLAS_OUT dst, int2 sg, int2 dg, int p, int2 ij)
{
  const int n_src = sg.x - 1;
  const int ci = (ij.x + 1) >> 1, cj = (ij.y + 1) >> 1;
  const int i0 = ci - 1, i2 = min(ci + 1, n_src);
  const int j0 = cj - 1, j2 = min(cj + 1, n_src);
  const float3 wi = refine_weights(ij.x), wj = refine_weights(ij.y);
#define ROW(jj)                                              \
  (wi.x * ATLAS_LOAD(src, sg, p, (int2)(i0, jj)) +           \
   wi.y * ATLAS_LOAD(src, sg, p, (int2)(ci, jj)) +           \
   wi.z * ATLAS_LOAD(src, sg, p, (int2)(i2, jj)))
  const float4 v = wj.x * ROW(j0) + wj.y * ROW(cj) + wj.z * ROW(j2);
#undef ROW
  ATLAS_STORE(dst, dg, p, ij, v);
}

/* Destination texel ij of patch p on a side or corner: entry k of `corners`
 * or `sides`, which must have been computed in this step. */
#define SUBDIVIDE_COPY(ij, k, corner, bit) ATLAS_STORE(dst, dg, p, ij, (corner) ? corners[k] : sides[k])
#define SUBDIVIDE_INSIDE(ij) subdivide_inside(src, dst, sg, dg, p, ij)
#define SUBDIVIDE_SKIP(q) UNFLAGGED(flags, generation, q)

/* Range: whole destination tiles, (dst tile, dst tile * patches). */
__kernel void subdivide_tiles(ATLAS_IN src, ATLAS_OUT dst, int2 sg, int2 dg, __global const int *list, int patches,
                              __global const uchar *flags, int generation, __global const int4 *restrict patch_sides, __global const int4 *restrict patch_rings,
                              __global const float4 *restrict sides, __global const float4 *restrict corners)
{
  TILE_TEXEL_PART(dg, list, patches, SUBDIVIDE_SKIP, patch_sides, patch_rings, SUBDIVIDE_COPY, SUBDIVIDE_INSIDE);
}

/* Range: patches; the same with a work item per patch walking its tile
 * (FOR_EACH_TILE_PART). */
__kernel void subdivide_patches(ATLAS_IN src, ATLAS_OUT dst, int2 sg, int2 dg, __global const int *list, int patches,
                                __global const uchar *flags, int generation,
                                __global const int4 *restrict patch_sides, __global const int4 *restrict patch_rings,
                                __global const float4 *restrict sides, __global const float4 *restrict corners)
{
  PATCH_ITEM_PARTS(dg, list, patches, SUBDIVIDE_SKIP, patch_sides, patch_rings, SUBDIVIDE_COPY, SUBDIVIDE_INSIDE);
}

/* Range: #edges; texels on patch sides, corners excluded, into `sides`,
 * each work item walking one side so that its frames and rows are set up
 * once. */
__kernel void subdivide_edges(ATLAS_IN src, __global float4 *restrict sides, __global const PatchEdge *edges,
                              __global const int *list, int edge_count, __global const uchar *flags,
                              int generation, int2 sg, int2 dg)
{
  const int k = get_global_id(0);
  if (k >= edge_count)
    return;
  const int n_src = sg.x - 1;
  const int edge = LISTED(list, k);
  if (UNFLAGGED(flags, generation, edge))
    return;
  const PatchEdge e = edges[edge];
  PREFETCH_EDGE_AHEAD(src, sg, edges, list, k, edge_count);
  const int first = edge * (dg.x - 2) - 1; /* texel t at first + t */
  EDGE_FRAMES(e, sg);
  const int interior = e.patch[1] >= 0;
  /* Old samples along the side: the side row and the rows on either side. */
  float4 prev_row = EDGE_LOAD(src, sg, 0, 0), prev_in = EDGE_LOAD(src, sg, 0, 1);
  float4 prev_out = interior ? EDGE_LOAD(src, sg, 0, -1) : prev_row;
  float4 cur_row = EDGE_LOAD(src, sg, 1, 0), cur_in = EDGE_LOAD(src, sg, 1, 1);
  float4 cur_out = interior ? EDGE_LOAD(src, sg, 1, -1) : cur_row;
  for (int c = 1; c <= n_src; ++c) {
    /* Edge point between old samples c-1 and c, then vertex point at c. */
    const float4 across_mid = 0.75f * (prev_row + cur_row) + 0.125f * ((prev_in + cur_in) + (prev_out + cur_out));
    const float4 mid = interior ? 0.5f * across_mid : 0.5f * (prev_row + cur_row);
    sides[first + 2 * c - 1] = mid;
    if (c == n_src)
      break;
    const float4 next_row = EDGE_LOAD(src, sg, c + 1, 0), next_in = EDGE_LOAD(src, sg, c + 1, 1);
    const float4 next_out = interior ? EDGE_LOAD(src, sg, c + 1, -1) : next_row;
    float4 v;
    if (interior) {
      const float4 row = 0.125f * (prev_row + next_row) + 0.75f * cur_row;
      const float4 in = 0.125f * (prev_in + next_in) + 0.75f * cur_in;
      const float4 out = 0.125f * (prev_out + next_out) + 0.75f * cur_out;
      v = 0.125f * (in + out) + 0.75f * row;
    } else {
      v = 0.125f * (prev_row + next_row) + 0.75f * cur_row;
    }
    sides[first + 2 * c] = v;
    prev_row = cur_row; prev_in = cur_in; prev_out = cur_out;
    cur_row = next_row; cur_in = next_in; cur_out = next_out;
  }
}

/* Range: #rings; patch corners, i.e. the level-1 vertices, into `corners`. */
__kernel void subdivide_corners(ATLAS_IN src, __global float4 *restrict corners, __global const CornerRing *rings,
                                __global const CornerSlot *slots, __global const int *list, int ring_count,
                                __global const uchar *flags, int generation, int2 sg)
{
  const int k = get_global_id(0);
  if (k >= ring_count)
    return;
  const int index = LISTED(list, k);
  if (UNFLAGGED(flags, generation, index))
    return;
  const CornerRing ring = rings[index];
  PREFETCH_RING_AHEAD(src, sg, rings, slots, list, k, ring_count);
  const CornerSlot first = slots[ring.first], last = slots[ring.first + ring.count - 1];
  const float4 v = CORNER_LOAD(src, sg, first, 0, 0);
  float4 r;
  if (ring.boundary) {
    /* A corner of one face stays sharp; others follow the boundary curve. */
    r = ring.count == 1 ? v
                        : 0.75f * v + 0.125f * (CORNER_LOAD(src, sg, first, 1, 0) +
                                                CORNER_LOAD(src, sg, last, 0, 1));
  } else {
    float4 es = (float4)(0.0f), ds = (float4)(0.0f);
    for (int m = 0; m < ring.count; ++m) {
      const CornerSlot s = slots[ring.first + m];
      es += CORNER_LOAD(src, sg, s, 1, 0);
      ds += CORNER_LOAD(src, sg, s, 1, 1);
    }
    const float n = (float)ring.count;
    r = (1.0f - 1.75f / n) * v + (1.5f / (n * n)) * es + (0.25f / (n * n)) * ds;
  }
  corners[index] = r;
}
