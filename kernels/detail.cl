/* Multiresolution editing (Ritschel et al. 2006, section 6, after Zorin et
 * al. 1997): the finest level S is kept as a smooth surface U = up(down(S))
 * plus details S - U, stored as coordinates in a local frame of U (a normal,
 * a tangent and the bitangent), so that they follow when U moves.
 * Details are per texel, patch-major. Every stored copy of a side or corner
 * texel decodes in one frame (the first patch's), so the copies stay equal. */

/* Orthonormal frame from differences d0, d1 of control points along the
 * two patch parameters: n across them, t along the first parameter, b =
 * n x t. Where they are degenerate: n = z, and t the first direction with
 * n taken out, else the second, else any across n. */
TEXEL_INLINE void frame_of(float3 d0, float3 d1, float3 *t, float3 *b, float3 *n)
{
  const float3 c = cross(d0, d1);
  const float2 squares = (float2)(dot(c, c), dot(d0, d0));
  if (squares.x > 1e-30f && squares.y > 1e-30f) {
    /* c is across d0 already, so t needs nothing taken out: both lengths
     * in one vector rsqrt, t not waiting on n (the two divisions, one
     * after the other, had been about a third of decoding's time). */
    const float2 inverse = rsqrt(squares);
    *n = c * inverse.x;
    *t = d0 * inverse.y;
    *b = cross(*n, *t);
    return;
  }
  *n = squares.x > 1e-30f ? normalize(c) : (float3)(0.0f, 0.0f, 1.0f);
  float3 u = d0 - dot(d0, *n) * *n;
  if (!(dot(u, u) > 1e-30f))
    u = d1 - dot(d1, *n) * *n;
  if (!(dot(u, u) > 1e-30f)) /* a collapsed tile: any direction across the normal */
    u = fabs((*n).x) < 0.9f ? (float3)(1.0f, 0.0f, 0.0f) - (*n).x * *n : (float3)(0.0f, 1.0f, 0.0f) - (*n).y * *n;
  *t = normalize(u);
  *b = cross(*n, *t);
}

/* The frame of texel ij of patch p from the control points around it in
 * its tile (one-sided differences at the tile's border). Only the
 * smooth surface U is framed, and each texel is encoded and decoded in the
 * frame of one tile, so a frame need not agree across tiles: it must only
 * turn with the surface. */
TEXEL_INLINE void detail_frame(ATLAS_IN pos, int2 g, int p, int2 ij, float3 *t, float3 *b, float3 *n)
{
  /* Named values, not an array: PoCL keeps private arrays in memory, a
   * copy per work item. */
  const int2 last = (int2)(g.x - 1);
#define DIFF(step) \
  (ATLAS_LOAD(pos, g, p, min(ij + (step), last)).xyz - ATLAS_LOAD(pos, g, p, max(ij - (step), (int2)(0))).xyz)
  frame_of(DIFF((int2)(1, 0)), DIFF((int2)(0, 1)), t, b, n);
#undef DIFF
}

/* detail_frame() of a texel strictly inside its tile, whose differences
 * need no clamping: the same values, with the loads spelt out. */
TEXEL_INLINE void inside_frame(ATLAS_IN pos, int2 g, int p, int2 ij, float3 *t, float3 *b, float3 *n)
{
  frame_of(ATLAS_LOAD(pos, g, p, ij + (int2)(1, 0)).xyz - ATLAS_LOAD(pos, g, p, ij - (int2)(1, 0)).xyz,
           ATLAS_LOAD(pos, g, p, ij + (int2)(0, 1)).xyz - ATLAS_LOAD(pos, g, p, ij - (int2)(0, 1)).xyz, t, b, n);
}

/* details = frame(U)^T (S - U) at texel ij of patch p. */
TEXEL_INLINE void encode_texel(ATLAS_IN fine, ATLAS_IN smooth, int2 g, int p, int2 ij, __global float4 *details)
{
  const int last = g.x - 1;
  float3 t, b, n;
  if (ij.x > 0 && ij.x < last && ij.y > 0 && ij.y < last)
    inside_frame(smooth, g, p, ij, &t, &b, &n);
  else
    detail_frame(smooth, g, p, ij, &t, &b, &n);
  const float3 d = ATLAS_LOAD(fine, g, p, ij).xyz - ATLAS_LOAD(smooth, g, p, ij).xyz;
  details[PATCH_MAJOR_INDEX(g, p, ij)] = (float4)(dot(d, t), dot(d, b), dot(d, n), 0.0f);
}

