/* Limit positions and limit normals of the Catmull-Clark surface at the
 * atlas's current level. Regular texels use the tensor-product B-spline limit
 * masks; patch corners use the masks for extraordinary, boundary and corner
 * vertices (the boundary cross tangents follow Biermann et al., as OpenSubdiv
 * does). Outputs: positions and unit normals, float4 with w = 0 for normals. */

/* The masks are separable: each row b of a 3x3 neighbourhood gives a
 * smoothed value s and a difference d along the first axis (limit_row),
 * and limit_rows_cross() combines three rows across. */
inline void limit_row(float4 left, float4 mid, float4 right, float4 *s, float4 *d)
{
  *s = (left + 4.0f * mid + right) * (1.0f / 6.0f);
  *d = (right - left) * 0.5f;
}

/* The limit point and the (unnormalised) normal, the cross product of the
 * two tangents. */
inline void limit_rows_cross(float4 s0, float4 s1, float4 s2, float4 d0, float4 d1, float4 d2, float4 *pos,
                             float3 *c)
{
  *pos = (s0 + 4.0f * s1 + s2) * (1.0f / 6.0f);
  const float4 du = (d0 + 4.0f * d1 + d2) * (1.0f / 6.0f);
  const float4 dv = (s2 - s0) * 0.5f;
  *c = cross(du.xyz, dv.xyz);
}

/* normalize() of four vectors, as float4 normals, with one vector square
 * root and one division for the four lengths: normalize() ends in the
 * same c * rsqrt(|c|^2) per lane, which is kept where |c|^2 is a normal
 * float (on every texel of a sound surface); elsewhere normalize()
 * itself. One square root and division per texel, with normalize()'s
 * tests, had been a sixth to a quarter of the limit kernels' time. */
TEXEL_INLINE void unit_normals4(float3 c0, float3 c1, float3 c2, float3 c3, float4 *n0, float4 *n1, float4 *n2,
                          float4 *n3)
{
  const float4 l2 = (float4)(dot(c0, c0), dot(c1, c1), dot(c2, c2), dot(c3, c3));
  const float4 inverse = rsqrt(l2);
  *n0 = (float4)(isnormal(l2.x) ? c0 * inverse.x : normalize(c0), 0.0f);
  *n1 = (float4)(isnormal(l2.y) ? c1 * inverse.y : normalize(c1), 0.0f);
  *n2 = (float4)(isnormal(l2.z) ? c2 * inverse.z : normalize(c2), 0.0f);
  *n3 = (float4)(isnormal(l2.w) ? c3 * inverse.w : normalize(c3), 0.0f);
}

/* A run of texels k = start .. end - 1 whose normals go four at a time
 * through unit_normals4() (a lone last texel, as at level 2, through
 * normalize() itself): NEXT(k, pos, c) makes texel k's position and
 * unnormalised normal (in order: a window may slide), STORE(k, pos, nrm)
 * writes it; the lanes past the end are neither made nor stored. */
#define IN_FOURS(start, end, NEXT, STORE)                                            \
  for (int k4_ = (start); k4_ < (end); k4_ += 4) {                                   \
    if (k4_ + 1 == (end)) { /* a last texel alone: normalize() */                     \
      float4 p_;                                                                     \
      float3 c_;                                                                     \
      NEXT(k4_, p_, c_);                                                             \
      STORE(k4_, p_, (float4)(normalize(c_), 0.0f));                                 \
      break;                                                                         \
    }                                                                                \
    const float3 unused_ = (float3)(0.0f, 0.0f, 1.0f);                               \
    float4 p0_, p1_ = (float4)(0.0f), p2_ = (float4)(0.0f), p3_ = (float4)(0.0f);    \
    float4 n0_, n1_, n2_, n3_;                                                       \
    float3 c0_, c1_ = unused_, c2_ = unused_, c3_ = unused_;                         \
    NEXT(k4_, p0_, c0_);                                                             \
    if (k4_ + 1 < (end))                                                             \
      NEXT(k4_ + 1, p1_, c1_);                                                       \
    if (k4_ + 2 < (end))                                                             \
      NEXT(k4_ + 2, p2_, c2_);                                                       \
    if (k4_ + 3 < (end))                                                             \
      NEXT(k4_ + 3, p3_, c3_);                                                       \
    unit_normals4(c0_, c1_, c2_, c3_, &n0_, &n1_, &n2_, &n3_);                       \
    STORE(k4_, p0_, n0_);                                                            \
    if (k4_ + 1 < (end))                                                             \
      STORE(k4_ + 1, p1_, n1_);                                                      \
    if (k4_ + 2 < (end))                                                             \
      STORE(k4_ + 2, p2_, n2_);                                                      \
    if (k4_ + 3 < (end))                                                             \
      STORE(k4_ + 3, p3_, n3_);                                                      \
  }

