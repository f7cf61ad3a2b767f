/* Gaussian reduction of the atlas, level l+1 -> l (2n -> n quads per patch
 * side): the paper's subsampling operator. Each kept texel is the binomial
 * (1,4,6,4,1)/16 average of its level-l+1 neighbourhood in both directions;
 * windows cross patch sides through the edge table. Mesh-boundary curves are
 * reduced along themselves only, sharp corners are kept, and an extraordinary
 * corner spreads the regular ring weights evenly over its n sectors.
 * sg, dg: grids (tile, tiles_x) of the source (finer) and destination levels. */

#define BINOMIAL5(k) ((k) == 0 ? 0.375f : ((k) == 1 || (k) == -1) ? 0.25f : 0.0625f)

/* A ring's interior corner weighs, per slot, the texels of that slot's
 * sector: its outgoing axis and the texels between the two axes, as the
 * separable filter would. */
#define SECTOR_SUM(LOAD) \
  (24.0f * LOAD(1, 0) + 6.0f * LOAD(2, 0) + 16.0f * LOAD(1, 1) + 4.0f * (LOAD(2, 1) + LOAD(1, 2)) + LOAD(2, 2))

/* Texel ij strictly inside patch p at the destination level. */
TEXEL_INLINE float4 reduced_inside(ATLAS_IN src, int2 sg, int p, int2 ij)
{
  float4 acc = (float4)(0.0f);
  for (int b = -2; b <= 2; ++b) {
    float4 row = (float4)(0.0f);
    for (int a = -2; a <= 2; ++a)
      row += BINOMIAL5(a) * ATLAS_LOAD(src, sg, p, 2 * ij + (int2)(a, b));
    acc += BINOMIAL5(b) * row;
  }
  return acc;
}

/* Range: (dst n - 1, (dst n - 1) * patches); texels strictly inside patches. */
__kernel void reduce_interior(ATLAS_IN src, ATLAS_OUT dst, int2 sg, int2 dg, int patches)
{
  int p;
  int2 ij;
  if (interior_texel(dg, 0, patches, &p, &ij))
    ATLAS_STORE(dst, dg, p, ij, reduced_inside(src, sg, p, ij));
}

/* Into acc: texel t along a patch side, corners excluded, from the source
 * level around it (the frames of EDGE_FRAMES); lo = -2 with a patch
 * across, 0 on a mesh boundary. */
#define REDUCE_SIDE_TEXEL(acc, src, sg, lo, t)                     \
  do {                                                            \
    acc = (float4)(0.0f);                                         \
    for (int b = (lo); b <= -(lo); ++b) {                         \
      float4 row = (float4)(0.0f);                                \
      for (int a = -2; a <= 2; ++a)                               \
        row += BINOMIAL5(a) * EDGE_LOAD(src, sg, 2 * (t) + a, b); \
      acc += ((lo) < 0 ? BINOMIAL5(b) : 1.0f) * row;              \
    }                                                             \
  } while (0)

/* Range: (n - 1, #edges); texels on patch sides, corners excluded. */
__kernel void reduce_edges(ATLAS_IN src, ATLAS_OUT dst, __global const PatchEdge *edges,
                           int edge_count, int2 sg, int2 dg)
{
  const int t = get_global_id(0) + 1, k = get_global_id(1);
  if (k >= edge_count || t >= dg.x - 1)
    return;
  const PatchEdge e = edges[k];
  EDGE_FRAMES(e, sg);
  float4 acc;
  REDUCE_SIDE_TEXEL(acc, src, sg, e.patch[1] >= 0 ? -2 : 0, t);
  EDGE_STORE(dst, dg, e, t, acc);
}

/* CPUs, whose work items run one after another, take the reduction as the
 * subdivision does: the sides and corners into compact arrays (a work item
 * per edge walking it, its frames set up once and the tiles of an edge
 * further on asked for ahead; a work item per ring), then each destination
 * tile written whole by one work item (reduce_patches), its border copied
 * from there, instead of every copy stored into its tile where it lies. */

/* Range: #edges; into sides[edge * (dst n - 1) + t - 1], t along the edge's
 * first patch's side. */
__kernel void reduce_edge_walks(ATLAS_IN src, __global float4 *restrict sides, __global const PatchEdge *edges,
                                int edge_count, int2 sg, int2 dg)
{
  const int k = get_global_id(0);
  if (k >= edge_count)
    return;
  const PatchEdge e = edges[k];
  PREFETCH_EDGE_AHEAD(src, sg, edges, (__global const int *)0, k, edge_count);
  EDGE_FRAMES(e, sg);
  const int lo = e.patch[1] >= 0 ? -2 : 0;
  const int first = k * (dg.x - 2) - 1;
  for (int t = 1; t < dg.x - 1; ++t) {
    float4 acc;
    REDUCE_SIDE_TEXEL(acc, src, sg, lo, t);
    sides[first + t] = acc;
  }
}

