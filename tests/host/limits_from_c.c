/* boreas tests: compiled, not run. The limits of boreas.h are constant expressions in
 * strict C99: the counts size arrays, and every limit, the double ones cast, makes an
 * integer constant expression (each typedef below has size -1, an error, if its test
 * fails). */
#include <boreas/boreas.h>

typedef char boreas_check_coordinate[(long)BOREAS_WORLD_MAX_COORDINATE > 0 ? 1 : -1];
typedef char boreas_check_step[(long)BOREAS_STEP_MAX_SECONDS > 0 ? 1 : -1];
typedef char boreas_check_speed[(long)BOREAS_WIND_MAX_SPEED > 0 ? 1 : -1];
typedef char boreas_check_density[(long)BOREAS_MEADOW_MAX_DENSITY > 0 ? 1 : -1];
typedef char boreas_check_cells[BOREAS_GRID_MAX_CELLS >= BOREAS_GRID_MAX_RESOLUTION ? 1 : -1];

int boreas_limits_in_arrays(void) {
  static char waves[BOREAS_WIND_MAX_WAVES];
  static char species[BOREAS_MEADOW_MAX_SPECIES];
  static char seed_points[BOREAS_MEADOW_MAX_SEED_POINTS];
  static char plant[BOREAS_PLANT_MAX_COMPONENTS];
  static char axis[BOREAS_GRID_MAX_RESOLUTION];
  static char channels[BOREAS_LIDAR_MAX_CHANNELS];
  return (int)(sizeof waves + sizeof species + sizeof seed_points + sizeof plant + sizeof axis +
               sizeof channels);
}

/* The large counts, as sizes only (no storage). */
typedef char boreas_sample_points[BOREAS_WIND_SAMPLE_MAX_POINTS];
typedef char boreas_meadow_components[BOREAS_MEADOW_MAX_COMPONENTS];
typedef char boreas_image_floats[BOREAS_IMAGE_MAX_FLOATS];
typedef char boreas_lidar_rays_per_turn[BOREAS_LIDAR_MAX_RAYS_PER_TURN];
typedef char boreas_depth_pixels[BOREAS_DEPTH_CAMERA_MAX_PIXELS];
typedef char boreas_skin_segments[BOREAS_SKIN_MAX_SEGMENTS];
typedef char boreas_animation_frames[BOREAS_ANIMATION_MAX_FRAMES];
typedef char boreas_animation_morph_frames[BOREAS_ANIMATION_MAX_MORPH_FRAMES];