/* Limit point and unnormalised normal from a 3x3 neighbourhood in three
 * rows of three (across a0..a2, along m0..m2, inwards i0..i2), the first
 * axis running along a row and the second across the rows, a right-handed
 * frame (limit_window(): the normal normalised). Named
 * values, not arrays: PoCL kept a kernel's private arrays in memory, one
 * copy per work item, and the window's loads and stores through it were a
 * quarter of the side kernel's time. */
inline void limit_window_cross(float4 a0, float4 a1, float4 a2, float4 m0, float4 m1, float4 m2, float4 i0,
                               float4 i1, float4 i2, float4 *pos, float3 *c)
{
  float4 s0, s1, s2, d0, d1, d2;
  limit_row(a0, a1, a2, &s0, &d0);
  limit_row(m0, m1, m2, &s1, &d1);
  limit_row(i0, i1, i2, &s2, &d2);
  limit_rows_cross(s0, s1, s2, d0, d1, d2, pos, c);
}

inline void limit_window(float4 a0, float4 a1, float4 a2, float4 m0, float4 m1, float4 m2, float4 i0, float4 i1,
                         float4 i2, float4 *pos, float4 *nrm)
{
  float3 c;
  limit_window_cross(a0, a1, a2, m0, m1, m2, i0, i1, i2, pos, &c);
  *nrm = (float4)(normalize(c), 0.0f);
}

/* A mesh boundary's: the crease curve's limit from the row along (m) and a
 * B-spline cross tangent towards the row inwards (i); the normal
 * unnormalised. */
inline void limit_crease_cross(float4 m0, float4 m1, float4 m2, float4 i0, float4 i1, float4 i2, float4 *pos,
                               float3 *c)
{
  const float4 s0 = (m0 + 4.0f * m1 + m2) * (1.0f / 6.0f);
  const float4 s1 = (i0 + 4.0f * i1 + i2) * (1.0f / 6.0f);
  *pos = s0;
  *c = cross(((m2 - m0) * 0.5f).xyz, (s1 - s0).xyz);
}

/* Lists (patches, edges, rings) or flags (UNFLAGGED) select what to
 * update; neither: everything.
 * The side and corner kernels put their results in compact arrays (a pos,
 * nrm pair per item), which limit_tiles then copies into whole tiles: every
 * tile's cache lines are written once, by one kernel, instead of being
 * fetched and written back by each of three. */

/* Pair k of a compact array: position, normal. */
#define PAIR_STORE(a, k, pv, nv) \
  do {                           \
    (a)[2 * (k)] = (pv);         \
    (a)[2 * (k) + 1] = (nv);     \
  } while (0)

/* Texel ij strictly inside patch p, from its 3x3 neighbourhood. */
TEXEL_INLINE void limit_inside(ATLAS_IN src, ATLAS_OUT pos, ATLAS_OUT nrm, int2 g, int p, int2 ij)
{
#define AT(a, b) ATLAS_LOAD(src, g, p, ij + (int2)(a, b))
  float4 pv, nv;
  limit_window(AT(-1, -1), AT(0, -1), AT(1, -1), AT(-1, 0), AT(0, 0), AT(1, 0), AT(-1, 1), AT(0, 1), AT(1, 1), &pv,
               &nv);
#undef AT
  ATLAS_STORE(pos, g, p, ij, pv);
  ATLAS_STORE(nrm, g, p, ij, nv);
}

/* Every texel strictly inside patch p, column by column: walking down a
 * column, two of the three rows' sums carry over to the next texel (the
 * same sums, so the same bits as limit_inside()). */
