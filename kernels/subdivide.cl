/* Catmull-Clark refinement of the atlas, level l -> l+1 (n -> 2n quads per
 * patch side). Above level 1 every vertex off a patch corner is regular, so
 * the masks there are the tensor-product cubic B-spline ones; corners use the
 * ring tables. Each stored copy of an edge or corner texel is written from
 * one computation, so the copies stay bit-identical. */

/* Weights of the old taps c-1, c, c+1 (c = (i+1)/2) for new index i along one
 * axis: even i is a vertex point (1,6,1)/8, odd i an edge midpoint (1,1)/2. */
inline float3 refine_weights(int i)
{
  return (i & 1) ? (float3)(0.5f, 0.5f, 0.0f) : (float3)(0.125f, 0.75f, 0.125f);
}

/* Texels strictly inside each patch. Range: the level l+1 atlas. */
__kernel void subdivide_interior(ATLAS_IN src, ATLAS_OUT dst, int n_src, int tiles_x,
                                 int patches, int src_width, int dst_width)
{
  const int n = 2 * n_src, tile = n + 1;
  const int x = get_global_id(0), y = get_global_id(1);
  const int tx = x / tile, ty = y / tile;
  const int i = x - tx * tile, j = y - ty * tile;
  if (i == 0 || j == 0 || i == n || j == n || tx >= tiles_x || ty * tiles_x + tx >= patches)
    return;

  const int2 o = (int2)(tx, ty) * (n_src + 1);
  const int ci = (i + 1) >> 1, cj = (j + 1) >> 1;
  const int i0 = ci - 1, i2 = min(ci + 1, n_src);
  const int j0 = cj - 1, j2 = min(cj + 1, n_src);
  const float3 wi = refine_weights(i), wj = refine_weights(j);

  const float4 r0 = wi.x * ATLAS_LOAD(src, src_width, o + (int2)(i0, j0)) +
                    wi.y * ATLAS_LOAD(src, src_width, o + (int2)(ci, j0)) +
                    wi.z * ATLAS_LOAD(src, src_width, o + (int2)(i2, j0));
  const float4 r1 = wi.x * ATLAS_LOAD(src, src_width, o + (int2)(i0, cj)) +
                    wi.y * ATLAS_LOAD(src, src_width, o + (int2)(ci, cj)) +
                    wi.z * ATLAS_LOAD(src, src_width, o + (int2)(i2, cj));
  const float4 r2 = wi.x * ATLAS_LOAD(src, src_width, o + (int2)(i0, j2)) +
                    wi.y * ATLAS_LOAD(src, src_width, o + (int2)(ci, j2)) +
                    wi.z * ATLAS_LOAD(src, src_width, o + (int2)(i2, j2));
  ATLAS_STORE(dst, dst_width, (int2)(tx, ty) * tile + (int2)(i, j), wj.x * r0 + wj.y * r1 + wj.z * r2);
}

/* Texels on patch sides, corners excluded. Range: (2n - 1, #edges). */
__kernel void subdivide_edges(ATLAS_IN src, ATLAS_OUT dst, __global const PatchEdge *edges,
                              int edge_count, int n_src, int tiles_x, int src_width, int dst_width)
{
  const int t = get_global_id(0) + 1, k = get_global_id(1);
  if (k >= edge_count || t >= 2 * n_src)
    return;
  const PatchEdge e = edges[k];
  const int c = (t + 1) >> 1, t0 = c - 1, t2 = min(c + 1, n_src);
  const float3 w = refine_weights(t);

#define ROW(d)                                                                   \
  (w.x * EDGE_LOAD(src, src_width, e, t0, d, n_src, tiles_x) +                   \
   w.y * EDGE_LOAD(src, src_width, e, c, d, n_src, tiles_x) +                    \
   w.z * EDGE_LOAD(src, src_width, e, t2, d, n_src, tiles_x))
  float4 v = ROW(0);
  /* A mesh-boundary side refines as a cubic B-spline curve on its own. */
  if (e.patch[1] >= 0)
    v = 0.125f * ROW(1) + 0.75f * v + 0.125f * ROW(-1);
#undef ROW
  EDGE_STORE(dst, dst_width, e, t, 2 * n_src, tiles_x, v);
}

/* Patch corners, i.e. the level-1 vertices and their copies. Range: #rings. */
__kernel void subdivide_corners(ATLAS_IN src, ATLAS_OUT dst, __global const CornerRing *rings,
                                __global const CornerSlot *slots, int ring_count, int n_src,
                                int tiles_x, int src_width, int dst_width)
{
  const int k = get_global_id(0);
  if (k >= ring_count)
    return;
  const CornerRing ring = rings[k];
  const CornerSlot first = slots[ring.first], last = slots[ring.first + ring.count - 1];
  const float4 v = ATLAS_LOAD(src, src_width, corner_atlas(first, 0, 0, n_src, tiles_x));
  float4 r;
  if (ring.boundary) {
    if (ring.count == 1) {
      r = v; /* a corner of one face stays sharp */
    } else {
      const float4 b0 = ATLAS_LOAD(src, src_width, corner_atlas(first, 1, 0, n_src, tiles_x));
      const float4 b1 = ATLAS_LOAD(src, src_width, corner_atlas(last, 0, 1, n_src, tiles_x));
      r = 0.75f * v + 0.125f * (b0 + b1);
    }
  } else {
    float4 es = (float4)(0.0f), ds = (float4)(0.0f);
    for (int m = 0; m < ring.count; ++m) {
      const CornerSlot s = slots[ring.first + m];
      es += ATLAS_LOAD(src, src_width, corner_atlas(s, 1, 0, n_src, tiles_x));
      ds += ATLAS_LOAD(src, src_width, corner_atlas(s, 1, 1, n_src, tiles_x));
    }
    const float n = (float)ring.count;
    r = (1.0f - 1.75f / n) * v + (1.5f / (n * n)) * es + (0.25f / (n * n)) * ds;
  }
  for (int m = 0; m < ring.count; ++m)
    ATLAS_STORE(dst, dst_width, corner_atlas(slots[ring.first + m], 0, 0, 2 * n_src, tiles_x), r);
}
