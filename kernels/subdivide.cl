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
#define SUBDIVIDE_COPY(ij, k, corner, bit) ATLAS_STORE(dst, dg, p, ij, (corner) ? corners[corner_base + (k)] : sides[k])
#define SUBDIVIDE_INSIDE(ij) subdivide_inside(src, dst, sg, dg, p, ij)
#define SUBDIVIDE_SKIP(q) UNFLAGGED(flags, generation, q)

/* Range: whole destination tiles, (dst tile, dst tile * patches). */
__kernel void subdivide_tiles(ATLAS_IN src, ATLAS_OUT dst, int2 sg, int2 dg, __global const int *list, int patches,
                              __global const uchar *flags, int generation, __global const int4 *restrict patch_sides, __global const int4 *restrict patch_rings,
                              __global const float4 *restrict sides, __global const float4 *restrict corners,
                              int corner_base)
{
  TILE_TEXEL_PART(dg, list, patches, SUBDIVIDE_SKIP, patch_sides, patch_rings, SUBDIVIDE_COPY, SUBDIVIDE_INSIDE);
}

/* Range: patches; the same with a work item per patch walking its tile
 * (FOR_EACH_TILE_PART). */
__kernel void subdivide_patches(ATLAS_IN src, ATLAS_OUT dst, int2 sg, int2 dg, __global const int *list, int patches,
                                __global const uchar *flags, int generation,
                                __global const int4 *restrict patch_sides, __global const int4 *restrict patch_rings,
                                __global const float4 *restrict sides, __global const float4 *restrict corners,
                                int corner_base)
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

/* The vertex point of an interior ring: v, the sums of its slots' texels
 * (1, 0) and (1, 1) taken in slot order from 0, and its valence. */
inline float4 ring_vertex_point(float4 v, float4 es, float4 ds, int count)
{
  const float n = (float)count;
  return (1.0f - 1.75f / n) * v + (1.5f / (n * n)) * es + (0.25f / (n * n)) * ds;
}

/* The vertex point of a boundary ring: a corner of one face stays sharp;
 * others follow the boundary curve through its first slot's texel (1, 0)
 * and its last slot's texel (0, 1). */
inline float4 boundary_vertex_point(float4 v, float4 first_out, float4 last_in, int count)
{
  return count == 1 ? v : 0.75f * v + 0.125f * (first_out + last_in);
}

/* Range: #rings; patch corners, i.e. the level-1 vertices, into
 * corners[base + ring]. */
__kernel void subdivide_corners(ATLAS_IN src, __global float4 *restrict corners, int base,
                                __global const CornerRing *rings, __global const CornerSlot *slots,
                                __global const int *list, int ring_count, __global const uchar *flags, int generation,
                                int2 sg)
{
  RING_ITEM(src, sg, rings, slots, list, ring_count, flags, generation);
  const CornerSlot first = slots[ring.first], last = slots[ring.first + ring.count - 1];
  const float4 v = CORNER_LOAD(src, sg, first, 0, 0);
  float4 r;
  if (ring.boundary) {
    r = boundary_vertex_point(v, ring.count == 1 ? v : CORNER_LOAD(src, sg, first, 1, 0),
                              ring.count == 1 ? v : CORNER_LOAD(src, sg, last, 0, 1), ring.count);
  } else {
    float4 es = (float4)(0.0f), ds = (float4)(0.0f);
    for (int m = 0; m < ring.count; ++m) {
      const CornerSlot s = slots[ring.first + m];
      es += CORNER_LOAD(src, sg, s, 1, 0);
      ds += CORNER_LOAD(src, sg, s, 1, 1);
    }
    r = ring_vertex_point(v, es, ds, ring.count);
  }
  corners[base + index] = r;
}

/* The corners of several levels from one gather.
 *
 * A ring's vertex point one level up needs only its 2N + 1 texels v,
 * e_m = (1, 0) and d_m = (1, 1) of each slot m; and those texels one level
 * up are again functions of the same 2N + 1 (slot m's texel (0, 1) is
 * e_{m+1}, slot m - 1 lies across its outgoing side). So one read of the
 * source level gives the corners of every level above it, the intermediate
 * levels' rings never being read back from memory. Each formula is the one
 * the side and tile kernels evaluate, term for term in their order:
 * - e'_m, the side kernel's edge point; its sums are symmetric, so which
 *   of the edge's patches is its first does not matter;
 * - d'_m, subdivide_inside() at the slot's corner texel in the patch's own
 *   axes: the pairs it sums first depend on the corner (0..3).
 * subdivide_inside() also adds taps of weight 0, some two texels from the
 * corner, outside the ring; they are left out. Adding 0 * x (x finite, as
 * every texel is) can change only the sign of a zero sum, and no corner
 * depends on that: a vertex point's sums start from +0, so it is never -0,
 * and a nonzero result does not see the sign of a zero term. The corners
 * are the same bits as a corner kernel per level gives
 * (test StoragePaths.CornersInOnePass*).
 *
 * Rings of more than RING_LEVELS_MAX slots, whose texels would not fit in
 * private memory, get their first level's corner here and are marked
 * (marks[ring] = mark) for subdivide_corners to take the later ones from
 * the levels themselves.
 *
 * Range: #rings; level from + 1 + l into corners[base + l * stride + ring]
 * for l < levels. */

