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

/* Helpers that a kernel calls per texel: PoCL's compiler leaves some of
 * them as calls, which keeps its work-item loops from vectorising. */
#ifdef __clang__
#define TEXEL_INLINE inline __attribute__((always_inline))
#else
#define TEXEL_INLINE inline
#endif

/* Texel (p, ij) of grid g in patch-major order: buffers of any per-texel
 * data (weights, details) and the buffer storage path share it. */
#define PATCH_MAJOR_INDEX(g, p, ij) (((p) * (g).x + (ij).y) * (g).x + (ij).x)

#ifdef ATLAS_IMAGE
#define ATLAS_IN __read_only image2d_t
#define ATLAS_OUT __write_only image2d_t
#define ATLAS_LOAD(a, g, p, ij) read_imagef((a), tile_origin((p), (g)) + (ij))
#define ATLAS_STORE(a, g, p, ij, v) write_imagef((a), tile_origin((p), (g)) + (ij), (v))
#else
#define ATLAS_IN __global const float4 *restrict
#define ATLAS_OUT __global float4 *restrict
#define ATLAS_INDEX(g, p, ij) PATCH_MAJOR_INDEX(g, p, ij)
#define ATLAS_LOAD(a, g, p, ij) ((a)[ATLAS_INDEX(g, p, ij)])
#define ATLAS_STORE(a, g, p, ij, v) ((a)[ATLAS_INDEX(g, p, ij)] = (v))
#endif


/* Texel of the patch's first corner in the atlas image. */
inline int2 tile_origin(int patch, int2 g)
{
  return (int2)((patch % g.y) * g.x, (patch / g.y) * g.x);
}

/* A patch seen from one of its sides or corners: texel (t, d) is
 * o + t * dt + d * dd, t running along the side (or the corner's outgoing
 * side) and d inwards. Sides and corners are numbered 0..3 counter-clockwise
 * from the patch's first corner; every frame is a rotation of the patch's
 * own, so it keeps the orientation. Branch-free: the tables replace a switch
 * per texel, which the CPU vectoriser handles badly. */
typedef struct {
  int patch;
  int2 o, dt, dd;
} Frame;

__constant int2 kCornerUnit[4] = {(int2)(0, 0), (int2)(1, 0), (int2)(1, 1), (int2)(0, 1)};
__constant int2 kSideDir[4] = {(int2)(1, 0), (int2)(0, 1), (int2)(-1, 0), (int2)(0, -1)};

inline Frame side_frame(int patch, int side, int n)
{
  Frame f;
  f.patch = patch;
  f.o = kCornerUnit[side & 3] * n;
  f.dt = kSideDir[side & 3];
  f.dd = kSideDir[(side + 1) & 3];
  return f;
}

/* The patch across an edge in the other patch's (t, d) terms: position t of
 * this side is n - t of that one, and d < 0 reaches -d texels into it. */
inline Frame across_frame(int patch, int side, int n)
{
  Frame f;
  f.patch = patch;
  f.o = kCornerUnit[(side + 1) & 3] * n;
  f.dt = -kSideDir[side & 3];
  f.dd = -kSideDir[(side + 1) & 3];
  return f;
}

/* A frame as a texel and two steps. FRAME_LOAD goes through it, and a
 * kernel that reads many texels of one frame keeps it (reduce_second_step):
 * the index arithmetic once, not per load. */
#ifdef ATLAS_IMAGE
typedef struct {
  int2 at, dt, dd;
} FrameSteps;
inline FrameSteps frame_steps(int2 g, Frame f)
{
  FrameSteps s;
  s.at = tile_origin(f.patch, g) + f.o;
  s.dt = f.dt;
  s.dd = f.dd;
  return s;
}
#define STEPS_LOAD(a, s, t, d) read_imagef((a), (s).at + (t) * (s).dt + (d) * (s).dd)
#define STEPS_STORE(a, s, t, d, v) write_imagef((a), (s).at + (t) * (s).dt + (d) * (s).dd, (v))
#else
typedef struct {
  int at, dt, dd;
} FrameSteps;
inline FrameSteps frame_steps(int2 g, Frame f)
{
  FrameSteps s;
  s.at = ATLAS_INDEX(g, f.patch, f.o);
  s.dt = f.dt.y * g.x + f.dt.x;
  s.dd = f.dd.y * g.x + f.dd.x;
  return s;
}
#define STEPS_LOAD(a, s, t, d) ((a)[(s).at + (t) * (s).dt + (d) * (s).dd])
#define STEPS_STORE(a, s, t, d, v) ((a)[(s).at + (t) * (s).dt + (d) * (s).dd] = (v))
#endif
#define FRAME_LOAD(a, g, f, t, d) STEPS_LOAD(a, frame_steps(g, f), t, d)
#define FRAME_STORE(a, g, f, t, d, v) STEPS_STORE(a, frame_steps(g, f), t, d, v)