/* Range: count; every patch's destination tile. */
__kernel void reduce_patches(ATLAS_IN src, ATLAS_OUT dst, int2 sg, int2 dg, int count,
                             __global const int4 *restrict patch_sides, __global const int4 *restrict patch_rings,
                             __global const float4 *restrict sides, __global const float4 *restrict corners)
{
#define REDUCE_COPY(ij, k, corner, bit) ATLAS_STORE(dst, dg, p, ij, (corner) ? corners[k] : sides[k])
#define REDUCE_INSIDE(ij) ATLAS_STORE(dst, dg, p, ij, reduced_inside(src, sg, p, ij))
  PATCH_ITEM_PARTS(dg, (__global const int *)0, count, NO_SKIP, patch_sides, patch_rings, REDUCE_COPY, REDUCE_INSIDE);
#undef REDUCE_INSIDE
#undef REDUCE_COPY
}

/* The step from level 3 to level 2 (4 x 4 to 2 x 2 quads per patch), which
 * every atlas at level 3 takes when it encodes details, as a work item per
 * patch that reduces its own sides too: a destination tile has one texel
 * inside and one in the middle of each side. Each of those five texels is
 * a chain of thirty dependent additions; a work item per edge or per patch
 * waits on its chain's latency, while here the five chains advance
 * together. Both patches of an edge compute its side texel in the edge's
 * frames, with REDUCE_SIDE_TEXEL's operations in its order, so both copies
 * have the bits reduce_edge_walks gives; corners come from corners[ring]
 * (reduce_corners).
 *
 * Range: count; every patch. */
__kernel void reduce_second_step(ATLAS_IN src, ATLAS_OUT dst, int2 sg, int2 dg, int count,
                                 __global const int4 *restrict patch_sides, __global const int4 *restrict patch_rings,
                                 __global const int4 *restrict patch_across, __global const PatchEdge *edges,
                                 __global const float4 *restrict corners, __global const int4 *restrict patch_slots,
                                 __global float4 *restrict sectors)
{
  PATCH_ITEM((__global const int *)0, count, NO_SKIP);
  const int4 ps = patch_sides[p], pr = patch_rings[p];
  PREFETCH_ACROSS_AHEAD(src, sg, patch_across, (__global const int *)0, item, count);
  FrameSteps fp[4], fq[4];
  int lo[4];
#pragma unroll
  for (int s = 0; s < 4; ++s) {
    const PatchEdge e = edges[int4_at(ps, s) >> 1];
    fp[s] = frame_steps(sg, side_frame(e.patch[0], e.side[0], 4));
    fq[s] = frame_steps(sg, across_frame(max(e.patch[1], 0), e.side[1], 4)); /* read only with a patch across */
    lo[s] = e.patch[1] >= 0 ? -2 : 0;
  }
  float4 acc[5]; /* the sides, then the inside */
#pragma unroll
  for (int k = 0; k < 5; ++k)
    acc[k] = (float4)(0.0f);
#pragma unroll
  for (int b = -2; b <= 2; ++b) {
    float4 row[5];
#pragma unroll
    for (int k = 0; k < 5; ++k)
      row[k] = (float4)(0.0f);
#pragma unroll
    for (int a = -2; a <= 2; ++a) {
#pragma unroll
      for (int s = 0; s < 4; ++s)
        row[s] += BINOMIAL5(a) * (b >= 0 ? STEPS_LOAD(src, fp[s], 2 + a, b) : STEPS_LOAD(src, fq[s], 2 + a, b));
      row[4] += BINOMIAL5(a) * ATLAS_LOAD(src, sg, p, (int2)(2 + a, 2 + b));
    }
#pragma unroll
    for (int s = 0; s < 4; ++s)
      if (b >= lo[s] && b <= -lo[s])
        acc[s] += (lo[s] < 0 ? BINOMIAL5(b) : 1.0f) * row[s];
    acc[4] += BINOMIAL5(b) * row[4];
  }
  float4 corner[4];
#pragma unroll
  for (int c = 0; c < 4; ++c) {
    const Frame f = side_frame(p, c, 2);
    corner[c] = corners[int4_at(pr, c)];
    ATLAS_STORE(dst, dg, p, f.o, corner[c]);
    ATLAS_STORE(dst, dg, p, f.o + f.dt, acc[c]);
  }
  ATLAS_STORE(dst, dg, p, (int2)(1, 1), acc[4]);
  if (!sectors)
    return;
  /* The step on to level 1 (reduce_corners) reads the sectors of this
   * 3 x 3 tile, as reduce_sectors would take them from it: seen from
   * corner c, (1, 0) is the middle of side c, (2, 0) the next corner, (2, 1)
   * the middle of side c + 1 and (1, 2) of side c + 2. */
  const int4 at = patch_slots[p];
#pragma unroll
  for (int c = 0; c < 4; ++c) {
#define TILE_TEXEL(a, b)                                                                                  \
  ((a) == 1 && (b) == 0   ? acc[c]                                                                        \
   : (a) == 2 && (b) == 0 ? corner[(c + 1) & 3]                                                           \
   : (a) == 1 && (b) == 1 ? acc[4]                                                                        \
   : (a) == 2 && (b) == 1 ? acc[(c + 1) & 3]                                                              \
   : (a) == 1 && (b) == 2 ? acc[(c + 2) & 3]                                                              \
                          : corner[(c + 2) & 3])
    sectors[int4_at(at, c)] = SECTOR_SUM(TILE_TEXEL);
#undef TILE_TEXEL
  }
}

