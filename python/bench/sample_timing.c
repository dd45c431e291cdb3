/* boreas for Python, benchmark: the C side of bench/sample_bench.py. Builds the world the
 * Python side builds (the grid and waves below, two steps), samples the wind at the same
 * count of points spread the same way, and prints the median wall time of one
 * boreas_wind_sample call over the runs.
 *
 *   boreas_sample_timing [points (default 1000000)] [runs (default 21)]
 *   -> "median_s 0.012345" on stdout */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "boreas/boreas.h"

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int by_value(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}

static int fail(const char* what) {
  fprintf(stderr, "boreas_sample_timing: %s: %s\n", what, boreas_last_error());
  return 1;
}

int main(int argc, char** argv) {
  int points = argc > 1 ? atoi(argv[1]) : 1000000;
  int runs = argc > 2 ? atoi(argv[2]) : 21;
  if (points < 1 || runs < 1) {
    fprintf(stderr, "usage: boreas_sample_timing [points] [runs]\n");
    return 2;
  }

  /* The world of sample_bench.py's make_world(). */
  boreas_world_def def = boreas_default_world_def();
  def.grid.origin[0] = -32.0f;
  def.grid.origin[1] = 0.0f;
  def.grid.origin[2] = -32.0f;
  def.grid.cell_size = 2.0f;
  def.grid.resolution[0] = 32;
  def.grid.resolution[1] = 8;
  def.grid.resolution[2] = 32;
  boreas_wave waves[3];
  const float params[3][6] = {/* dx, dz, amplitude, wavelength, speed, sharpness */
                              {0.8f, 0.6f, 5.0f, 40.0f, 6.0f, 1.0f},
                              {0.6f, 0.8f, 2.0f, 15.0f, 4.0f, 3.0f},
                              {1.0f, 0.2f, 1.0f, 7.0f, 3.0f, 2.0f}};
  for (int i = 0; i < 3; ++i) {
    waves[i] = boreas_default_wave();
    waves[i].direction[0] = params[i][0];
    waves[i].direction[1] = params[i][1];
    waves[i].amplitude = params[i][2];
    waves[i].wavelength = params[i][3];
    waves[i].speed = params[i][4];
    waves[i].sharpness = params[i][5];
  }
  def.waves = waves;
  def.wave_count = 3;
  boreas_world world = NULL;
  if (boreas_world_create(&def, &world) != BOREAS_OK) return fail("boreas_world_create");
  for (int i = 0; i < 2; ++i)
    if (boreas_world_step(world, 1.0f / 30.0f) != BOREAS_OK) return fail("boreas_world_step");

  /* Points uniform in [-40, 40] x [0, 20] x [-40, 40] m, as sample_bench.py's. */
  float* xyz = malloc(sizeof(float) * 3 * (size_t)points);
  float* wind = malloc(sizeof(float) * 3 * (size_t)points);
  double* seconds = malloc(sizeof(double) * (size_t)runs);
  if (!xyz || !wind || !seconds) return 1;
  unsigned long long state = 12345;
  for (size_t i = 0; i < 3 * (size_t)points; ++i) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    double u = (double)(state >> 11) / 9007199254740992.0; /* [0, 1) */
    xyz[i] = (float)(i % 3 == 1 ? 20.0 * u : 80.0 * u - 40.0);
  }

  if (boreas_wind_sample(world, xyz, points, wind) != BOREAS_OK) /* warm-up */
    return fail("boreas_wind_sample");
  for (int r = 0; r < runs; ++r) {
    double t0 = now();
    if (boreas_wind_sample(world, xyz, points, wind) != BOREAS_OK)
      return fail("boreas_wind_sample");
    seconds[r] = now() - t0;
  }
  qsort(seconds, (size_t)runs, sizeof(double), by_value);
  printf("median_s %.9f\n", seconds[runs / 2]);
  free(xyz);
  free(wind);
  free(seconds);
  boreas_world_destroy(world);
  return 0;
}