TEXEL_INLINE void limit_inside_columns(ATLAS_IN src, ATLAS_OUT pos, ATLAS_OUT nrm, int2 g, int p)
{
  const int n = g.x - 1;
#define ROW_SUMS(i, j, s, d) \
  limit_row(ATLAS_LOAD(src, g, p, (int2)((i) - 1, j)), ATLAS_LOAD(src, g, p, (int2)(i, j)), \
            ATLAS_LOAD(src, g, p, (int2)((i) + 1, j)), &s, &d)
  /* Down a column, its normals four at a time (IN_FOURS). */
#define NEXT_TEXEL(j, pk, ck)                           \
  do {                                                  \
    ROW_SUMS(i, (j) + 1, s2, d2);                       \
    limit_rows_cross(s0, s1, s2, d0, d1, d2, &pk, &ck); \
    s0 = s1;                                            \
    s1 = s2;                                            \
    d0 = d1;                                            \
    d1 = d2;                                            \
  } while (0)
#define STORE_TEXEL(j, pk, nk)                   \
  do {                                           \
    ATLAS_STORE(pos, g, p, (int2)(i, j), pk);    \
    ATLAS_STORE(nrm, g, p, (int2)(i, j), nk);    \
  } while (0)
  for (int i = 1; i < n; ++i) {
    float4 s0, s1, s2, d0, d1, d2;
    ROW_SUMS(i, 0, s0, d0);
    ROW_SUMS(i, 1, s1, d1);
    IN_FOURS(1, n, NEXT_TEXEL, STORE_TEXEL);
  }
#undef STORE_TEXEL
#undef NEXT_TEXEL
#undef ROW_SUMS
}

/* Texel ij of patch p on a side or corner: entry k of `corners` or `sides`,
 * whose edges and rings must have been computed in this update. */
#define LIMIT_COPY(ij, k, corner, bit)                                        \
  do {                                                                        \
    __global const float4 *pair_ = ((corner) ? corners : sides) + 2 * (k);     \
    ATLAS_STORE(pos, g, p, ij, pair_[0]);                                     \
    ATLAS_STORE(nrm, g, p, ij, pair_[1]);                                     \
  } while (0)
#define LIMIT_INSIDE(ij) limit_inside(src, pos, nrm, g, p, ij)
#define LIMIT_SKIP(q) UNFLAGGED(flags, generation, q)

/* Bounding sphere (centre xyz, radius w) of the positions in patch p's
 * tile: the centre of their box, and one square root per patch. min/max,
 * not fmin/fmax: positions are finite, and fmin/fmax's care for NaN had
 * been a compare and a blend per texel, about a quarter of limit_patches. */
TEXEL_INLINE float4 tile_bounds(ATLAS_IN pos, int2 g, int p)
{
  float3 lo = (float3)(INFINITY), hi = (float3)(-INFINITY);
  for (int j = 0; j < g.x; ++j)
    for (int i = 0; i < g.x; ++i) {
      const float3 x = ATLAS_LOAD(pos, g, p, (int2)(i, j)).xyz;
      lo = min(lo, x);
      hi = max(hi, x);
    }
  const float3 c = 0.5f * (lo + hi);
  float r2 = 0.0f;
  for (int j = 0; j < g.x; ++j)
    for (int i = 0; i < g.x; ++i) {
      const float3 d = ATLAS_LOAD(pos, g, p, (int2)(i, j)).xyz - c;
      r2 = max(r2, dot(d, d));
    }
  return (float4)(c, sqrt(r2));
}

/* Range: count. tile_bounds() of the listed or flagged patches (neither:
 * every patch), after the limit kernels that did not make them. */
__kernel void patch_bounds(ATLAS_IN pos, int2 g, __global const int *list, int count, __global const uchar *flags,
                           int generation, __global float4 *bounds)
{
  const int k = get_global_id(0);
  if (k < count) {
    const int p = LISTED(list, k);
    if (!UNFLAGGED(flags, generation, p))
      bounds[p] = tile_bounds(pos, g, p);
  }
}

/* Range: count; the bounding sphere of each listed cluster's patch
 * spheres (list null: every cluster, patches / PATCH_CLUSTER rounded up):
 * the centre of their centres' box, as radius half its diagonal and the
 * largest of theirs, in one pass without a square root per patch. Grown by
 * a margin far beyond the rounding of these sums and of the brush's tests
 * against a patch, so that a cluster a brush test finds beyond its bound
 * holds no patch that test would have found within its own. With flags
 * (a set's, UNFLAGGED), only the clusters holding a flagged patch. */
__kernel void cluster_bounds(__global const float4 *restrict bounds, int patches, __global const int *list, int count,
                             __global const uchar *flags, int generation, __global float4 *restrict clusters)
{
  const int k = get_global_id(0);
  if (k >= count)
    return;
  const int c = LISTED(list, k);
  const int first = c * PATCH_CLUSTER, end = min(first + PATCH_CLUSTER, patches);
  if (flags) { /* a set's flags: only clusters with a flagged patch changed */
    bool any_flagged = false;
    for (int p = first; p < end; ++p)
      any_flagged |= !UNFLAGGED(flags, generation, p);
    if (!any_flagged)
      return;
  }
  float3 lo = (float3)(INFINITY), hi = (float3)(-INFINITY);
  float r = 0.0f;
  for (int p = first; p < end; ++p) {
    const float4 b = bounds[p];
    lo = min(lo, b.xyz);
    hi = max(hi, b.xyz);
    r = max(r, b.w);
  }
  const float3 centre = 0.5f * (lo + hi), reach = 0.5f * (hi - lo), a = fabs(centre);
  r += sqrt(dot(reach, reach));
  clusters[c] = (float4)(centre, r * (1.0f + 1e-5f) + 1e-5f * max(max(a.x, a.y), a.z));
}