/* subdivide_inside() at texel (1, 1) of a slot whose corner is `corner`,
 * from the slot's v, e, its texel (0, 1) f and d, less the taps of weight 0. */
inline float4 ring_face_point(int corner, float4 v, float4 e, float4 f, float4 d)
{
  /* subdivide_inside() sums rows along the patch's own i first: which of
   * the slot's texels pair up, and in which order, follows the corner. */
  float4 r0, r1;
  switch (corner) {
  case 0:
    r0 = 0.5f * v + 0.5f * e;
    r1 = 0.5f * f + 0.5f * d;
    break;
  case 1:
    r0 = 0.5f * f + 0.5f * v;
    r1 = 0.5f * d + 0.5f * e;
    break;
  case 2:
    r0 = 0.5f * d + 0.5f * f;
    r1 = 0.5f * e + 0.5f * v;
    break;
  default:
    r0 = 0.5f * e + 0.5f * d;
    r1 = 0.5f * v + 0.5f * f;
    break;
  }
  return 0.5f * r0 + 0.5f * r1;
}

__kernel void subdivide_corner_levels(ATLAS_IN src, __global float4 *restrict corners, int base, int stride,
                                      int levels, __global uchar *restrict marks, uchar mark,
                                      __global const CornerRing *rings, __global const CornerSlot *slots,
                                      __global const int *list, int ring_count, __global const uchar *flags,
                                      int generation, int2 sg)
{
  RING_ITEM(src, sg, rings, slots, list, ring_count, flags, generation);
  const int count = ring.count;
  const CornerSlot first = slots[ring.first], last = slots[ring.first + count - 1];
  __global float4 *out = corners + base + index;
  float4 v = CORNER_LOAD(src, sg, first, 0, 0);
  if (ring.boundary) {
    /* The boundary sides' points are their midpoints. */
    float4 a = count == 1 ? v : CORNER_LOAD(src, sg, first, 1, 0);
    float4 b = count == 1 ? v : CORNER_LOAD(src, sg, last, 0, 1);
    for (int l = 0; l < levels; ++l) {
      const float4 r = boundary_vertex_point(v, a, b, count);
      out[l * stride] = r;
      a = 0.5f * (v + a);
      b = 0.5f * (v + b);
      v = r;
    }
    marks[index] = 0;
    return;
  }
  float4 e[RING_LEVELS_MAX], d[RING_LEVELS_MAX];
  int corner[RING_LEVELS_MAX];
  const int held = count <= RING_LEVELS_MAX;
  float4 es = (float4)(0.0f), ds = (float4)(0.0f);
  for (int m = 0; m < count; ++m) {
    const CornerSlot s = slots[ring.first + m];
    const float4 em = CORNER_LOAD(src, sg, s, 1, 0), dm = CORNER_LOAD(src, sg, s, 1, 1);
    es += em;
    ds += dm;
    if (held) {
      e[m] = em;
      d[m] = dm;
      corner[m] = s.corner;
    }
  }
  float4 r = ring_vertex_point(v, es, ds, count);
  out[0] = r;
  marks[index] = held ? 0 : mark;
  if (!held)
    return;
  for (int l = 1; l < levels; ++l) {
    /* The ring one level up, in place: e'_m reads e_{m-1} and d_{m-1}
     * (kept from before their update) and e_{m+1} (not updated yet). */
    const float4 e0 = e[0];
    float4 e_before = e[count - 1], d_before = d[count - 1];
    es = (float4)(0.0f);
    ds = (float4)(0.0f);
    for (int m = 0; m < count; ++m) {
      const float4 em = e[m], dm = d[m], en = m + 1 < count ? e[m + 1] : e0;
      e[m] = 0.5f * (0.75f * (v + em) + 0.125f * ((en + dm) + (e_before + d_before)));
      d[m] = ring_face_point(corner[m], v, em, en, dm);
      es += e[m];
      ds += d[m];
      e_before = em;
      d_before = dm;
    }
    v = r;
    r = ring_vertex_point(v, es, ds, count);
    out[l * stride] = r;
  }
}
