/* Structs shared by the host (C++17) and the kernels (OpenCL C 1.2).
 * Only 32-bit integer members, so both sides agree on the layout. */
#ifndef MESHPAINT_ATLAS_TYPES_H
#define MESHPAINT_ATLAS_TYPES_H

#ifndef __OPENCL_VERSION__
#include <cstdint>
namespace meshpaint {
typedef std::int32_t mp_int;
#else
typedef int mp_int;
#endif

/* One level-1 edge, i.e. one shared side of two patches. patch[1] is -1 on a
 * mesh boundary. Sides are numbered 0..3 counter-clockwise from the patch's
 * first corner; the shared side runs in opposite directions in the two
 * patches. */
typedef struct {
  mp_int patch[2];
  mp_int side[2];
} PatchEdge;

/* One level-1 vertex, i.e. one patch corner stored once per incident patch.
 * Its slots (first .. first+count-1 in the slot table) list the incident
 * patches in order around the vertex: each next patch lies across the
 * incoming side of the previous one. On a boundary the first slot's outgoing
 * side and the last slot's incoming side are mesh-boundary sides. */
typedef struct {
  mp_int first;
  mp_int count;
  mp_int boundary;
  mp_int pad;
} CornerRing;

/* The most slots of an interior ring whose corners a multi-step
 * subdivision refines in private memory (subdivide_corner_levels); wider
 * rings take theirs from each level. */
#define RING_LEVELS_MAX 16

/* Patches per work item of encode_patches (CPUs), a patch per lane of
 * float8 arithmetic. */
#define PATCH_LANES 8

/* Consecutive patches per cluster, whose bounding sphere lets the brush's
 * passes over every patch (brush_cull, brush_reach) leave far clusters at
 * one test (CPUs: cluster_bounds, brush_cull_clusters,
 * brush_reach_clusters). */
#define PATCH_CLUSTER 64

/* A patch and which of its corners (0..3) the ring vertex is. */
typedef struct {
  mp_int patch;
  mp_int corner;
} CornerSlot;

/* Brush falloff profiles, over d / radius in [0, 1]. */
#define FALLOFF_CONSTANT 0
#define FALLOFF_LINEAR 1
#define FALLOFF_SMOOTHSTEP 2
#define FALLOFF_GAUSSIAN 3

/* The paint equation's ops: surface = lerp(surface, paint OP surface, a). */
#define PAINT_OP_COPY 0
#define PAINT_OP_OVER 1
#define PAINT_OP_MAX 2
#define PAINT_OP_ADD 3
#define PAINT_OP_SUBTRACT 4

/* Paint channels: diffuse and specular are rgb layers; the material layer
 * holds (roughness, displacement, label, mask). */
#define CHANNEL_DIFFUSE 0
#define CHANNEL_SPECULAR 1
#define CHANNEL_ROUGHNESS 2
#define CHANNEL_DISPLACEMENT 3
#define CHANNEL_LABEL 4
#define CHANNEL_MASK 5
#define CHANNEL_COUNT 6

/* Patterns of pattern paint (paint = pigment in pattern(coordinate)). */
#define PATTERN_NONE 0
#define PATTERN_NOISE 1      /* gradient noise, 0..1 */
#define PATTERN_TURBULENCE 2 /* sum of |noise| over octaves */
#define PATTERN_MARBLE 3     /* sin(x + turbulence), veins */
#define PATTERN_BATH 4       /* 1 below the plane z = 0 of the pattern space, soft edge */
#define PATTERN_IMAGE 5      /* a 2D image over pattern-space x, y in [0, 1), repeated */
#define PATTERN_VOLUME 6     /* a 3D voxel array over pattern-space [0, 1)^3, clamped */

#define PATTERN_COORD_POSITION 0 /* the surface point: solid textures */
#define PATTERN_COORD_UV 1       /* the patch parameters (u, v, 0) */
#define PATTERN_COORD_SCREEN 2   /* the view plane: (x, y, 0), the view's half angle at 1 */

#define MATTE_SELF 0   /* the pattern value is the pigment's coverage */
#define MATTE_OPAQUE 1 /* full coverage; the pattern value shades the pigment */

/* One brush dab. value[c] holds channel c's paint (rgb for diffuse and
 * specular, x for the others); alpha[c] its alpha, 0 leaving it untouched.
 * Floats and ints only, so both sides agree on the layout. */
typedef struct {
  float centre[4];                /* xyz: world position of the brush centre */
  float radius;                   /* world units */
  float strength;                 /* scales every alpha */
  mp_int falloff;                 /* FALLOFF_* */
  mp_int op;                      /* PAINT_OP_* */
  float value[CHANNEL_COUNT][4];
  float alpha[CHANNEL_COUNT];
  float specular_coefficient;     /* >= 0: paint the specular colour's largest component to this, keeping its hue */
  mp_int pattern;                 /* PATTERN_* */
  mp_int pattern_coord;           /* PATTERN_COORD_* */
  mp_int matte;                   /* MATTE_* */
  mp_int octaves;
  float pattern_transform[12];    /* rows of a 3x4 matrix: world (or uv) to pattern space */
  mp_int raster_size[4];          /* pattern image or volume: width, height, depth, channels */
  mp_int stamp_size[2];           /* brush stamp: width, height; 0: none */
  float stamp_u[4], stamp_v[4];   /* the stamp's axes in the tangent plane at the centre */
  mp_int space;                   /* SPACE_* */
  mp_int paint_backfaces;         /* tangent, screen: 0 skips faces turned away from the brush */
  float centre_normal[4];         /* the surface normal at the centre */
  float eye[4], view_right[4], view_up[4], view_dir[4]; /* screen: the camera and its unit axes */
  float screen_centre[2];         /* screen: the centre on the view plane, (x / z, y / z) */
  float centre_depth;             /* screen: the centre's distance along view_dir */
  float focal;                    /* screen: 1 / tan(view angle / 2) */
  mp_int unfolded;                /* parameter: entries of the dab's PatchUnfolding table */
  float centre_texel[2];          /* parameter: the centre in the texels of its patch */
  float texel_size;               /* parameter: world units per texel there */
  float side_sign;                /* 1 painting the outside, -1 the inside: the side a normal points to */
  mp_int only_over_label;         /* label channel: the one class a dab may overwrite; -1 any */
  mp_int locked_labels;           /* label channel: entries of the list of classes never overwritten */
} BrushDab;

/* What the culling kernel reports for a patch that reaches into the brush:
 * the patch and its closest texel, where the host snaps the brush centre. */
typedef struct {
  mp_int patch;
  mp_int closest_texel;           /* patch-major index within the tile */
  float distance;                 /* closest texel to the centre */
  mp_int pad;
  float closest_position[4];      /* that texel on the limit surface */
  float closest_normal[4];        /* and its limit normal */
} CullRecord;

/* What the reach kernel reports for a patch no texel of which comes within
 * the brush's reach; otherwise bit s says whether side s does. */
#define REACH_NONE 255

/* Where a parameter-space dab lays some texels of a patch: texel (i, j)
 * lies at i * u + j * v + n * offset in the texels of the patch under the
 * dab's centre (n texels per tile side): a rotation by a multiple of 90
 * degrees and a shift by whole tiles, the same at every level. */
typedef struct {
  mp_int u[2];
  mp_int v[2];
  mp_int offset[2];               /* in tile sides */
  mp_int valid;                   /* 0: the dab leaves these texels alone */
  mp_int pad;
} TexelMap;

/* A parameter-space dab's maps for one listed patch, by the part of the
 * tile a texel lies in. Every stored copy of a side or corner texel takes
 * the map of the same patch, so copies get the same bits. */
#define UNFOLD_INTERIOR 0
#define UNFOLD_SIDE 1                 /* + side, 0..3: the side's texels without its corners */
#define UNFOLD_CORNER 5               /* + corner, 0..3 */
#define UNFOLD_PARTS 9
typedef struct {
  TexelMap part[UNFOLD_PARTS];
} PatchUnfolding;

/* Brush spaces: where the brush's distance to its centre is measured. */
#define SPACE_OBJECT 0    /* in space: a ball around the centre */
#define SPACE_TANGENT 1   /* in the tangent plane at the centre: the stamp projected along the normal */
#define SPACE_SCREEN 2    /* on the view plane, scaled to world units at the centre's depth */
#define SPACE_PARAMETER 3 /* in the parameters of the centre's patch, unfolded across its sides: a square of texels */

/* Geometry tools: how a dab moves control points. */
#define MOVE_SCULPT 0   /* along the normal at the brush centre */
#define MOVE_INFLATE 1  /* along each point's own normal */
#define MOVE_FLATTEN 2  /* towards the plane through the centre */

#ifndef __OPENCL_VERSION__
} /* namespace meshpaint */
#endif

#endif /* MESHPAINT_ATLAS_TYPES_H */
