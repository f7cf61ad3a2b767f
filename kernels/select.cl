/* Sets of patches with their sides and corners, worked out on the device as
 * flags (UNFLAGGED in atlas_access.cl) for sets too large for host lists
 * to pay: a flag holds the generation of the last set that took the item,
 * so a new set needs no pass that clears them (the host clears them when
 * the generations wrap, once in 255 sets). Several items may flag one
 * byte at once; they all store the same value. */

/* Range: count. Flags the corners (rings) of the listed patches. */
__kernel void flag_corners(__global const int *list, int count, __global const int4 *restrict patch_rings,
                           int generation, __global uchar *rings)
{
  const int k = get_global_id(0);
  if (k >= count)
    return;
  const int4 r = patch_rings[list[k]];
  const uchar f = (uchar)generation;
  rings[r.x] = f;
  rings[r.y] = f;
  rings[r.z] = f;
  rings[r.w] = f;
}

/* Range: ring_count. Flags every patch at a flagged corner: after
 * flag_corners(), the listed patches and those sharing a corner with one,
 * whose tiles hold copies of the limit at the listed ones' texels. A ring
 * is read once here, where a pass over the listed patches read each about
 * four times (and took twice as long). */
__kernel void flag_ring_patches(__global const uchar *restrict rings_flagged, int ring_count,
                                __global const CornerRing *restrict rings, __global const CornerSlot *restrict slots,
                                int generation, __global uchar *patches)
{
  const int r = get_global_id(0);
  if (r >= ring_count || rings_flagged[r] != (uchar)generation)
    return;
  const CornerRing ring = rings[r];
  for (int i = 0; i < ring.count; ++i)
    patches[slots[ring.first + i].patch] = (uchar)generation;
}

/* Range: patch_count. Flags each side (edge) and corner (ring) of every
 * flagged patch. */
__kernel void flag_borders(__global const uchar *restrict patches, int patch_count,
                           __global const int4 *restrict patch_sides, __global const int4 *restrict patch_rings,
                           int generation, __global uchar *edges, __global uchar *rings)
{
  const int p = get_global_id(0);
  if (p >= patch_count || patches[p] != (uchar)generation)
    return;
  const int4 e = patch_sides[p] >> 1, r = patch_rings[p]; /* 2 * edge + which patch of it */
  const uchar f = (uchar)generation;
  edges[e.x] = f;
  edges[e.y] = f;
  edges[e.z] = f;
  edges[e.w] = f;
  rings[r.x] = f;
  rings[r.y] = f;
  rings[r.z] = f;
  rings[r.w] = f;
}
