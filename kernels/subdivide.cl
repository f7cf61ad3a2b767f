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

/* w.x * a + w.y * b + w.z * c: one axis of the tensor-product masks. */
inline float4 refine_row(float3 w, float4 a, float4 b, float4 c)
{
  return w.x * a + w.y * b + w.z * c;
}

/* Declares v, the new texel ij strictly inside a patch of n_src old quads a
 * side, from that patch's old texels LOAD(i, j): the tensor-product masks,
 * taps clamped to the tile (where their weight is 0). Every computation of
 * such a texel goes through here, so all give the same bits. */
#define REFINE_INSIDE(v, n_src, ij, LOAD)                                                       \
  float4 v;                                                                                     \
  {                                                                                             \
    const int ci_ = ((ij).x + 1) >> 1, cj_ = ((ij).y + 1) >> 1;                                 \
    const int i0_ = ci_ - 1, i2_ = min(ci_ + 1, (n_src)), j0_ = cj_ - 1, j2_ = min(cj_ + 1, (n_src)); \
    const float3 wi_ = refine_weights((ij).x), wj_ = refine_weights((ij).y);                    \
    v = refine_row(wj_, refine_row(wi_, LOAD(i0_, j0_), LOAD(ci_, j0_), LOAD(i2_, j0_)),        \
                   refine_row(wi_, LOAD(i0_, cj_), LOAD(ci_, cj_), LOAD(i2_, cj_)),             \
                   refine_row(wi_, LOAD(i0_, j2_), LOAD(ci_, j2_), LOAD(i2_, j2_)));            \
  }

