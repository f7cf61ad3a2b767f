/* The painted surface per welded vertex, written straight into the arrays a
 * viewer draws (buffers in host memory): points displaced along the limit
 * normal, normals and channels, as PaintSurface::painted_surface() computes
 * them on the host, bit for bit. Every stored copy of a shared texel holds
 * the same bits, so the copies of one vertex write the same values.
 *
 * A value is written only where it differs, and the array's flag is then
 * set: the viewer re-uploads only the arrays that changed. */

#define DISPLAY_PUT(out, flag, index, value) \
  do {                                       \
    if (as_uint(out[index]) != as_uint(value)) { \
      out[index] = (value);                  \
      changed[flag] = 1;                     \
    }                                        \
  } while (0)

inline void put3(__global float *out, __global int *changed, int flag, int v, float4 value)
{
  DISPLAY_PUT(out, flag, 3 * v, value.x);
  DISPLAY_PUT(out, flag, 3 * v + 1, value.y);
  DISPLAY_PUT(out, flag, 3 * v + 2, value.z);
}

/* The texel of this work item, its index t and its welded vertex v; false
 * past the listed tiles. */
inline int display_texel(int2 g, __global const int *list, int count, __global const int *vertex_of, int *p,
                         int2 *ij, int *t, int *v)
{
  if (!tile_texel(g, list, count, p, ij))
    return 0;
  *t = PATCH_MAJOR_INDEX(g, *p, *ij);
  *v = vertex_of[*t];
  return *v >= 0;
}

/* Range: (tile, tile * count) over the listed patches (null: all).
 * Flags: 0 points, 1 normals, 2 diffuse, 3 specular, 4 roughness,
 * 5 displacement, 6 mask, 7 label. */
__kernel void display_vertices(ATLAS_IN positions, ATLAS_IN normals, __global const float4 *diffuse,
                               __global const float4 *specular, __global const float4 *material, int2 g,
                               __global const int *list, int count, __global const int *vertex_of,
                               __global float *points, __global float *out_normals, __global float *out_diffuse,
                               __global float *out_specular, __global float *roughness,
                               __global float *displacement, __global float *mask, __global int *label,
                               __global int *changed)
{
  int p, t, v;
  int2 ij;
  if (!display_texel(g, list, count, vertex_of, &p, &ij, &t, &v))
    return;
  const float4 n = ATLAS_LOAD(normals, g, p, ij);
  const float4 m = material[t];
  /* P = P0 + h N, one product and one sum per coordinate (no contraction). */
  const float4 point = ATLAS_LOAD(positions, g, p, ij) + m.y * n;
  put3(points, changed, 0, v, point);
  put3(out_normals, changed, 1, v, n);
  put3(out_diffuse, changed, 2, v, diffuse[t]);
  put3(out_specular, changed, 3, v, specular[t]);
  DISPLAY_PUT(roughness, 4, v, m.x);
  DISPLAY_PUT(displacement, 5, v, m.y);
  DISPLAY_PUT(mask, 6, v, m.w);
  if (label[v] != (int)m.z) {
    label[v] = (int)m.z;
    changed[7] = 1;
  }
}

/* The inside's channels of a two-sided surface. Flags: 8 inside_diffuse,
 * 9 inside_specular, 10 inside_roughness. */
__kernel void display_inside(__global const float4 *diffuse, __global const float4 *specular,
                             __global const float4 *material, int2 g, __global const int *list, int count,
                             __global const int *vertex_of, __global float *out_diffuse,
                             __global float *out_specular, __global float *roughness, __global int *changed)
{
  int p, t, v;
  int2 ij;
  if (!display_texel(g, list, count, vertex_of, &p, &ij, &t, &v))
    return;
  put3(out_diffuse, changed, 8, v, diffuse[t]);
  put3(out_specular, changed, 9, v, specular[t]);
  DISPLAY_PUT(roughness, 10, v, material[t].x);
}
