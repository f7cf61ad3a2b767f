/* Atlas addressing shared by every kernel family.
 *
 * The atlas of level l holds one tile of (n+1) x (n+1) texels per patch,
 * n = 2^(l-1), tiles laid row-major, tiles_x per atlas row. Kernels address
 * texels in 2D; the storage behind that is chosen at build time:
 *   ATLAS_IMAGE defined: image2d_t (RGBA float), for devices with image units;
 *   otherwise:           a linear float4 buffer, row pitch `width` texels.
 * Kernel signatures use ATLAS_IN / ATLAS_OUT and pass `width` in both cases. */

#pragma OPENCL FP_CONTRACT OFF

#ifdef ATLAS_IMAGE
#define ATLAS_IN __read_only image2d_t
#define ATLAS_OUT __write_only image2d_t
#define ATLAS_LOAD(a, width, xy) read_imagef((a), (xy))
#define ATLAS_STORE(a, width, xy, v) write_imagef((a), (xy), (v))
#else
#define ATLAS_IN __global const float4 *restrict
#define ATLAS_OUT __global float4 *restrict
#define ATLAS_LOAD(a, width, xy) ((a)[(xy).y * (width) + (xy).x])
#define ATLAS_STORE(a, width, xy, v) ((a)[(xy).y * (width) + (xy).x] = (v))
#endif

/* Texel of the patch's first corner in the atlas. */
inline int2 tile_origin(int patch, int tile, int tiles_x)
{
  return (int2)((patch % tiles_x) * tile, (patch / tiles_x) * tile);
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

/* Texel at (t, d) of a side frame, in atlas coordinates. */
inline int2 side_atlas(int patch, int side, int t, int d, int n, int tiles_x)
{
  return tile_origin(patch, n + 1, tiles_x) + side_texel(side, t, d, n);
}

/* The ring slot `k`'s texel at (a, b) seen from its corner: a along the
 * outgoing side, b along the incoming side. */
inline int2 corner_atlas(CornerSlot slot, int a, int b, int n, int tiles_x)
{
  return side_atlas(slot.patch, slot.corner, a, b, n, tiles_x);
}

/* Reads texel (t, d) across a patch edge, where d < 0 reaches into the
 * neighbouring patch: position t of this side is n - t of the other. */
#define EDGE_LOAD(src, width, e, t, d, n, tiles_x)                               \
  ((d) >= 0 ? ATLAS_LOAD(src, width, side_atlas((e).patch[0], (e).side[0], (t), (d), (n), (tiles_x))) \
            : ATLAS_LOAD(src, width, side_atlas((e).patch[1], (e).side[1], (n) - (t), -(d), (n), (tiles_x))))

/* Writes one edge texel to both patches that store it. */
#define EDGE_STORE(dst, width, e, t, n, tiles_x, v)                               \
  do {                                                                           \
    ATLAS_STORE(dst, width, side_atlas((e).patch[0], (e).side[0], (t), 0, (n), (tiles_x)), (v)); \
    if ((e).patch[1] >= 0)                                                       \
      ATLAS_STORE(dst, width, side_atlas((e).patch[1], (e).side[1], (n) - (t), 0, (n), (tiles_x)), (v)); \
  } while (0)