/* Longest grid edge of patch p's tile, to measure how far an edit
 * stretches the sampling. Squared lengths, one square root at the end;
 * along each row, then between each row and the one before it. */
TEXEL_INLINE float tile_extent(ATLAS_IN pos, int2 g, int p)
{
  float longest = 0.0f;
  for (int j = 0; j < g.x; ++j)
    for (int i = 1; i < g.x; ++i) {
      const float3 along = ATLAS_LOAD(pos, g, p, (int2)(i, j)).xyz - ATLAS_LOAD(pos, g, p, (int2)(i - 1, j)).xyz;
      const float3 across = ATLAS_LOAD(pos, g, p, (int2)(j, i)).xyz - ATLAS_LOAD(pos, g, p, (int2)(j, i - 1)).xyz;
      longest = max(longest, max(dot(along, along), dot(across, across))); /* finite: see tile_bounds() */
    }
  return sqrt(longest);
}

/* Decoding reads a side's details in its edge's first patch only, and a
 * corner's in its ring's first slot (decode_edges, decode_corners): the
 * other copies are never read and are not encoded (they hold 0, as the
 * buffer was filled). `owned` per patch: the texel_border() bits of the
 * parts it decodes, the sides and corners; the inside is always its own. */
inline int part_bit(int2 ij, int n)
{
  const int part = tile_part(ij, n);
  return part >= UNFOLD_CORNER ? 16 << (part - UNFOLD_CORNER) : part >= UNFOLD_SIDE ? 1 << (part - UNFOLD_SIDE) : 0;
}

/* Range: (tile, tile * count), every patch. */
__kernel void encode_details(ATLAS_IN fine, ATLAS_IN smooth, int2 g, int count, __global const uchar *restrict owned,
                             __global float4 *details)
{
  int p;
  int2 ij;
  if (!tile_texel(g, 0, count, &p, &ij))
    return;
  const int bit = part_bit(ij, g.x - 1);
  if (bit == 0 || (owned[p] & bit))
    encode_texel(fine, smooth, g, p, ij, details);
}

/* encode_patches runs a work item per eight patches, a patch per lane
 * (lanes.cl): float3 arithmetic keeps a texel's three components in one
 * register and spends most of its time shuffling them. A tile's texels
 * come in the same order in every lane, so each lane's texel has the same
 * neighbours and the same owner bit. Each lane does what encode_texel()
 * and tile_extent() do, operation for operation (rsqrt(), sqrt() and the
 * sums of cross() and dot() are the same per lane, and the extent is a
 * maximum of finite values, whose order does not matter), so the results
 * are the same bits; a lane whose frame is degenerate is encoded by
 * encode_texel() itself. */

/* Range: count / PATCH_LANES rounded up; encode_details' texels, a work
 * item per eight patches walking their tiles together, and each tile's
 * tile_extent() into `extent` (unless null) while it is in the cache,
 * instead of patch_extent's pass over the level. */