/* Declares the frames of an edge's two patches (fp, fq) for reading grid g. */
#define EDGE_FRAMES(e, g)                                                   \
  const Frame fp = side_frame((e).patch[0], (e).side[0], (g).x - 1);        \
  const Frame fq = across_frame(max((e).patch[1], 0), (e).side[1], (g).x - 1)

/* Texel (t, d) around the edge: d >= 0 in the first patch, d < 0 across. */
#define EDGE_LOAD(src, g, t, d) ((d) >= 0 ? FRAME_LOAD(src, g, fp, t, d) : FRAME_LOAD(src, g, fq, t, d))

/* Writes one edge texel to both patches that store it, in grid g (which may
 * be another level than the frames were declared for). */
#define EDGE_STORE(dst, g, e, t, v)                                                    \
  do {                                                                                 \
    FRAME_STORE(dst, g, side_frame((e).patch[0], (e).side[0], (g).x - 1), t, 0, v);    \
    if ((e).patch[1] >= 0)                                                             \
      FRAME_STORE(dst, g, across_frame((e).patch[1], (e).side[1], (g).x - 1), t, 0, v); \
  } while (0)

/* Texel (a, b) seen from a ring slot's corner: a along the slot's outgoing
 * side, b along its incoming side. */
#define CORNER_LOAD(src, g, slot, a, b) FRAME_LOAD(src, g, side_frame((slot).patch, (slot).corner, (g).x - 1), a, b)
#define CORNER_STORE(dst, g, slot, v) FRAME_STORE(dst, g, side_frame((slot).patch, (slot).corner, (g).x - 1), 0, 0, v)

/* Prefetching for the kernels that gather around edges and rings, which
 * they take in list order, their tiles in no order. A CPU runs a
 * work-group's items one after another and waited on each miss in turn;
 * an item that asks for the tiles of the item PREFETCH_AHEAD places after
 * it overlaps them. Only where the host asks for it (-D ATLAS_PREFETCH:
 * CPU devices, buffer storage). */
#define PREFETCH_AHEAD 8
#if defined(ATLAS_PREFETCH) && defined(__clang__) && !defined(ATLAS_IMAGE)
/* A tile's cache lines (the first 8 of a big one, whose side kernels walk
 * far enough for the hardware's own prefetch). */
TEXEL_INLINE void prefetch_tile(__global const float4 *a, int2 g, int p)
{
  __global const char *t = (__global const char *)(a + PATCH_MAJOR_INDEX(g, p, (int2)(0, 0)));
  const int lines = min((g.x * g.x * 16 + 63) / 64, 8);
  for (int k = 0; k < lines; ++k)
    __builtin_prefetch(t + 64 * k);
}

/* The tiles on both sides of edge list[k + PREFETCH_AHEAD]. */
inline void prefetch_edge_ahead(__global const float4 *a, int2 g, __global const PatchEdge *edges,
                                __global const int *list, int k, int count)
{
  if (k + PREFETCH_AHEAD >= count)
    return;
  const PatchEdge e = edges[list ? list[k + PREFETCH_AHEAD] : k + PREFETCH_AHEAD];
  prefetch_tile(a, g, e.patch[0]);
  if (e.patch[1] >= 0)
    prefetch_tile(a, g, e.patch[1]);
}

/* The tiles across the sides of patch list[k + PREFETCH_AHEAD], from its
 * entry in a patch_across table (4 * patch + side, -1 on a boundary). */
TEXEL_INLINE void prefetch_across_ahead(__global const float4 *a, int2 g, __global const int4 *across,
                                        __global const int *list, int k, int count)
{
  if (k + PREFETCH_AHEAD >= count)
    return;
  const int4 x = across[list ? list[k + PREFETCH_AHEAD] : k + PREFETCH_AHEAD];
  prefetch_tile(a, g, max(x.x, 0) >> 2);
  prefetch_tile(a, g, max(x.y, 0) >> 2);
  prefetch_tile(a, g, max(x.z, 0) >> 2);
  prefetch_tile(a, g, max(x.w, 0) >> 2);
}

