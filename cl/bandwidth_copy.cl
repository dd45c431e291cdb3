/* boreas: a float4 copy, the memory-bandwidth yardstick the benchmarks compare against. */
__kernel void boreas_bandwidth_copy(__global const float4* in, __global float4* out) {
  int id = get_global_id(0);
  out[id] = in[id];
}
