/* Catmull-Clark refinement of the atlas, level l -> l+1 (n -> 2n quads per
 * patch side). Above level 1 every vertex off a patch corner is regular, so
 * the masks there are the tensor-product cubic B-spline ones; corners use the
 * ring tables. Each stored copy of an edge or corner texel is written from
 * one computation, so the copies stay bit-identical.
 * sg, dg: grids (tile, tiles_x) of the source and destination levels. */

/* Weights of the old taps c-1, c, c+1 (c = (i+1)/2) for new index i along one
 * axis: even i is a vertex point (1,6,1)/8, odd i an edge midpoint (1,1)/2. */
inline float3 refine_weights(int i)
{
  return (i & 1) ? (float3)(0.5f, 0.5f, 0.0f) : (float3)(0.125f, 0.75f, 0.125f);
}

/* Range: (dst tile, dst tile * patches); texels strictly inside patches. */
__kernel void subdivide_interior(ATLAS_IN src, ATLAS_OUT dst, int2 sg, int2 dg, int patches)
{
  int p;
  int2 ij;
  if (!interior_texel(dg, patches, &p, &ij))
    return;
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

/* Range: (2 n_src - 1, #edges); texels on patch sides, corners excluded. */
__kernel void subdivide_edges(ATLAS_IN src, ATLAS_OUT dst, __global const PatchEdge *edges,
                              int edge_count, int2 sg, int2 dg)
{
  const int t = get_global_id(0) + 1, k = get_global_id(1);
  const int n_src = sg.x - 1;
  if (k >= edge_count || t >= 2 * n_src)
    return;
  const PatchEdge e = edges[k];
  const int c = (t + 1) >> 1, t0 = c - 1, t2 = min(c + 1, n_src);
  const float3 w = refine_weights(t);
#define ROW(d)                                   \
  (w.x * EDGE_LOAD(src, sg, e, t0, d) +          \
   w.y * EDGE_LOAD(src, sg, e, c, d) +           \
   w.z * EDGE_LOAD(src, sg, e, t2, d))
  float4 v = ROW(0);
  /* A mesh-boundary side refines as a cubic B-spline curve on its own. */
  if (e.patch[1] >= 0)
    v = 0.125f * ROW(1) + 0.75f * v + 0.125f * ROW(-1);
#undef ROW
  EDGE_STORE(dst, dg, e, t, v);
}

/* Range: #rings; patch corners, i.e. the level-1 vertices and their copies. */
__kernel void subdivide_corners(ATLAS_IN src, ATLAS_OUT dst, __global const CornerRing *rings,
                                __global const CornerSlot *slots, int ring_count, int2 sg, int2 dg)
{
  const int k = get_global_id(0);
  if (k >= ring_count)
    return;
  const CornerRing ring = rings[k];
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
  for (int m = 0; m < ring.count; ++m)
    CORNER_STORE(dst, dg, slots[ring.first + m], r);
}