/* The texels at the corners of ring list[k + PREFETCH_AHEAD]. */
inline void prefetch_ring_ahead(__global const float4 *a, int2 g, __global const CornerRing *rings,
                                __global const CornerSlot *slots, __global const int *list, int k, int count)
{
  if (k + PREFETCH_AHEAD >= count)
    return;
  const CornerRing ring = rings[list ? list[k + PREFETCH_AHEAD] : k + PREFETCH_AHEAD];
  if (g.x == 2) { /* level 1: a slot's texels are its whole tile, one cache line */
    for (int i = 0; i < ring.count; ++i)
      __builtin_prefetch(a + PATCH_MAJOR_INDEX(g, slots[ring.first + i].patch, (int2)(0, 0)));
    return;
  }
  for (int i = 0; i < ring.count; ++i) {
    const CornerSlot slot = slots[ring.first + i];
    const Frame f = side_frame(slot.patch, slot.corner, g.x - 1);
    __builtin_prefetch(a + PATCH_MAJOR_INDEX(g, f.patch, f.o));
    __builtin_prefetch(a + PATCH_MAJOR_INDEX(g, f.patch, f.o + f.dt + f.dd));
  }
}
#define PREFETCH_TILE(a, g, p) prefetch_tile((a), (g), (p))
#define PREFETCH_TEXEL(a, g, p, ij) __builtin_prefetch((a) + PATCH_MAJOR_INDEX(g, p, ij))
#define PREFETCH_EDGE_AHEAD(a, g, edges, list, k, count) prefetch_edge_ahead((a), (g), (edges), (list), (k), (count))
#define PREFETCH_RING_AHEAD(a, g, rings, slots, list, k, count) \
  prefetch_ring_ahead((a), (g), (rings), (slots), (list), (k), (count))
#define PREFETCH_ACROSS_AHEAD(a, g, across, list, k, count) \
  prefetch_across_ahead((a), (g), (across), (list), (k), (count))
#else
#define PREFETCH_TILE(a, g, p) ((void)0)
#define PREFETCH_TEXEL(a, g, p, ij) ((void)0)
#define PREFETCH_EDGE_AHEAD(a, g, edges, list, k, count) ((void)0)
#define PREFETCH_RING_AHEAD(a, g, rings, slots, list, k, count) ((void)0)
#define PREFETCH_ACROSS_AHEAD(a, g, across, list, k, count) ((void)0)
#endif

/* Patch and texel of a work item of a kernel over whole tiles, whose range
 * is (tile, tile * count): the patch is list[a], or a itself when list is
 * null (every patch). Returns 0 for the rounding tail. */
inline int tile_texel(int2 g, __global const int *list, int count, int *p, int2 *ij)
{
  const int i = get_global_id(0), y = get_global_id(1);
  const int a = y / g.x;
  *ij = (int2)(i, y - a * g.x);
  if (a >= count)
    return 0;
  *p = list ? list[a] : a;
  return 1;
}

/* Whole-tile kernels come in two forms: a work item per texel (*_tiles,
 * range (tile, tile * count)), which GPUs want, and a work item per patch
 * walking its tile row by row (*_patches, range count). CPUs run a group's
 * items one after another: there the item per patch reads the patch's
 * tables once and spends nothing on working out its patch and texel.
 * The body of a *_patches kernel: runs the
 * statement given last for each texel ij of patch p (list[k] for item k, or
 * k when list is null), row by row; k is `patch_item`. Not variadic: OpenCL C
 * has no variadic macros (NVIDIA's compiler refuses them), and a call's
 * commas sit inside its own parentheses. */
#define FOR_EACH_PATCH_TEXEL(g, list, count, statement)   \
  do {                                                    \
    const int patch_item = get_global_id(0);              \
    if (patch_item >= (count))                            \
      break;                                              \
    const int p = (list) ? (list)[patch_item] : patch_item; \
    for (int j_ = 0; j_ < (g).x; ++j_)                    \
      for (int i_ = 0; i_ < (g).x; ++i_) {                \
        const int2 ij = (int2)(i_, j_);                   \
        statement;                                        \
      }                                                   \
  } while (0)

