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

/* A patch and which of its corners (0..3) the ring vertex is. */
typedef struct {
  mp_int patch;
  mp_int corner;
} CornerSlot;

#ifndef __OPENCL_VERSION__
} /* namespace meshpaint */
#endif

#endif /* MESHPAINT_ATLAS_TYPES_H */