__kernel void encode_patches(ATLAS_IN fine, ATLAS_IN smooth, int2 g, int count, __global const uchar *restrict owned,
                             __global float4 *details, __global float *restrict extent)
{
  const int first = get_global_id(0) * PATCH_LANES;
  if (first >= count)
    return;
  const int8 lane = (int8)(0, 1, 2, 3, 4, 5, 6, 7);
  const int8 valid = first + lane < count;
  const int8 patch = min(first + lane, (int8)(count - 1)); /* lanes past the end repeat the last */
  const int8 own = (int8)(owned[patch.s0], owned[patch.s1], owned[patch.s2], owned[patch.s3], owned[patch.s4],
                          owned[patch.s5], owned[patch.s6], owned[patch.s7]);
  const int n = g.x - 1;
  float8 longest = (float8)(0.0f);
  for (int j = 0; j <= n; ++j) {
    /* Along the row, the smooth texels left, here and right move on by one. */
    Lanes here = load_lanes(smooth, g, patch, (int2)(0, j)), left = here;
    Lanes fine_left = here; /* read from i = 1 on, after it is set */
    for (int i = 0; i <= n; ++i) {
      const int2 ij = (int2)(i, j);
      const Lanes right = i < n ? load_lanes(smooth, g, patch, (int2)(i + 1, j)) : here;
      const Lanes fine_here = load_lanes(fine, g, patch, ij);
      /* tile_extent(): the grid edges to the left and below. */
      if (i > 0) {
        const Lanes along = lanes_sub(fine_here, fine_left);
        longest = max(longest, lanes_dot(along, along));
      }
      if (j > 0) {
        const Lanes across = lanes_sub(fine_here, load_lanes(fine, g, patch, (int2)(i, j - 1)));
        longest = max(longest, lanes_dot(across, across));
      }
      const int bit = part_bit(ij, n);
      const int8 owner = bit == 0 ? (int8)(-1) : (own & bit) != 0, stored = valid & owner;
      if (any(stored)) {
        /* detail_frame()'s clamped differences, frame_of()'s usual case. */
        const Lanes up = j < n ? load_lanes(smooth, g, patch, (int2)(i, j + 1)) : here;
        const Lanes down = j > 0 ? load_lanes(smooth, g, patch, (int2)(i, j - 1)) : here;
        const Lanes d0 = lanes_sub(right, left), d1 = lanes_sub(up, down);
        const Lanes c = lanes_cross(d0, d1);
        const float8 squares_c = lanes_dot(c, c), squares_d0 = lanes_dot(d0, d0);
        const int8 usual = squares_c > 1e-30f && squares_d0 > 1e-30f;
        const Lanes nrm = lanes_scale(c, rsqrt(squares_c));
        const Lanes tan = lanes_scale(d0, rsqrt(squares_d0));
        const Lanes bin = lanes_cross(nrm, tan);
        const Lanes d = lanes_sub(fine_here, here);
        /* Every lane's texel stored in one go, a copy that another patch
         * holds as the 0 it already has; lanes past the end repeat the
         * last patch's values. Degenerate frames are then done again. */
        const float8 zero = (float8)(0.0f);
        store_lanes(details, g, patch, ij, select(zero, lanes_dot(d, tan), owner),
                    select(zero, lanes_dot(d, bin), owner), select(zero, lanes_dot(d, nrm), owner));
        const int8 again = stored & ~usual;
        if (any(again)) {
          int redo[PATCH_LANES], pa[PATCH_LANES];
          vstore8(again, 0, redo);
          vstore8(patch, 0, pa);
          for (int l = 0; l < PATCH_LANES; ++l)
            if (redo[l])
              encode_texel(fine, smooth, g, pa[l], ij, details);
        }
      }
      left = here;
      here = right;
      fine_left = fine_here;
    }
  }
  if (extent) {
    float reach[PATCH_LANES];
    vstore8(sqrt(longest), 0, reach);
    for (int l = 0; l < PATCH_LANES && first + l < count; ++l)
      extent[first + l] = reach[l];
  }
}

/* s + the details d in the frame (t, b, n). */
inline float4 detailed(float4 s, float4 d, float3 t, float3 b, float3 n)
{
  return (float4)(s.xyz + (d.x * t + d.y * b + d.z * n), s.w);
}

/* U + frame(U) details at texel ij of patch p. */
TEXEL_INLINE float4 with_detail(ATLAS_IN smooth, int2 g, int p, int2 ij, __global const float4 *details, float3 t,
                                float3 b, float3 n)
{
  return detailed(ATLAS_LOAD(smooth, g, p, ij), details[PATCH_MAJOR_INDEX(g, p, ij)], t, b, n);
}

TEXEL_INLINE float4 decoded(ATLAS_IN smooth, int2 g, int p, int2 ij, __global const float4 *details)
{
  float3 t, b, n;
  detail_frame(smooth, g, p, ij, &t, &b, &n);
  return with_detail(smooth, g, p, ij, details, t, b, n);
}

