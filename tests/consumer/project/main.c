/* A C program against the installed boreas: a steady wind must read back as set, and a
 * bad argument and a removed or null id must be refused. Exits non-zero on any failure. */
#include <boreas/boreas.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

int main(void) {
  /* The library loaded is the one this program was built against. */
  char header_version[32];
  snprintf(header_version, sizeof header_version, "%d.%d.%d", BOREAS_VERSION_MAJOR,
           BOREAS_VERSION_MINOR, BOREAS_VERSION_PATCH);
  if (strcmp(boreas_version(), header_version) != 0) {
    fprintf(stderr, "library %s, header %s\n", boreas_version(), header_version);
    return 1;
  }
  boreas_world_def def = boreas_default_world_def();
  boreas_world world = NULL;
  if (boreas_world_create(&def, &world) != BOREAS_OK) {
    fprintf(stderr, "create: %s\n", boreas_last_error());
    return 1;
  }
  boreas_wave wave = boreas_default_wave();
  wave.direction[0] = 0.0f;
  wave.direction[1] = 2.0f;
  wave.amplitude = 6.0f;
  wave.sharpness = 0.0f;
  if (boreas_wind_set_waves(world, &wave, 1, 0.0f) != BOREAS_OK ||
      boreas_world_step(world, 0.1f) != BOREAS_OK) {
    fprintf(stderr, "wind: %s\n", boreas_last_error());
    return 1;
  }
  float p[3] = {1.0f, 2.0f, 3.0f}, f[3];
  if (boreas_wind_sample(world, p, 1, f) != BOREAS_OK || fabsf(f[2] - 6.0f) > 1e-4f || f[0] != 0.0f) {
    fprintf(stderr, "sample: got (%g, %g, %g), want (0, 0, 6)\n", f[0], f[1], f[2]);
    return 1;
  }
  if (boreas_world_step(world, -1.0f) != BOREAS_ERROR_INVALID_ARGUMENT) {
    fprintf(stderr, "a negative dt was accepted\n");
    return 1;
  }
  /* Ids: typed per kind, zero is null, a removed id is caught. */
  boreas_flow_primitive_def vortex = boreas_default_flow_primitive_def();
  vortex.type = BOREAS_FLOW_VORTEX;
  vortex.radius = 5.0f;
  boreas_primitive_id id = BOREAS_NULL_ID;
  boreas_primitive_id none = BOREAS_NULL_ID;
  if (boreas_wind_add_primitive(world, &vortex, &id) != BOREAS_OK ||
      boreas_primitive_id_is_null(id) || boreas_wind_remove_primitive(world, id) != BOREAS_OK ||
      boreas_wind_remove_primitive(world, id) != BOREAS_ERROR_NOT_FOUND ||
      boreas_wind_remove_primitive(world, none) != BOREAS_ERROR_NOT_FOUND) {
    fprintf(stderr, "ids: %s\n", boreas_last_error());
    return 1;
  }
  /* A meadow on the caller's height map (pixels, not a file: the library reads no images). */
  const float heights[4] = {0.0f, 1.0f, 0.0f, 1.0f};
  boreas_meadow_def meadow = boreas_default_meadow_def();
  meadow.size[0] = meadow.size[1] = 1.0f;
  meadow.density = 50.0f;
  meadow.terrain.width = meadow.terrain.height = 2;
  meadow.terrain.channels = 1;
  meadow.terrain.pixels = heights;
  meadow.terrain_relief = 0.5f;
  boreas_meadow_id patch = BOREAS_NULL_ID;
  if (boreas_world_add_meadow(world, &meadow, &patch) != BOREAS_OK ||
      boreas_world_step(world, 0.02f) != BOREAS_OK) {
    fprintf(stderr, "meadow: %s\n", boreas_last_error());
    return 1;
  }
  printf("boreas %s: wind (%g, %g, %g) at t = %g\n", boreas_version(), f[0], f[1], f[2],
         boreas_world_get_time(world));
  boreas_world_destroy(world);
  return 0;
}