/* Range: whole tiles, (tile, tile * count): a work item per texel. */
__kernel void limit_tiles(ATLAS_IN src, ATLAS_OUT pos, ATLAS_OUT nrm, int2 g, __global const int *list, int count,
                          __global const uchar *flags, int generation, __global const int4 *restrict patch_sides, __global const int4 *restrict patch_rings,
                          __global const float4 *restrict sides, __global const float4 *restrict corners)
{
  TILE_TEXEL_PART(g, list, count, LIMIT_SKIP, patch_sides, patch_rings, LIMIT_COPY, LIMIT_INSIDE);
}

/* Range: count; the same with a work item per patch walking its border
 * (FOR_EACH_TILE_PART) and then its interior by columns; with buffer
 * storage also the patch's tile_bounds() into `bounds` unless it is null. */
__kernel void limit_patches(ATLAS_IN src, ATLAS_OUT pos, ATLAS_OUT nrm, int2 g, __global const int *list, int count,
                            __global const uchar *flags, int generation, __global const int4 *restrict patch_sides, __global const int4 *restrict patch_rings,
                            __global const float4 *restrict sides, __global const float4 *restrict corners,
                            __global float4 *restrict bounds)
{
#define LIMIT_LATER(ij) ((void)0)
  PATCH_ITEM_PARTS(g, list, count, LIMIT_SKIP, patch_sides, patch_rings, LIMIT_COPY, LIMIT_LATER);
#undef LIMIT_LATER
  limit_inside_columns(src, pos, nrm, g, p);
#ifndef ATLAS_IMAGE
  /* The tile the item has just written, still in its cache: the bounds
   * cost a pass there instead of a kernel over the set. */
  if (bounds)
    bounds[p] = tile_bounds(pos, g, p);
#endif
}

/* Range: count; per edge, its texels on the patch sides, corners excluded,
 * into `sides`. */
__kernel void limit_edges(ATLAS_IN src, __global float4 *restrict sides, __global const PatchEdge *edges,
                          __global const int *list, int count, __global const uchar *flags, int generation, int2 g)
{
  const int k = get_global_id(0);
  if (k >= count)
    return;
  const int edge = LISTED(list, k);
  if (UNFLAGGED(flags, generation, edge))
    return;
  const PatchEdge e = edges[edge];
  PREFETCH_EDGE_AHEAD(src, g, edges, list, k, count);
  EDGE_FRAMES(e, g);
  const int interior = e.patch[1] >= 0;
  const int first = edge * (g.x - 2) - 1; /* pair of texel t: first + t */
  /* A 3x3 window slides along the side, one new column per texel: rows
   * across (a), along the side (m) and inwards (i); on a mesh boundary the
   * row across is never read. */
  float4 m0 = EDGE_LOAD(src, g, 0, 0), m1 = EDGE_LOAD(src, g, 1, 0);
  float4 i0 = EDGE_LOAD(src, g, 0, 1), i1 = EDGE_LOAD(src, g, 1, 1);
  float4 a0 = interior ? EDGE_LOAD(src, g, 0, -1) : m0, a1 = interior ? EDGE_LOAD(src, g, 1, -1) : m1;
  /* Along the side, its normals four at a time (IN_FOURS). */
#define NEXT_TEXEL(t, pk, ck)                                                          \
  do {                                                                                 \
    const float4 m2 = EDGE_LOAD(src, g, (t) + 1, 0), i2 = EDGE_LOAD(src, g, (t) + 1, 1); \
    const float4 a2 = interior ? EDGE_LOAD(src, g, (t) + 1, -1) : m2;                  \
    if (interior)                                                                      \
      limit_window_cross(a0, a1, a2, m0, m1, m2, i0, i1, i2, &pk, &ck);                \
    else                                                                               \
      limit_crease_cross(m0, m1, m2, i0, i1, i2, &pk, &ck);                            \
    a0 = a1;                                                                           \
    a1 = a2;                                                                           \
    m0 = m1;                                                                           \
    m1 = m2;                                                                           \
    i0 = i1;                                                                           \
    i1 = i2;                                                                           \
  } while (0)
#define STORE_TEXEL(t, pk, nk) PAIR_STORE(sides, first + (t), pk, nk)
  IN_FOURS(1, g.x - 1, NEXT_TEXEL, STORE_TEXEL);
#undef STORE_TEXEL
#undef NEXT_TEXEL
}

