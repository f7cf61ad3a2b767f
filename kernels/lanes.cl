/* Eight patches per work item, a patch per lane (CPU devices): PoCL does not
 * spread the atlas kernels' work items over the lanes of a vector register,
 * since their values are vectors themselves, and float3 or float4
 * arithmetic keeps a texel's components in one register and spends much of
 * its time shuffling them. Lanes hold each component apart instead: a
 * float8 of x, one of y, and so on. The tiles of a work item's patches are
 * walked together, texel ij in every lane at once. With FP_CONTRACT off
 * (atlas_access.cl) each lane performs the per-texel kernel's operations in
 * their order and gets its bits. The lanes are float8, so PATCH_LANES
 * (atlas_types.h) is 8. */

typedef struct {
  float8 x, y, z;
} Lanes;

typedef struct {
  float8 x, y, z, w;
} Lanes4;

/* Eight float4, a lane each, as their components: a transpose in two
 * rounds of shuffles (not 32 loads of a float each). */
TEXEL_INLINE Lanes4 transpose_lanes(float4 v0, float4 v1, float4 v2, float4 v3, float4 v4, float4 v5, float4 v6,
                                    float4 v7)
{
  const float8 a04 = (float8)(v0, v4), a15 = (float8)(v1, v5), a26 = (float8)(v2, v6), a37 = (float8)(v3, v7);
  const uint8 lo = (uint8)(0, 8, 1, 9, 4, 12, 5, 13), hi = (uint8)(2, 10, 3, 11, 6, 14, 7, 15);
  const float8 xy01 = shuffle2(a04, a15, lo), xy23 = shuffle2(a26, a37, lo);
  const float8 zw01 = shuffle2(a04, a15, hi), zw23 = shuffle2(a26, a37, hi);
  const uint8 even = (uint8)(0, 1, 8, 9, 4, 5, 12, 13), odd = (uint8)(2, 3, 10, 11, 6, 7, 14, 15);
  Lanes4 r;
  r.x = shuffle2(xy01, xy23, even);
  r.y = shuffle2(xy01, xy23, odd);
  r.z = shuffle2(zw01, zw23, even);
  r.w = shuffle2(zw01, zw23, odd);
  return r;
}

/* Texel ij of the patches `patch`, a lane each, all four components: eight
 * 16-byte loads by LOAD(a, g, p, ij) and a transpose. */
#define LANES4_LOADED(LOAD, a, g, patch, ij)                                                               \
  transpose_lanes(LOAD(a, g, (patch).s0, ij), LOAD(a, g, (patch).s1, ij), LOAD(a, g, (patch).s2, ij),    \
                  LOAD(a, g, (patch).s3, ij), LOAD(a, g, (patch).s4, ij), LOAD(a, g, (patch).s5, ij),    \
                  LOAD(a, g, (patch).s6, ij), LOAD(a, g, (patch).s7, ij))
#define PATCH_MAJOR_LOAD(a, g, p, ij) ((a)[PATCH_MAJOR_INDEX(g, p, ij)])

/* From an atlas layer, as (x, y, z). */
TEXEL_INLINE Lanes load_lanes(ATLAS_IN a, int2 g, int8 patch, int2 ij)
{
  const Lanes4 v = LANES4_LOADED(ATLAS_LOAD, a, g, patch, ij);
  Lanes r;
  r.x = v.x;
  r.y = v.y;
  r.z = v.z;
  return r;
}

/* From a patch-major float4 buffer (the paint channels). */
TEXEL_INLINE Lanes4 load_lanes4(__global const float4 *a, int2 g, int8 patch, int2 ij)
{
  return LANES4_LOADED(PATCH_MAJOR_LOAD, a, g, patch, ij);
}

/* The inverse of load_lanes4(): texel ij of the patches `patch` set to
 * (x, y, z, w), lane by lane, from two rounds of shuffles and eight
 * 16-byte stores. */
TEXEL_INLINE void store_lanes4(__global float4 *out, int2 g, int8 patch, int2 ij, float8 x, float8 y, float8 z,
                               float8 w)
{
  const uint8 lo = (uint8)(0, 8, 1, 9, 2, 10, 3, 11), hi = (uint8)(4, 12, 5, 13, 6, 14, 7, 15);
  const float8 xy0 = shuffle2(x, y, lo), xy1 = shuffle2(x, y, hi);
  const float8 zw0 = shuffle2(z, w, lo), zw1 = shuffle2(z, w, hi);
  const uint8 first = (uint8)(0, 1, 8, 9, 2, 3, 10, 11), second = (uint8)(4, 5, 12, 13, 6, 7, 14, 15);
  const float8 l01 = shuffle2(xy0, zw0, first), l23 = shuffle2(xy0, zw0, second);
  const float8 l45 = shuffle2(xy1, zw1, first), l67 = shuffle2(xy1, zw1, second);
  out[PATCH_MAJOR_INDEX(g, patch.s0, ij)] = l01.lo;
  out[PATCH_MAJOR_INDEX(g, patch.s1, ij)] = l01.hi;
  out[PATCH_MAJOR_INDEX(g, patch.s2, ij)] = l23.lo;
  out[PATCH_MAJOR_INDEX(g, patch.s3, ij)] = l23.hi;
  out[PATCH_MAJOR_INDEX(g, patch.s4, ij)] = l45.lo;
  out[PATCH_MAJOR_INDEX(g, patch.s5, ij)] = l45.hi;
  out[PATCH_MAJOR_INDEX(g, patch.s6, ij)] = l67.lo;
  out[PATCH_MAJOR_INDEX(g, patch.s7, ij)] = l67.hi;
}

/* The same into an atlas layer: store_lanes4() on buffers, a write per
 * lane on images. */
TEXEL_INLINE void atlas_store_lanes4(ATLAS_OUT out, int2 g, int8 patch, int2 ij, float8 x, float8 y, float8 z,
                                     float8 w)
{
#ifdef ATLAS_IMAGE
#define STORE_LANE(l) ATLAS_STORE(out, g, patch.s##l, ij, (float4)(x.s##l, y.s##l, z.s##l, w.s##l));
  STORE_LANE(0) STORE_LANE(1) STORE_LANE(2) STORE_LANE(3) STORE_LANE(4) STORE_LANE(5) STORE_LANE(6) STORE_LANE(7)
#undef STORE_LANE
#else
  store_lanes4(out, g, patch, ij, x, y, z, w);
#endif
}

/* Texel ij of the patches `patch` set to (x, y, z, 0). */
TEXEL_INLINE void store_lanes(__global float4 *out, int2 g, int8 patch, int2 ij, float8 x, float8 y, float8 z)
{
  store_lanes4(out, g, patch, ij, x, y, z, (float8)(0.0f));
}

TEXEL_INLINE Lanes lanes_sub(Lanes a, Lanes b)
{
  Lanes r;
  r.x = a.x - b.x;
  r.y = a.y - b.y;
  r.z = a.z - b.z;
  return r;
}

TEXEL_INLINE Lanes lanes_scale(Lanes a, float8 s)
{
  Lanes r;
  r.x = a.x * s;
  r.y = a.y * s;
  r.z = a.z * s;
  return r;
}

TEXEL_INLINE Lanes lanes_cross(Lanes a, Lanes b)
{
  Lanes r;
  r.x = a.y * b.z - a.z * b.y;
  r.y = a.z * b.x - a.x * b.z;
  r.z = a.x * b.y - a.y * b.x;
  return r;
}

/* dot()'s sum, lane by lane. */
TEXEL_INLINE float8 lanes_dot(Lanes a, Lanes b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }
