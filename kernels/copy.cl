/* A plain copy, float4 by float4: the device's copy bandwidth, which the
 * benchmarks set beside what each kernel family achieves. Inputs: src;
 * outputs: dst, both float4 (xyzw). */

/* Range: count (rounded up to whole groups). */
__kernel void copy_float4(__global const float4 *restrict src, __global float4 *restrict dst, int count)
{
  const int k = get_global_id(0);
  if (k < count)
    dst[k] = src[k];
}
