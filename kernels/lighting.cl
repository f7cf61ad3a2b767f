/* Texture-space subsurface lighting (Ritschel et al. 2006, section 7): the
 * irradiance of a directional light, stored per texel, then blurred over the
 * atlas with the smoothing kernels, which lets light bleed under the surface
 * into the shadowed side of thin parts. */

/* Range: (tile, tile * count), every patch. out (patch-major): the
 * irradiance max(0, n . light) in xyz, 1 in w. */
__kernel void irradiance(ATLAS_IN nrm, int2 g, int count, float4 light, __global float4 *out)
{
  int p;
  int2 ij;
  if (!tile_texel(g, 0, count, &p, &ij))
    return;
  const float e = fmax(0.0f, dot(ATLAS_LOAD(nrm, g, p, ij).xyz, light.xyz));
  out[PATCH_MAJOR_INDEX(g, p, ij)] = (float4)(e, e, e, 1.0f);
}
