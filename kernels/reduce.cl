/* Gaussian reduction of the atlas, level l+1 -> l (2n -> n quads per patch
 * side): the paper's subsampling operator. Each kept texel is the binomial
 * (1,4,6,4,1)/16 average of its level-l+1 neighbourhood in both directions;
 * windows cross patch sides through the edge table. Mesh-boundary curves are
 * reduced along themselves only, sharp corners are kept, and an extraordinary
 * corner spreads the regular ring weights evenly over its n sectors. */

#define BINOMIAL5(k) ((k) == 0 ? 0.375f : ((k) == 1 || (k) == -1) ? 0.25f : 0.0625f)

/* Range: the level-l atlas; texels strictly inside each patch. */
__kernel void reduce_interior(ATLAS_IN src, ATLAS_OUT dst, int n, int tiles_x, int patches,
                              int src_width, int dst_width)
{
  const int tile = n + 1;
  const int x = get_global_id(0), y = get_global_id(1);
  const int tx = x / tile, ty = y / tile;
  const int i = x - tx * tile, j = y - ty * tile;
  if (i == 0 || j == 0 || i == n || j == n || tx >= tiles_x || ty * tiles_x + tx >= patches)
    return;
  const int2 c = (int2)(tx, ty) * (2 * n + 1) + (int2)(2 * i, 2 * j);
  float4 acc = (float4)(0.0f);
  for (int b = -2; b <= 2; ++b) {
    float4 row = (float4)(0.0f);
    for (int a = -2; a <= 2; ++a)
      row += BINOMIAL5(a) * ATLAS_LOAD(src, src_width, c + (int2)(a, b));
    acc += BINOMIAL5(b) * row;
  }
  ATLAS_STORE(dst, dst_width, (int2)(x, y), acc);
}

/* Range: (n - 1, #edges); texels on patch sides, corners excluded. */
__kernel void reduce_edges(ATLAS_IN src, ATLAS_OUT dst, __global const PatchEdge *edges,
                           int edge_count, int n, int tiles_x, int src_width, int dst_width)
{
  const int t = get_global_id(0) + 1, k = get_global_id(1);
  if (k >= edge_count || t >= n)
    return;
  const PatchEdge e = edges[k];
  const int lo = e.patch[1] >= 0 ? -2 : 0, hi = e.patch[1] >= 0 ? 2 : 0;
  float4 acc = (float4)(0.0f);
  for (int b = lo; b <= hi; ++b) {
    float4 row = (float4)(0.0f);
    for (int a = -2; a <= 2; ++a)
      row += BINOMIAL5(a) * EDGE_LOAD(src, src_width, e, 2 * t + a, b, 2 * n, tiles_x);
    acc += (lo < 0 ? BINOMIAL5(b) : 1.0f) * row;
  }
  EDGE_STORE(dst, dst_width, e, t, n, tiles_x, acc);
}

/* Range: #rings; every copy of each patch corner. */
__kernel void reduce_corners(ATLAS_IN src, ATLAS_OUT dst, __global const CornerRing *rings,
                             __global const CornerSlot *slots, int ring_count, int n, int tiles_x,
                             int src_width, int dst_width)
{
  const int k = get_global_id(0);
  if (k >= ring_count)
    return;
  const CornerRing ring = rings[k];
  const int ns = 2 * n;
  const CornerSlot first = slots[ring.first], last = slots[ring.first + ring.count - 1];
  const float4 v = ATLAS_LOAD(src, src_width, corner_atlas(first, 0, 0, ns, tiles_x));
  float4 r;
  if (ring.boundary) {
    if (ring.count == 1) {
      r = v;
    } else {
      const float4 b1 = ATLAS_LOAD(src, src_width, corner_atlas(first, 1, 0, ns, tiles_x)) +
                        ATLAS_LOAD(src, src_width, corner_atlas(last, 0, 1, ns, tiles_x));
      const float4 b2 = ATLAS_LOAD(src, src_width, corner_atlas(first, 2, 0, ns, tiles_x)) +
                        ATLAS_LOAD(src, src_width, corner_atlas(last, 0, 2, ns, tiles_x));
      r = 0.375f * v + 0.25f * b1 + 0.0625f * b2;
    }
  } else {
    /* Sector of one patch seen from the corner: its outgoing axis and the
     * texels between the two axes, weighted as the separable filter would. */
    float4 sectors = (float4)(0.0f);
    for (int m = 0; m < ring.count; ++m) {
      const CornerSlot s = slots[ring.first + m];
#define AT(a, b) ATLAS_LOAD(src, src_width, corner_atlas(s, a, b, ns, tiles_x))
      sectors += 24.0f * AT(1, 0) + 6.0f * AT(2, 0) + 16.0f * AT(1, 1) +
                 4.0f * (AT(2, 1) + AT(1, 2)) + AT(2, 2);
#undef AT
    }
    r = (36.0f * v + (4.0f / (float)ring.count) * sectors) * (1.0f / 256.0f);
  }
  for (int m = 0; m < ring.count; ++m)
    ATLAS_STORE(dst, dst_width, corner_atlas(slots[ring.first + m], 0, 0, n, tiles_x), r);
}