/* Destination texel ij strictly inside patch p. */
TEXEL_INLINE void subdivide_inside(ATLAS_IN src, ATLAS_OUT dst, int2 sg, int2 dg, int p, int2 ij)
{
#define SOURCE_TEXEL(i, j) ATLAS_LOAD(src, sg, p, (int2)((i), (j)))
  REFINE_INSIDE(v, sg.x - 1, ij, SOURCE_TEXEL);
#undef SOURCE_TEXEL
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

/* A side's new texels from the old ones along it (row) and on the rows
 * either side of it (in, out; on a mesh boundary, where interior is 0,
 * only the row counts): the edge point between old samples 0 and 1, and
 * the vertex point at old sample 1 of 0, 1, 2. Each sum is symmetric, in
 * the two ends and in the two sides, so the two patches of a side, each
 * in its own frame, get the same bits. */
inline float4 side_edge_point(float4 r0, float4 r1, float4 i0, float4 i1, float4 o0, float4 o1, int interior)
{
  const float4 across = 0.75f * (r0 + r1) + 0.125f * ((i0 + i1) + (o0 + o1));
  return interior ? 0.5f * across : 0.5f * (r0 + r1);
}

inline float4 side_vertex_point(float4 r0, float4 r1, float4 r2, float4 i0, float4 i1, float4 i2, float4 o0,
                                float4 o1, float4 o2, int interior)
{
  const float4 row = 0.125f * (r0 + r2) + 0.75f * r1;
  if (!interior)
    return row;
  const float4 in = 0.125f * (i0 + i2) + 0.75f * i1;
  const float4 out = 0.125f * (o0 + o2) + 0.75f * o1;
  return 0.125f * (in + out) + 0.75f * row;
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
    sides[first + 2 * c - 1] = side_edge_point(prev_row, cur_row, prev_in, cur_in, prev_out, cur_out, interior);
    if (c == n_src)
      break;
    const float4 next_row = EDGE_LOAD(src, sg, c + 1, 0), next_in = EDGE_LOAD(src, sg, c + 1, 1);
    const float4 next_out = interior ? EDGE_LOAD(src, sg, c + 1, -1) : next_row;
    sides[first + 2 * c] = side_vertex_point(prev_row, cur_row, next_row, prev_in, cur_in, next_in, prev_out, cur_out,
                                             next_out, interior);
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

/* The patch across side s of a patch whose across table (patch_across) is
 * a, and its side there; patch -1 on a mesh boundary. */
inline int2 across_side(int4 a, int s)
{
  const int code = int4_at(a, s);
  return code < 0 ? (int2)(-1, 0) : (int2)(code >> 2, code & 3);
}

/* Corner c (0..3, counter-clockwise) of a level-1 tile, whose 2 x 2 texels
 * are its corners. */
inline int2 first_corner(int c)
{
  return (int2)(((c + 1) >> 1) & 1, (c >> 1) & 1);
}

/* The level-2 texel in the middle of side s of patch x, whose across table
 * entry is a: subdivide_edges' edge point of level 1, in x's frame. Its
 * row is x's corners s and s + 1, the row inside x's corners s + 3 and
 * s + 2, and the row across the corners sq + 2 and sq + 3 of the patch
 * across (side sq there). */
TEXEL_INLINE float4 first_side_point(ATLAS_IN src, int2 sg, int4 a, int x, int s)
{
  const int2 other = across_side(a, s);
  const int interior = other.x >= 0, q = max(other.x, 0), sq = other.y;
  const float4 r0 = ATLAS_LOAD(src, sg, x, first_corner(s)), r1 = ATLAS_LOAD(src, sg, x, first_corner(s + 1));
  const float4 i0 = ATLAS_LOAD(src, sg, x, first_corner(s + 3)), i1 = ATLAS_LOAD(src, sg, x, first_corner(s + 2));
  const float4 o0 = interior ? ATLAS_LOAD(src, sg, q, first_corner(sq + 2)) : r0;
  const float4 o1 = interior ? ATLAS_LOAD(src, sg, q, first_corner(sq + 3)) : r1;
  return side_edge_point(r0, r1, i0, i1, o0, o1, interior);
}

/* The steps 1 -> 2 and 2 -> 3, which every atlas takes, as a work item per
 * patch (CPUs) that walks its own sides too: the tiles are small there
 * (2 x 2, 3 x 3 old texels), so a fixed-size walk keeps every index a
 * constant and the tile in registers, and no side kernel runs or writes
 * the compact arrays. Both patches of a side compute it, to the same bits
 * (side_edge_point() and side_vertex_point() are symmetric); corners come
 * from corners[corner_base + ring] as in subdivide_patches. Each texel has
 * the bits subdivide_edges and subdivide_patches give it.
 *
 * Range: patches; level 1 or 2 src into the next level dst. */

/* The step 1 -> 2 of patch p, each new texel ij given to EMIT(ij, value):
 * its corners and the middles of its sides, then the face point. Shared
 * with subdivide_decode_first (detail.cl), as SECOND_STEP_TILE() below. */
#define FIRST_STEP_TILE(src, sg, p, pr, pa, corners, corner_base, EMIT)                                     \
  do {                                                                                                       \
    _Pragma("unroll") for (int c = 0; c < 4; ++c)                                                            \
    {                                                                                                        \
      const int2 at = kCornerUnit[c] * 2;                                                                    \
      EMIT(at, corners[corner_base + int4_at(pr, c)]);                                                       \
      EMIT(at + kSideDir[c], first_side_point(src, sg, pa, p, c));                                           \
    }                                                                                                        \
    REFINE_INSIDE(face, 1, (int2)(1, 1), FIRST_STEP_OLD);                                                    \
    EMIT((int2)(1, 1), face);                                                                                \
  } while (0)
#define FIRST_STEP_OLD(i, j) ATLAS_LOAD(src, sg, p, (int2)((i), (j)))

__kernel void subdivide_first_step(ATLAS_IN src, ATLAS_OUT dst, int2 sg, int2 dg, __global const int *list,
                                   int patches, __global const uchar *flags, int generation,
                                   __global const int4 *restrict patch_rings,
                                   __global const int4 *restrict patch_across,
                                   __global const float4 *restrict corners, int corner_base)
{
  PATCH_ITEM(list, patches, SUBDIVIDE_SKIP);
  const int4 pr = patch_rings[p], pa = patch_across[p];
  PREFETCH_ACROSS_AHEAD(src, sg, patch_across, list, item, patches);
#define FIRST_STEP_STORE(ij, v) ATLAS_STORE(dst, dg, p, ij, v)
  FIRST_STEP_TILE(src, sg, p, pr, pa, corners, corner_base, FIRST_STEP_STORE);
#undef FIRST_STEP_STORE
}

/* The step 2 -> 3 of patch p as subdivide_second_step takes it, each new
 * texel ij given to EMIT(ij, value): corners, then each side, then the
 * inside. Shared with the kernel that decodes level 3 as it makes it
 * (subdivide_decode_second, detail.cl), so that both give the same bits. */
#define SECOND_STEP_TILE(src, sg, p, pr, pa, corners, corner_base, EMIT)                                          \
  do {                                                                                                             \
    float4 t2[3][3]; /* the old tile, [j][i] */                                                                    \
    _Pragma("unroll") for (int j = 0; j < 3; ++j)                                                                  \
    {                                                                                                              \
      _Pragma("unroll") for (int i = 0; i < 3; ++i) { t2[j][i] = ATLAS_LOAD(src, sg, p, (int2)(i, j)); }          \
    }                                                                                                              \
    _Pragma("unroll") for (int c = 0; c < 4; ++c) { EMIT(kCornerUnit[c] * 4, corners[corner_base + int4_at(pr, c)]); } \
    /* Each side from the old row along it, the row inside and the row                                            \
     * across, in the neighbour's tile. */                                                                         \
    _Pragma("unroll") for (int s = 0; s < 4; ++s)                                                                  \
    {                                                                                                              \
      const Frame f = side_frame(p, s, 2);                                                                         \
      float4 row[3], in[3], out[3];                                                                                \
      _Pragma("unroll") for (int t = 0; t < 3; ++t)                                                                \
      {                                                                                                            \
        const int2 r = f.o + t * f.dt, i = r + f.dd;                                                               \
        row[t] = t2[r.y][r.x];                                                                                     \
        in[t] = t2[i.y][i.x];                                                                                      \
      }                                                                                                            \
      const int2 other = across_side(pa, s);                                                                       \
      const int interior = other.x >= 0;                                                                           \
      const Frame fq = across_frame(max(other.x, 0), other.y, 2);                                                  \
      _Pragma("unroll") for (int t = 0; t < 3; ++t) { out[t] = interior ? FRAME_LOAD(src, sg, fq, t, -1) : row[t]; } \
      const Frame fn = side_frame(p, s, 4);                                                                        \
      const int2 a = fn.o + fn.dt, b = a + fn.dt, c = b + fn.dt;                                                   \
      EMIT(a, side_edge_point(row[0], row[1], in[0], in[1], out[0], out[1], interior));                            \
      EMIT(b, side_vertex_point(row[0], row[1], row[2], in[0], in[1], in[2], out[0], out[1], out[2], interior));   \
      EMIT(c, side_edge_point(row[1], row[2], in[1], in[2], out[1], out[2], interior));                            \
    }                                                                                                              \
    _Pragma("unroll") for (int j = 1; j < 4; ++j)                                                                  \
    {                                                                                                              \
      _Pragma("unroll") for (int i = 1; i < 4; ++i)                                                                \
      {                                                                                                            \
        REFINE_INSIDE(v, 2, (int2)(i, j), SECOND_STEP_OLD);                                                        \
        EMIT((int2)(i, j), v);                                                                                     \
      }                                                                                                            \
    }                                                                                                              \
  } while (0)
#define SECOND_STEP_OLD(i, j) t2[j][i]

__kernel void subdivide_second_step(ATLAS_IN src, ATLAS_OUT dst, int2 sg, int2 dg, __global const int *list,
                                    int patches, __global const uchar *flags, int generation,
                                    __global const int4 *restrict patch_rings,
                                    __global const int4 *restrict patch_across,
                                    __global const float4 *restrict corners, int corner_base)
{
  PATCH_ITEM(list, patches, SUBDIVIDE_SKIP);
  const int4 pr = patch_rings[p], pa = patch_across[p];
  PREFETCH_ACROSS_AHEAD(src, sg, patch_across, list, item, patches);
#define SECOND_STEP_STORE(ij, v) ATLAS_STORE(dst, dg, p, ij, v)
  SECOND_STEP_TILE(src, sg, p, pr, pa, corners, corner_base, SECOND_STEP_STORE);
#undef SECOND_STEP_STORE
}
