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

/* Range: count; the same with a work item per patch walking its tile
 * (FOR_EACH_TILE_PART, whose entries into compact arrays go unused), and
 * the tile's tile_extent() into `extent` (unless null) while it is in the
 * cache, instead of patch_extent's pass over the level. */
__kernel void encode_patches(ATLAS_IN fine, ATLAS_IN smooth, int2 g, int count, __global const uchar *restrict owned,
                             __global float4 *details, __global float *restrict extent)
{
  const int p = get_global_id(0);
  if (p >= count)
    return;
  const int n = g.x - 1, own = owned[p];
  const int4 unused = (int4)(0);
#define ENCODE_BORDER(ij, k, corner, bit)             \
  do {                                                \
    if (own & (bit))                                  \
      encode_texel(fine, smooth, g, p, ij, details);  \
  } while (0)
#define ENCODE_INSIDE(ij) encode_texel(fine, smooth, g, p, ij, details)
  FOR_EACH_TILE_PART(n, unused, unused, ENCODE_BORDER, ENCODE_INSIDE);
#undef ENCODE_INSIDE
#undef ENCODE_BORDER
  if (extent)
    extent[p] = tile_extent(fine, g, p);
}

/* U + frame(U) details at texel ij of patch p. */
TEXEL_INLINE float4 with_detail(ATLAS_IN smooth, int2 g, int p, int2 ij, __global const float4 *details, float3 t,
                                float3 b, float3 n)
{
  const float4 s = ATLAS_LOAD(smooth, g, p, ij);
  const float4 d = details[PATCH_MAJOR_INDEX(g, p, ij)];
  return (float4)(s.xyz + (d.x * t + d.y * b + d.z * n), s.w);
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

/* Range: count. tile_extent() of each listed patch (null: every patch). */
__kernel void patch_extent(ATLAS_IN pos, int2 g, __global const int *list, int count, __global float *out)
{
  const int k = get_global_id(0);
  if (k >= count)
    return;
  out[k] = tile_extent(pos, g, LISTED(list, k));
}