/* The same for a kernel over the texels strictly inside patches (sides and
 * corners belong to the table-driven kernels), whose range is
 * (tile - 2, (tile - 2) * count): no work item lands on a side. */
inline int interior_texel(int2 g, __global const int *list, int count, int *p, int2 *ij)
{
  const int inner = g.x - 2;
  const int i = get_global_id(0), y = get_global_id(1);
  const int a = y / inner;
  *ij = (int2)(i + 1, y - a * inner + 1);
  if (a >= count)
    return 0;
  *p = list ? list[a] : a;
  return 1;
}

/* The sides (bits 0-3) and corners (bits 4-7) of a patch that texel ij of
 * an n x n tile lies on. */
inline int texel_border(int2 ij, int n)
{
  const int lo_i = ij.x == 0, hi_i = ij.x == n, lo_j = ij.y == 0, hi_j = ij.y == n;
  return lo_j | hi_i << 1 | hi_j << 2 | lo_i << 3 | (lo_i & lo_j) << 4 | (hi_i & lo_j) << 5 | (hi_i & hi_j) << 6 |
         (lo_i & hi_j) << 7;
}

/* The part of a tile texel ij lies in: UNFOLD_INTERIOR, UNFOLD_SIDE + side
 * or UNFOLD_CORNER + corner. */
inline int tile_part(int2 ij, int n)
{
  const int lo_i = ij.x == 0, hi_i = ij.x == n, lo_j = ij.y == 0, hi_j = ij.y == n;
  if ((lo_i || hi_i) && (lo_j || hi_j))
    return UNFOLD_CORNER + (lo_j ? (lo_i ? 0 : 1) : (hi_i ? 2 : 3));
  if (lo_j)
    return UNFOLD_SIDE + 0;
  if (hi_i)
    return UNFOLD_SIDE + 1;
  if (hi_j)
    return UNFOLD_SIDE + 2;
  return lo_i ? UNFOLD_SIDE + 3 : UNFOLD_INTERIOR;
}

/* Component c (0..3) of v. */
inline int int4_at(int4 v, int c)
{
  return c == 0 ? v.x : c == 1 ? v.y : c == 2 ? v.z : v.w;
}

/* The side (x) of texel ij on a side of the tile, corners excluded, and
 * its place t along that side in the patch's own frame (y). */
inline int2 side_place(int2 ij, int n)
{
  const int s = tile_part(ij, n) - UNFOLD_SIDE;
  return (int2)(s, s == 0 ? ij.x : s == 1 ? ij.y : s == 2 ? n - ij.x : n - ij.y);
}

/* Whole-tile kernels that copy their sides and corners from the compact
 * results of a side and a corner kernel (an entry per side texel, edge by
 * edge, and per ring): where texel ij on the border of a tile (n = tile - 1)
 * finds its value, through the patch's tables: per side 2 * edge + (1 when
 * the patch is the edge's second), per corner the ring. Returns the ring
 * for a corner (*corner = 1), else edge * (n - 1) + t - 1 with t along the
 * edge's first patch's side. */
inline int border_entry(int2 ij, int n, int4 sides, int4 rings, int *corner)
{
  const int part = tile_part(ij, n);
  *corner = part >= UNFOLD_CORNER;
  if (*corner)
    return int4_at(rings, part - UNFOLD_CORNER);
  const int2 st = side_place(ij, n);
  const int code = int4_at(sides, st.x);
  return (code >> 1) * (n - 1) + ((code & 1) ? n - st.y : st.y) - 1;
}

/* Entry of texel t along side s of a patch with side table ps. */
#define SIDE_ENTRY(n, ps, s, t)                                  \
  ((int4_at(ps, s) >> 1) * ((n) - 1) - 1 + ((int4_at(ps, s) & 1) ? (n) - (t) : (t)))

/* The per-patch walk of a tile whose border comes from compact arrays,
 * row by row as the tile lies in memory, but with no texel asking which
 * part it is in: BORDER(ij, k, corner, bit) for each texel on a side or
 * corner, with border_entry()'s k and corner, and bit the texel_border()
 * bit of its part; INSIDE(ij) for each texel strictly inside. n = tile - 1;
 * ps, pr: the patch's tables. */
