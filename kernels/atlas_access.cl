/* Atlas addressing shared by every kernel family.
 *
 * A level's atlas holds one tile of (n+1) x (n+1) texels per patch,
 * n = 2^(level-1). Kernels address texels as (patch, i, j); a grid
 * g = (tile, tiles_x) describes the level. The storage behind that is chosen
 * at build time:
 *   ATLAS_IMAGE defined: one image2d_t (RGBA float) with the tiles laid
 *                        row-major, tiles_x per row: for devices whose texture
 *                        units swizzle images for locality;
 *   otherwise:           one float4 buffer with each tile contiguous (patch
 *                        after patch), so that a patch and its neighbours sit
 *                        in a few cache lines: the fast layout on CPUs. */

#pragma OPENCL FP_CONTRACT OFF

#ifdef ATLAS_IMAGE
#define ATLAS_IN __read_only image2d_t
#define ATLAS_OUT __write_only image2d_t
#define ATLAS_LOAD(a, g, p, ij) read_imagef((a), tile_origin((p), (g)) + (ij))
#define ATLAS_STORE(a, g, p, ij, v) write_imagef((a), tile_origin((p), (g)) + (ij), (v))
#else
#define ATLAS_IN __global const float4 *restrict
#define ATLAS_OUT __global float4 *restrict
#define ATLAS_INDEX(g, p, ij) (((p) * (g).x + (ij).y) * (g).x + (ij).x)
#define ATLAS_LOAD(a, g, p, ij) ((a)[ATLAS_INDEX(g, p, ij)])
#define ATLAS_STORE(a, g, p, ij, v) ((a)[ATLAS_INDEX(g, p, ij)] = (v))
#endif

/* Texel of the patch's first corner in the atlas image. */
inline int2 tile_origin(int patch, int2 g)
{
  return (int2)((patch % g.y) * g.x, (patch / g.y) * g.x);
}

/* Patch-local texel at position t along side `side` and depth d inside it
 * (d = 0 is the side itself). The map is a rotation, so (t, d) frames keep the
 * patch's orientation. */
inline int2 side_texel(int side, int t, int d, int n)
{
  switch (side & 3) {
  case 0: return (int2)(t, d);
  case 1: return (int2)(n - d, t);
  case 2: return (int2)(n - t, n - d);
  default: return (int2)(d, n - t);
  }
}

/* Texel (t, d) of an edge's side frame, where d < 0 reaches into the
 * neighbouring patch: position t of this side is n - t of the other. */
#define EDGE_LOAD(src, g, e, t, d)                                                          \
  ((d) >= 0 ? ATLAS_LOAD(src, g, (e).patch[0], side_texel((e).side[0], (t), (d), (g).x - 1)) \
            : ATLAS_LOAD(src, g, (e).patch[1], side_texel((e).side[1], (g).x - 1 - (t), -(d), (g).x - 1)))

/* Writes one edge texel to both patches that store it. */
#define EDGE_STORE(dst, g, e, t, v)                                                         \
  do {                                                                                      \
    ATLAS_STORE(dst, g, (e).patch[0], side_texel((e).side[0], (t), 0, (g).x - 1), (v));     \
    if ((e).patch[1] >= 0)                                                                  \
      ATLAS_STORE(dst, g, (e).patch[1], side_texel((e).side[1], (g).x - 1 - (t), 0, (g).x - 1), (v)); \
  } while (0)

/* Texel (a, b) seen from a ring slot's corner: a along the slot's outgoing
 * side, b along its incoming side. */
#define CORNER_LOAD(src, g, slot, a, b) \
  ATLAS_LOAD(src, g, (slot).patch, side_texel((slot).corner, (a), (b), (g).x - 1))
#define CORNER_STORE(dst, g, slot, v) \
  ATLAS_STORE(dst, g, (slot).patch, side_texel((slot).corner, 0, 0, (g).x - 1), (v))

/* Patch and texel of a work item of an atlas-wide kernel, whose range is
 * (tile, tile * patches): returns 0 for texels on a patch side or corner and
 * for the rounding tail, which the table-driven kernels own. */
inline int interior_texel(int2 g, int patches, int *p, int2 *ij)
{
  const int i = get_global_id(0), y = get_global_id(1);
  *p = y / g.x;
  const int j = y - *p * g.x;
  *ij = (int2)(i, j);
  return i > 0 && j > 0 && i < g.x - 1 && j < g.x - 1 && *p < patches;
}
