/* boreas: ambient occlusion of a tree's crown (Kusternig et al. sec. 3.4, 6.1: per-vertex
 * occlusion precomputed over the crown and tinted by the leaves' translucency), as a
 * light-transport estimate rather than a visibility count. The crown is a grid of leaf area
 * density (m^2 of leaf per m^3, built by the host from the leaves' centres, their area
 * calibrated to the species' leaf area index: trees/leaf_occlusion.h); light from a uniform
 * sky reaching a point from direction w has crossed an optical depth
 *     tau(w) = Omega G(w) * integral of density along the ray
 * (Nilson's gap probability in a clumped canopy: G(w) the projection of the leaves' area
 * toward w, computed by the host from their normals, Ross; Omega the species' clumping
 * index), and each leaf it meets passes the fraction t of it on (its transmittance), so
 * channel c is attenuated by exp(-(1 - t_c) tau). The occlusion is the cosine-weighted mean
 * of that over the upper hemisphere: directions come cosine-distributed from the host with
 * equal weights.
 *
 * Two kernels: one work-item per voxel marches the directions from its centre (the sample at
 * a point is its voxel's density, taken at the middle of each half-cell step, so the
 * integral is exact for the piecewise constant grid, its own voxel's upper half included);
 * one work-item per leaf takes the voxels' values trilinearly at its centre.
 * Run once per tree when it is drawn, not per step: not a hot kernel. */

__kernel void boreas_leaf_occlusion_grid(__global const float* density, int nx, int ny, int nz,
                                         float cell, __global const float* directions,
                                         __global const float* projection, int count, float clumping,
                                         float extinction_r, float extinction_g, float extinction_b,
                                         __global float* occlusion) {
  const int v = (int)get_global_id(0);
  if (v >= nx * ny * nz) return;
  const int ix = v % nx, iy = (v / nx) % ny, iz = v / (nx * ny);
  /* Voxel units: the grid spans [0, n) on each axis, voxel (i, j, k) centred at +0.5. */
  const float px = (float)ix + 0.5f, py = (float)iy + 0.5f, pz = (float)iz + 0.5f;
  float sum_r = 0.0f, sum_g = 0.0f, sum_b = 0.0f;
  for (int d = 0; d < count; ++d) {
    const float dx = directions[3 * d], dy = directions[3 * d + 1], dz = directions[3 * d + 2];
    float depth = 0.0f; /* integral of density, m^2/m^3 * voxels */
    for (float s = 0.25f;; s += 0.5f) {
      const float x = px + s * dx, y = py + s * dy, z = pz + s * dz;
      if (x < 0.0f || y < 0.0f || z < 0.0f || x >= (float)nx || y >= (float)ny || z >= (float)nz) break;
      depth += density[((int)z * ny + (int)y) * nx + (int)x];
    }
    /* Omega G, half-cell steps, metres per voxel */
    const float tau = clumping * projection[d] * depth * 0.5f * cell;
    sum_r += exp(-extinction_r * tau);
    sum_g += exp(-extinction_g * tau);
    sum_b += exp(-extinction_b * tau);
  }
  const float w = 1.0f / (float)count;
  occlusion[3 * v] = sum_r * w;
  occlusion[3 * v + 1] = sum_g * w;
  occlusion[3 * v + 2] = sum_b * w;
}

__kernel void boreas_leaf_occlusion_leaves(__global const float* occlusion, int nx, int ny, int nz,
                                           float origin_x, float origin_y, float origin_z, float cell,
                                           __global const float* points, int count, __global float* out) {
  const int i = (int)get_global_id(0);
  if (i >= count) return;
  /* Voxel-centre coordinates, clamped to the grid's centres (the grid holds every leaf). */
  const float gx = clamp((points[3 * i] - origin_x) / cell - 0.5f, 0.0f, (float)(nx - 1));
  const float gy = clamp((points[3 * i + 1] - origin_y) / cell - 0.5f, 0.0f, (float)(ny - 1));
  const float gz = clamp((points[3 * i + 2] - origin_z) / cell - 0.5f, 0.0f, (float)(nz - 1));
  /* The lower corner of the cell around the point: at most the second-to-last centre. */
  const int x0 = min((int)gx, max(nx - 2, 0)), y0 = min((int)gy, max(ny - 2, 0)), z0 = min((int)gz, max(nz - 2, 0));
  const int x1 = min(x0 + 1, nx - 1), y1 = min(y0 + 1, ny - 1), z1 = min(z0 + 1, nz - 1);
  const float fx = gx - (float)x0, fy = gy - (float)y0, fz = gz - (float)z0;
  for (int c = 0; c < 3; ++c) {
#define BOREAS_AO(X, Y, Z) occlusion[3 * (((Z) * ny + (Y)) * nx + (X)) + c]
    const float a = mix(BOREAS_AO(x0, y0, z0), BOREAS_AO(x1, y0, z0), fx);
    const float b = mix(BOREAS_AO(x0, y1, z0), BOREAS_AO(x1, y1, z0), fx);
    const float d = mix(BOREAS_AO(x0, y0, z1), BOREAS_AO(x1, y0, z1), fx);
    const float e = mix(BOREAS_AO(x0, y1, z1), BOREAS_AO(x1, y1, z1), fx);
#undef BOREAS_AO
    out[3 * i + c] = mix(mix(a, b, fy), mix(d, e, fy), fz);
  }
}