/* Range: count; each patch corner's ring, into `corners`. The masks' trigonometry
 * comes per valence m from `valences` (entries 2m, 2m + 1: see
 * limit_constants() in atlas.cpp); multiples of the angle by rotation. */
__kernel void limit_corners(ATLAS_IN src, __global float4 *restrict corners, __global const CornerRing *rings,
                            __global const CornerSlot *slots, __global const float4 *restrict valences,
                            __global const int *list, int count, __global const uchar *flags, int generation,
                            int2 g)
{
  RING_ITEM(src, g, rings, slots, list, count, flags, generation);
  const int m = ring.count;
  const CornerSlot first = slots[ring.first], last = slots[ring.first + m - 1];
  const float4 v = CORNER_LOAD(src, g, first, 0, 0);
  float4 p, t1, t2;
  if (ring.boundary && m == 1) {
    p = v;
    t1 = CORNER_LOAD(src, g, first, 1, 0) - v;
    t2 = CORNER_LOAD(src, g, first, 0, 1) - v;
  } else if (ring.boundary) {
    /* Edges E_0..E_m around the vertex, face i between E_i and E_i+1. */
    const float4 e0 = CORNER_LOAD(src, g, first, 1, 0);
    const float4 em = CORNER_LOAD(src, g, last, 0, 1);
    p = (4.0f * v + e0 + em) * (1.0f / 6.0f);
    t1 = (e0 - em) * 0.5f;
    if (m == 2) {
      const CornerSlot s1 = slots[ring.first + 1];
      t2 = (-4.0f * v - e0 + 4.0f * CORNER_LOAD(src, g, s1, 1, 0) - em + CORNER_LOAD(src, g, first, 1, 1) +
            CORNER_LOAD(src, g, s1, 1, 1)) *
           (1.0f / 6.0f);
    } else {
      const float4 k4 = valences[2 * m + 1]; /* cos, sin of pi/m, denom, r */
      const float c = k4.x, s = k4.y, r = k4.w;
      t2 = (4.0f * r * (c - 1.0f)) * v + (-r * (1.0f + 2.0f * c)) * (e0 + em);
      float ci = 1.0f, si = 0.0f; /* cos, sin of i pi/m */
      for (int i = 0; i < m; ++i) {
        const CornerSlot slot = slots[ring.first + i];
        const float cn = ci * c - si * s, sn = si * c + ci * s;
        if (i > 0)
          t2 += (4.0f * si) * CORNER_LOAD(src, g, slot, 1, 0);
        t2 += (si + sn) * CORNER_LOAD(src, g, slot, 1, 1);
        ci = cn;
        si = sn;
      }
      t2 *= k4.z;
    }
  } else {
    const float4 k4 = valences[2 * m]; /* cos, sin of 2pi/m, lambda, 1 / (4 lambda - 1) */
    const float fm = (float)m, c = k4.x, st = k4.y, face_scale = k4.w;
    float4 es = (float4)(0.0f), ds = (float4)(0.0f);
    t1 = (float4)(0.0f);
    t2 = (float4)(0.0f);
    float cp = c, ci = 1.0f, si_ = 0.0f; /* cos(-theta) = cos(theta) */
    for (int i = 0; i < m; ++i) {
      const CornerSlot slot = slots[ring.first + i];
      const float4 ei = CORNER_LOAD(src, g, slot, 1, 0);
      const float4 di = CORNER_LOAD(src, g, slot, 1, 1);
      const float cn = ci * c - si_ * st, sn = si_ * c + ci * st;
      es += ei;
      ds += di;
      t1 += (4.0f * ci) * ei + (face_scale * (ci + cn)) * di;
      t2 += (4.0f * cp) * ei + (face_scale * (cp + ci)) * di;
      cp = ci;
      ci = cn;
      si_ = sn;
    }
    p = (fm * fm * v + 4.0f * es + ds) * (1.0f / (fm * (fm + 5.0f)));
  }
  PAIR_STORE(corners, index, p, (float4)(normalize(cross(t1.xyz, t2.xyz)), 0.0f));
}