/* decoded() for a texel strictly inside its tile. */
TEXEL_INLINE float4 decoded_inside(ATLAS_IN smooth, int2 g, int p, int2 ij, __global const float4 *details)
{
  float3 t, b, n;
  inside_frame(smooth, g, p, ij, &t, &b, &n);
  return with_detail(smooth, g, p, ij, details, t, b, n);
}

/* Decoding reads U from a layer of the finest level's layout and writes
 * into the finest level, which holds S: the texels of the listed patches,
 * sides and corners are rebuilt; the rest keep S. The side and corner
 * kernels fill compact arrays (border_entry()), and decode_tiles (or
 * decode_patches) writes the tiles, each cache line by one kernel: the
 * listed patches' texels, but not those on the sides and corners in
 * `outside` (per listed patch, bits as texel_border()): shared with unlisted
 * patches, they keep S. */

/* Texel ij of patch p on a side or corner, the item-th listed: entry k of
 * `corners` or `sides`, unless the part (bit) is shared with an unlisted
 * patch. */
#define DECODE_COPY(ij, k, corner, bit)                                  \
  do {                                                                   \
    if (!(outside[item] & (bit)))                                           \
      ATLAS_STORE(fine, g, p, ij, (corner) ? corners[k] : sides[k]);     \
  } while (0)
#define DECODE_INSIDE(ij) ATLAS_STORE(fine, g, p, ij, decoded_inside(smooth, g, p, ij, details))

/* Range: (tile, tile * count). */
__kernel void decode_tiles(ATLAS_IN smooth, int2 g, __global const int *list, int count,
                           __global const float4 *details, ATLAS_OUT fine, __global const int4 *restrict patch_sides,
                           __global const int4 *restrict patch_rings, __global const float4 *restrict sides,
                           __global const float4 *restrict corners, __global const uchar *restrict outside)
{
  TILE_TEXEL_PART(g, list, count, NO_SKIP, patch_sides, patch_rings, DECODE_COPY, DECODE_INSIDE);
}

/* Range: count; the same with a work item per patch walking its tile
 * (FOR_EACH_TILE_PART). */
__kernel void decode_patches(ATLAS_IN smooth, int2 g, __global const int *list, int count,
                             __global const float4 *details, ATLAS_OUT fine, __global const int4 *restrict patch_sides,
                             __global const int4 *restrict patch_rings, __global const float4 *restrict sides,
                             __global const float4 *restrict corners, __global const uchar *restrict outside)
{
  PATCH_ITEM_PARTS(g, list, count, NO_SKIP, patch_sides, patch_rings, DECODE_COPY, DECODE_INSIDE);
}

/* Range: count; the listed patch sides into `sides`, in the first patch's
 * frame, one work item per side walking along it. */
__kernel void decode_edges(ATLAS_IN smooth, int2 g, __global const PatchEdge *edges,
                           __global const int *list, int count, __global const float4 *details,
                           __global float4 *restrict sides)
{
  const int k = get_global_id(0);
  if (k >= count)
    return;
  const int edge = list[k];
  const PatchEdge e = edges[edge];
  if (k + PREFETCH_AHEAD < count) {
    const int ahead = edges[list[k + PREFETCH_AHEAD]].patch[0];
    PREFETCH_TILE(smooth, g, ahead);
    PREFETCH_TILE(details, g, ahead);
  }
  const Frame f = side_frame(e.patch[0], e.side[0], g.x - 1);
  const int first = edge * (g.x - 2) - 1; /* texel t at first + t */
  for (int t = 1; t < g.x - 1; ++t)
    sides[first + t] = decoded(smooth, g, e.patch[0], f.o + t * f.dt, details);
}

/* Range: count; the listed corners into `corners`, in the first slot's frame. */
__kernel void decode_corners(ATLAS_IN smooth, int2 g, __global const CornerRing *rings,
                             __global const CornerSlot *slots, __global const int *list, int count,
                             __global const float4 *details, __global float4 *restrict corners)
{
  const int k = get_global_id(0);
  if (k >= count)
    return;
  const CornerRing ring = rings[list[k]];
  if (k + PREFETCH_AHEAD < count) {
    const CornerSlot ahead = slots[rings[list[k + PREFETCH_AHEAD]].first];
    const Frame f = side_frame(ahead.patch, ahead.corner, g.x - 1);
    PREFETCH_TEXEL(smooth, g, f.patch, f.o);
    PREFETCH_TEXEL(smooth, g, f.patch, f.o + f.dd);
    PREFETCH_TEXEL(details, g, f.patch, f.o);
  }
  const CornerSlot first = slots[ring.first];
  corners[list[k]] = decoded(smooth, g, first.patch, side_frame(first.patch, first.corner, g.x - 1).o, details);
}

