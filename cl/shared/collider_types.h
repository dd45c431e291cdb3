/* boreas: a collider as the plants' kernels see it over one step — a sphere, a capsule or
 * an oriented box, written as one shape: the box of half extents h (local axes ax, ay,
 * az) grown by a radius r. A sphere is h = 0, a capsule h = (0, half_height, 0), a box
 * r = 0. Over the step the shape moves by d = velocity dt from its position at the step's
 * start (translation swept exactly; the orientation is the one at the middle of the step:
 * a turn within one step is not swept). Written by host/src/colliders/collider.cpp.
 * Compiles as OpenCL C and C++. */
#ifndef BOREAS_CL_SHARED_COLLIDER_TYPES_H
#define BOREAS_CL_SHARED_COLLIDER_TYPES_H

typedef struct BoreasGpuCollider {
  float cx, cy, cz; /* position at the step's start, m */
  float radius;     /* m: the sphere's or capsule's radius; 0 for a box */
  float dx, dy, dz; /* its move over the step, m (world) */
  float pad0;
  float lx, ly, lz; /* that move in its own axes: d . ax, d . ay, d . az, m */
  float pad1;
  float ix, iy, iz; /* 1 / lx, 1 / ly, 1 / lz, or 1e20 where the move has no part along
                       the axis: finite, so with positions within 1e9 m the slab test's
                       ends stay finite and no NaN comes of them */
  float pad2;
  float axx, axy, axz, hx; /* local x axis (unit, world) and the half extent along it, m */
  float ayx, ayy, ayz, hy;
  float azx, azy, azz, hz;
} BoreasGpuCollider;

/* A collider that touches nothing: far away, no size (padding slots). */
#define BOREAS_SILENT_COLLIDER_POSITION 1e9f

#endif