#define FOR_EACH_TILE_PART(n, ps, pr, BORDER, INSIDE)                          \
  do {                                                                         \
    BORDER((int2)(0, 0), (pr).x, 1, 16);                                       \
    for (int t_ = 1; t_ < (n); ++t_)                                           \
      BORDER((int2)(t_, 0), SIDE_ENTRY(n, ps, 0, t_), 0, 1);                   \
    BORDER((int2)((n), 0), (pr).y, 1, 32);                                     \
    for (int j_ = 1; j_ < (n); ++j_) {                                         \
      BORDER((int2)(0, j_), SIDE_ENTRY(n, ps, 3, (n) - j_), 0, 8);             \
      for (int i_ = 1; i_ < (n); ++i_)                                         \
        INSIDE((int2)(i_, j_));                                                \
      BORDER((int2)((n), j_), SIDE_ENTRY(n, ps, 1, j_), 0, 2);                 \
    }                                                                          \
    BORDER((int2)(0, (n)), (pr).w, 1, 128);                                    \
    for (int t_ = 1; t_ < (n); ++t_)                                           \
      BORDER((int2)((n) - t_, (n)), SIDE_ENTRY(n, ps, 2, t_), 0, 4);           \
    BORDER((int2)((n), (n)), (pr).z, 1, 64);                                   \
  } while (0)

/* Kernel bodies over whole tiles whose border comes from compact arrays,
 * in the two forms: PATCH_ITEM_PARTS for a work item per patch (range
 * count) walking its tile with FOR_EACH_TILE_PART, TILE_TEXEL_PART for a
 * work item per texel (tile_texel()'s range) sent to BORDER or INSIDE.
 * Both declare p, n = tile - 1 and item (the patch's place in the list),
 * and end the kernel for the rounding tail and for a patch p where
 * SKIP(p) holds (NO_SKIP, or a set's flags: UNFLAGGED). */
#define NO_SKIP(p) 0
/* The start of any kernel with a work item per patch: declares item and p. */
#define PATCH_ITEM(list, count, SKIP)          \
  const int item = get_global_id(0);           \
  if (item >= (count))                         \
    return;                                    \
  const int p = LISTED(list, item);            \
  if (SKIP(p))                                 \
    return

#define PATCH_ITEM_PARTS(g, list, count, SKIP, patch_sides, patch_rings, BORDER, INSIDE) \
  PATCH_ITEM(list, count, SKIP);                                                  \
  const int n = (g).x - 1;                                                        \
  const int4 ps_ = (patch_sides)[p], pr_ = (patch_rings)[p];                      \
  FOR_EACH_TILE_PART(n, ps_, pr_, BORDER, INSIDE)

#define TILE_TEXEL_PART(g, list, count, SKIP, patch_sides, patch_rings, BORDER, INSIDE) \
  int p, corner_;                                                                     \
  int2 ij;                                                                            \
  if (!tile_texel(g, list, count, &p, &ij) || SKIP(p))                                \
    return;                                                                           \
  const int n = (g).x - 1, item = get_global_id(1) / (g).x;                           \
  if (ij.x > 0 && ij.x < n && ij.y > 0 && ij.y < n) {                                 \
    INSIDE(ij);                                                                       \
  } else {                                                                            \
    const int k_ = border_entry(ij, n, (patch_sides)[p], (patch_rings)[p], &corner_); \
    BORDER(ij, k_, corner_, texel_border(ij, n));                                     \
  }

/* Item k of a table-driven kernel: list[k], or k itself when list is null. */
#define LISTED(list, k) ((list) ? (list)[k] : (k))

/* The body's start of a kernel over rings (range: count): declares index
 * (list[item], or item when list is null) and its CornerRing ring, asks for
 * the tiles of a ring further on, and ends the kernel for the rounding tail
 * and for a ring outside a set's flags. */
#define RING_ITEM(src, g, rings, slots, list, count, flags, generation) \
  const int ring_item = get_global_id(0);                                \
  if (ring_item >= (count))                                              \
    return;                                                              \
  const int index = LISTED(list, ring_item);                             \
  if (UNFLAGGED(flags, generation, index))                               \
    return;                                                              \
  const CornerRing ring = (rings)[index];                                \
  PREFETCH_RING_AHEAD(src, g, rings, slots, list, ring_item, count)

/* A set worked out on the device (select.cl) comes as flags over every
 * item, not as a list: item x is in it when flags[x] holds the set's
 * generation. Kernels that take one run over every item (list null) and
 * leave the others, or over their list when flags is null. */
#define UNFLAGGED(flags, generation, x) ((flags) && (flags)[x] != (uchar)(generation))