/* Decoding as the last step of subdivision makes U (CPUs, a finest level
 * 2 or 3, a work item per listed patch): FIRST_STEP_TILE() or
 * SECOND_STEP_TILE() keeps the patch's tile of U in registers, and each
 * texel the patch decodes is decoded from there, so U never goes through
 * memory. A side or corner is decoded by the patch holding its details
 * (`owned`), which stores it into every tile holding a copy; the parts in
 * `outside` keep S. Each tile texel is stored by one work item, and gets
 * decoded()'s operations on the same values: the bits of decode_edges,
 * decode_corners and decode_patches. */

/* detail_frame() at texel (i, j) of a tile of n + 1 texels a side held as
 * u[j][i]: its clamped differences. */
#define TILE_FRAME(u, n, i, j, t, b, nrm)                                                                   \
  frame_of((u)[j][min((i) + 1, (n))].xyz - (u)[j][max((i) - 1, 0)].xyz,                                    \
           (u)[min((j) + 1, (n))][i].xyz - (u)[max((j) - 1, 0)][i].xyz, (t), (b), (nrm))

/* decoded() at texel (i, j) of such a tile. */
TEXEL_INLINE float4 tile_decoded(float4 u[5][5], int n, int i, int j, __global const float4 *details, int2 g, int p)
{
  float3 t, b, nrm;
  TILE_FRAME(u, n, i, j, &t, &b, &nrm);
  return detailed(u[j][i], details[PATCH_MAJOR_INDEX(g, p, (int2)(i, j))], t, b, nrm);
}

/* The start of such a kernel: patch p (the item-th listed) and its tile
 * of U made by STEP_TILE in u[j][i]. */
#define TILE_OF_U(list, STEP_TILE)                                                               \
  PATCH_ITEM(list, count, NO_SKIP);                                                              \
  const int4 pr = patch_rings[p], pa = patch_across[p];                                          \
  PREFETCH_ACROSS_AHEAD(src, sg, patch_across, list, item, count);                               \
  float4 u[5][5];                                                                                \
  STEP_TILE(src, sg, p, pr, pa, corners, corner_base, KEEP_TEXEL)
#define KEEP_TEXEL(ij, v) u[(ij).y][(ij).x] = (v)

/* The texels ij = (i, j) of a tile of N + 1 a side, each with its
 * part_bit() `bit`; the loop's body follows. */
#define EACH_TILE_TEXEL(N)                                                                       \
  _Pragma("unroll") for (int j = 0; j <= (N); ++j)                                               \
    _Pragma("unroll") for (int i = 0, bit = part_bit((int2)(0, j), (N)); i <= (N);               \
                           ++i, bit = part_bit((int2)(i, j), (N)))

/* The kernel body for tiles of N + 1 texels a side made by STEP_TILE. */
#define SUBDIVIDE_DECODE(N, STEP_TILE)                                                           \
  TILE_OF_U(list, STEP_TILE);                                                                    \
  const int decodes = owned[p] & ~outside[item];                                                 \
  EACH_TILE_TEXEL(N)                                                                             \
  {                                                                                              \
    const int2 ij = (int2)(i, j);                                                                \
    if (bit != 0 && !(decodes & bit))                                                            \
      continue;                                                                                  \
    const float4 s = tile_decoded(u, (N), i, j, details, g, p);                                  \
    ATLAS_STORE(fine, g, p, ij, s);                                                              \
    if (bit >= 16) { /* a corner: the ring's other slots */                                      \
      const CornerRing ring = rings[int4_at(pr, tile_part(ij, (N)) - UNFOLD_CORNER)];            \
      for (int m = 1; m < ring.count; ++m) {                                                     \
        const CornerSlot o = slots[ring.first + m];                                              \
        ATLAS_STORE(fine, g, o.patch, kCornerUnit[o.corner] * (N), s);                           \
      }                                                                                          \
    } else if (bit != 0) { /* a side: the patch across, if any */                                \
      const int2 st = side_place(ij, (N)), other = across_side(pa, st.x);                        \
      if (other.x >= 0)                                                                          \
        FRAME_STORE(fine, g, across_frame(other.x, other.y, (N)), st.y, 0, s);                   \
    }                                                                                            \
  }

/* Range: count; src level 1 or 2, fine the next level (grid g). */
#define SUBDIVIDE_DECODE_ARGUMENTS                                                                                    \
  ATLAS_IN src, int2 sg, int2 g, __global const int *list, int count, __global const int4 *restrict patch_rings,     \
    __global const int4 *restrict patch_across, __global const float4 *restrict corners, int corner_base,            \
    __global const float4 *restrict details, ATLAS_OUT fine, __global const CornerRing *restrict rings,              \
    __global const CornerSlot *restrict slots, __global const uchar *restrict owned,                                  \
    __global const uchar *restrict outside
__kernel void subdivide_decode_first(SUBDIVIDE_DECODE_ARGUMENTS) { SUBDIVIDE_DECODE(2, FIRST_STEP_TILE) }
__kernel void subdivide_decode_second(SUBDIVIDE_DECODE_ARGUMENTS) { SUBDIVIDE_DECODE(4, SECOND_STEP_TILE) }

/* Encoding as the last step of subdivision, the same way (CPUs, a finest
 * level 2 or 3, a work item per patch): the tile of U stays in registers
 * and S is read once, so U never goes through memory. Each texel whose
 * details the patch holds (`owned`) gets encode_texel()'s operations on the
 * same values, and the copies held elsewhere are stored as the 0 they are
 * (as encode_patches stores them): encode_details' bits. Each tile's
 * tile_extent() goes into `extent` while the tile of S is in the cache. */
#define SUBDIVIDE_ENCODE(N, STEP_TILE)                                                           \
  TILE_OF_U((__global const int *)0, STEP_TILE);                                                 \
  const int own = owned[p];                                                                      \
  EACH_TILE_TEXEL(N)                                                                             \
  {                                                                                              \
    float4 e = (float4)(0.0f);                                                                   \
    if (bit == 0 || (own & bit)) {                                                               \
      float3 t, b, nrm;                                                                          \
      TILE_FRAME(u, (N), i, j, &t, &b, &nrm);                                                    \
      const float3 d = ATLAS_LOAD(fine, g, p, (int2)(i, j)).xyz - u[j][i].xyz;                   \
      e = (float4)(dot(d, t), dot(d, b), dot(d, nrm), 0.0f);                                     \
    }                                                                                            \
    details[PATCH_MAJOR_INDEX(g, p, (int2)(i, j))] = e;                                          \
  }                                                                                              \
  extent[p] = tile_extent(fine, g, p)

/* Range: count, every patch; src level 1 or 2, fine the next level (grid g). */
#define SUBDIVIDE_ENCODE_ARGUMENTS                                                                                    \
  ATLAS_IN src, int2 sg, int2 g, int count, __global const int4 *restrict patch_rings,                                \
    __global const int4 *restrict patch_across, __global const float4 *restrict corners, int corner_base,            \
    ATLAS_IN fine, __global const uchar *restrict owned, __global float4 *restrict details,                          \
    __global float *restrict extent
__kernel void subdivide_encode_first(SUBDIVIDE_ENCODE_ARGUMENTS) { SUBDIVIDE_ENCODE(2, FIRST_STEP_TILE); }
__kernel void subdivide_encode_second(SUBDIVIDE_ENCODE_ARGUMENTS) { SUBDIVIDE_ENCODE(4, SECOND_STEP_TILE); }

/* Range: count. tile_extent() of each listed patch (null: every patch). */
__kernel void patch_extent(ATLAS_IN pos, int2 g, __global const int *list, int count, __global float *out)
{
  const int k = get_global_id(0);
  if (k >= count)
    return;
  out[k] = tile_extent(pos, g, LISTED(list, k));
}