/* Range: count; every patch. Its four sectors, each into
 * sectors[patch_slots[p][c]]: the slots of a ring lie in a row in the
 * order reduce_corners sums them, so that it reads them in order instead
 * of gathering a tile per slot. */
__kernel void reduce_sectors(ATLAS_IN src, int2 sg, int count, __global const int4 *restrict patch_slots,
                             __global float4 *restrict sectors)
{
  PATCH_ITEM((__global const int *)0, count, NO_SKIP);
  const int4 at = patch_slots[p];
#pragma unroll
  for (int c = 0; c < 4; ++c) {
    const FrameSteps f = frame_steps(sg, side_frame(p, c, sg.x - 1));
#define SECTOR_LOAD(a, b) STEPS_LOAD(src, f, a, b)
    sectors[int4_at(at, c)] = SECTOR_SUM(SECTOR_LOAD);
#undef SECTOR_LOAD
  }
}

/* Range: #rings; each ring's corner into corners[ring], or with `corners`
 * null every copy of it into its tile. With `sectors` (reduce_sectors or
 * reduce_second_step) an interior ring sums those instead of its slots'
 * tiles. With `corners_known`, corners[ring] holds the source level's
 * corner on entry (the step before made it, and its tiles hold copies):
 * read in order there instead of gathered from a tile, and overwritten. */
__kernel void reduce_corners(ATLAS_IN src, ATLAS_OUT dst, __global const CornerRing *rings,
                             __global const CornerSlot *slots, int ring_count, int2 sg, int2 dg,
                             __global float4 *restrict corners, __global const float4 *restrict sectors,
                             int corners_known)
{
  const int k = get_global_id(0);
  if (k >= ring_count)
    return;
  const CornerRing ring = rings[k];
  if (!sectors)
    PREFETCH_RING_AHEAD(src, sg, rings, slots, (__global const int *)0, k, ring_count);
  const CornerSlot first = slots[ring.first], last = slots[ring.first + ring.count - 1];
  const float4 v = corners_known ? corners[k] : CORNER_LOAD(src, sg, first, 0, 0);
  float4 r;
  if (ring.boundary) {
    r = ring.count == 1
          ? v
          : 0.375f * v +
              0.25f * (CORNER_LOAD(src, sg, first, 1, 0) + CORNER_LOAD(src, sg, last, 0, 1)) +
              0.0625f * (CORNER_LOAD(src, sg, first, 2, 0) + CORNER_LOAD(src, sg, last, 0, 2));
  } else {
    float4 sum = (float4)(0.0f);
    for (int m = 0; m < ring.count; ++m) {
      const CornerSlot s = slots[ring.first + m];
#define SECTOR_LOAD(a, b) CORNER_LOAD(src, sg, s, a, b)
      sum += sectors ? sectors[ring.first + m] : SECTOR_SUM(SECTOR_LOAD);
#undef SECTOR_LOAD
    }
    r = (36.0f * v + (4.0f / (float)ring.count) * sum) * (1.0f / 256.0f);
  }
  if (corners) {
    corners[k] = r;
    return;
  }
  for (int m = 0; m < ring.count; ++m)
    CORNER_STORE(dst, dg, slots[ring.first + m], r);
}
