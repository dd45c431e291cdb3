/* boreas: OpenCL vegetation-wind physics. The public C API.
 *
 * Conventions (Box2D v3 style):
 *  - Y is up, the ground is the XZ plane, SI units (m, s, m/s).
 *  - Every *_def / parameter struct has a boreas_default_*() that fills in the defaults;
 *    start from it and change what you need.
 *  - Functions return a boreas_status; on anything but BOREAS_OK, boreas_last_error()
 *    says what was wrong (per thread), and the world is left exactly as it was.
 *  - Handles are opaque; ids are typed per kind, zero is null, and a removed, expired,
 *    foreign or wrong-kind id is caught (see "Handles and ids").
 *  - The caller owns every output buffer. The id out-parameter of every add call may be
 *    NULL when the id is not wanted (a gust or a rain shower that runs its course).
 *  - Output arrays, one rule for all: a getter that fills an array takes (out, capacity,
 *    count). With out NULL, count receives the number of items and nothing else happens;
 *    otherwise capacity must hold them all, or the call fails with
 *    BOREAS_ERROR_INVALID_ARGUMENT naming the size needed and writes nothing (count
 *    included). Nothing is ever cut short silently.
 *  - Names: boreas_<object>_<verb>[_<noun>]; what reads state is boreas_<object>_get_<what>
 *    (boreas_world_get_time, boreas_tree_get_branches); what adds to a world is
 *    boreas_world_add_<kind>.
 *  - Threads: different worlds may be used on different threads at the same time, each
 *    getting the state it would get alone. One world is used by one thread at a time: calls
 *    on the same world must not overlap (guard it with your own lock if several threads
 *    share it); handing a world from one thread to another between calls is fine. Calls
 *    that take no world (devices, defaults, built-in species, status names,
 *    boreas_preprocess_mesh_tree) may be made from any thread at any time.
 *    boreas_last_error() is per thread. Progress callbacks run on the calling thread; a
 *    call into the same world from one (stepping the world whose BlobTree is being built)
 *    is refused with BOREAS_ERROR_INVALID_ARGUMENT ("the world is locked"), and
 *    boreas_world_destroy then leaves the world alone. Worker threads the library starts
 *    for a call (a batch of trees grows on every core) have finished when the call
 *    returns. Processes may share one kernel cache folder (files are replaced atomically).
 *
 * The wind at a point p and time t is
 *   wind(p, t) = sine_sum(p.x, p.z, t) + grid(p, t),
 * zero inside solid cells. The sine sum is analytic (Skjermo 2007 eq. 14) and covers any
 * ground; the grid is a volumetric force field over part of it (Endo et al. sec. 4.1),
 * updated on the device every step from flow primitives, gusts and obstacles, fading out
 * beyond its sides (boreas_grid_def.edge_fade), and it can follow the camera
 * (follow_focus). Wind values are in m/s: the plant models turn them into forces.
 */
#ifndef BOREAS_BOREAS_H
#define BOREAS_BOREAS_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(_WIN32)
#define BOREAS_API __declspec(dllexport)
#else
#define BOREAS_API __attribute__((visibility("default")))
#endif

/* ---------------------------------------------------------------------------------------
 * Version
 *
 * The version of this header; boreas_version() gives the library's, so a program can
 * check that the library it loaded is the one it was built against. While the major
 * version is 0, each minor version may change the ABI, and the shared library's SONAME
 * (libboreas.so.0.MINOR) changes with it; from 1.0 on, the SONAME follows the major
 * version. CHANGELOG.md lists what changed.
 * ------------------------------------------------------------------------------------- */
#define BOREAS_VERSION_MAJOR 0
#define BOREAS_VERSION_MINOR 2
#define BOREAS_VERSION_PATCH 0
/* One number that orders versions: 10000 major + 100 minor + patch (0.2.0 is 200). */
#define BOREAS_VERSION \
  (BOREAS_VERSION_MAJOR * 10000 + BOREAS_VERSION_MINOR * 100 + BOREAS_VERSION_PATCH)

/* The library's version as "MAJOR.MINOR.PATCH". */
BOREAS_API const char* boreas_version(void);

/* ---------------------------------------------------------------------------------------
 * Limits
 *
 * The largest values the library accepts, for callers that check input before they call
 * (file loaders, bindings, user interfaces): cite these instead of retyping the numbers.
 * A call past one fails with BOREAS_ERROR_INVALID_ARGUMENT naming the field and the limit.
 * Each is a constant expression in C and C++: the counts are int (array sizes,
 * static_assert), the others double. Ranges of single fields are in their comments.
 * ------------------------------------------------------------------------------------- */
/* m: no coordinate of a position (a tree's base; a meadow's, collider's or emitter's
 * center; the grid's origin; the camera of boreas_meadow_get_vertices) lies farther from
 * 0. At 1e7 m a float still resolves 1 m. */
#define BOREAS_WORLD_MAX_COORDINATE 1e7
/* s: the longest step (boreas_world_step). An hour is past any use; with the grid's
 * smallest cell_size and response_time it keeps dt / cell_size and dt / response_time
 * finite in float. */
#define BOREAS_STEP_MAX_SECONDS 3600.0
/* m/s: the bound on a wave's amplitude and speed and on a primitive's or gust's strength.
 * Three times the speed of sound: past every real wind, and the forces it makes (the
 * square of the speed, times areas) stay far inside float. */
#define BOREAS_WIND_MAX_SPEED 1000.0
/* m/s and rad/s: the bounds on a collider's velocity and angular velocity (each
 * component). Past any vehicle near plants; a step's sweep stays far inside float. */
#define BOREAS_COLLIDER_MAX_SPEED 1000.0
#define BOREAS_COLLIDER_MAX_SPIN 1000.0
/* Waves in one wave set (boreas_world_def.wave_count, boreas_wind_set_waves). Each wave
 * is a sine per plant point per step; real winds take a handful. */
#define BOREAS_WIND_MAX_WAVES 1024
/* Points per boreas_wind_sample call: 12 bytes in and 12 out each, 768 MiB each way. Sample
 * more in several calls. */
#define BOREAS_WIND_SAMPLE_MAX_POINTS (1 << 26)
/* Cells along each axis of the grid (boreas_grid_def.resolution[i]): 1024 x 64 x 1024
 * cells already fill BOREAS_GRID_MAX_CELLS. */
#define BOREAS_GRID_MAX_RESOLUTION 1024
/* Cells in the grid in all: its two device buffers of 16 bytes a cell are 2 GiB. */
#define BOREAS_GRID_MAX_CELLS (1 << 26)
/* Components in one meadow: size[0] * size[1] * density may not ask for more. At over 100
 * device bytes a component (cl/shared/underbrush_types.h) that is nearly 2 GB; plant
 * larger ground as several meadows. */
#define BOREAS_MEADOW_MAX_COMPONENTS (1 << 24)
/* Components per square meter (boreas_meadow_def.density): one every 3 mm, denser than
 * any turf. */
#define BOREAS_MEADOW_MAX_DENSITY 1e5
/* Species in one meadow (boreas_meadow_def.species_count): planting weighs every pair of
 * them against each other (a 16 x 16 table of spacings); real meadows mix a handful. */
#define BOREAS_MEADOW_MAX_SPECIES 16
/* Propagation starts per species (boreas_meadow_def.seed_points): a few thousand already
 * give an even carpet; more only cost time before the first plant. */
#define BOREAS_MEADOW_MAX_SEED_POINTS 4096
/* Components one plant of an underbrush species makes (its parts times their counts, a
 * species file's limit): seven times a fern's 35, the most of the built-in species. */
#define BOREAS_PLANT_MAX_COMPONENTS 256
/* Floats in one boreas_image (1 GiB): a reader can refuse a larger file before reading
 * it. */
#define BOREAS_IMAGE_MAX_FLOATS (1 << 28)
/* Channels of one LiDAR (boreas_lidar_def.channels): twice the 128 of the largest units
 * sold. */
#define BOREAS_LIDAR_MAX_CHANNELS 256
/* Rays of one LiDAR turn, channels * points_per_turn: 16 times a 128-channel unit at 2048
 * points a turn. A step casts at most two turns (boreas_world_add_lidar), so a step's
 * rays stay within 2^23. */
#define BOREAS_LIDAR_MAX_RAYS_PER_TURN (1 << 22)
/* Pixels of one depth image (boreas_depth_camera_def width * height): 4096 x 4096. */
#define BOREAS_DEPTH_CAMERA_MAX_PIXELS (1 << 24)
/* Segments of a branch in a tree's skin (boreas_skin_def.segments): a branch's curve is
 * one cubic, so a few segments follow its bend; 64 is past any use. */
#define BOREAS_SKIN_MAX_SEGMENTS 64
/* Keys of one animation (boreas_animation_def.frames): ten minutes at 24 frames a second. */
#define BOREAS_ANIMATION_MAX_FRAMES 14400
/* Keys of an animation that writes meadows or imported trees (boreas_animation_def.frames
 * with meadow_count or mesh_tree_count > 0): their motion is fitted over all keys at once
 * (a keys x keys Gram matrix a mesh), and a mesh gets at most one morph target a key,
 * where WebGL 2 (three.js's morph textures) promises 256 layers. */
#define BOREAS_ANIMATION_MAX_MORPH_FRAMES 256
/* Clumps baked per meadow (boreas_animation_def.meadow_clumps): each is a mesh with its own
 * morph targets; a few carry a meadow's species mix and density, 64 is past any use. */
#define BOREAS_ANIMATION_MAX_CLUMPS 64
/* Seconds stepped before an animation's first key (boreas_animation_def.warmup): as long as
 * the longest animation. */
#define BOREAS_ANIMATION_MAX_WARMUP_SECONDS 600.0f

/* ---------------------------------------------------------------------------------------
 * Status and errors
 * ------------------------------------------------------------------------------------- */
typedef enum boreas_status {
  BOREAS_OK = 0,
  BOREAS_ERROR_INVALID_ARGUMENT = 1, /* NULL, NaN, out of range, wrong size */
  BOREAS_ERROR_NO_DEVICE = 2,        /* no OpenCL platform or no matching device */
  BOREAS_ERROR_KERNEL_BUILD = 3,     /* a kernel failed to compile; the message has the log */
  BOREAS_ERROR_OPENCL = 4,           /* an OpenCL call failed at run time */
  BOREAS_ERROR_NOT_FOUND = 5,        /* an id that was removed, expired or never existed */
  BOREAS_ERROR_OUT_OF_MEMORY = 6,
  BOREAS_ERROR_IO = 7,               /* a file could not be read or written */
  BOREAS_ERROR_INTERNAL = 8
} boreas_status;

/* The message of the last failed call on this thread ("" if none). Valid until the next
 * boreas call on this thread. */
BOREAS_API const char* boreas_last_error(void);

/* Name of a status code, e.g. "BOREAS_ERROR_INVALID_ARGUMENT". */
BOREAS_API const char* boreas_status_name(boreas_status status);

/* ---------------------------------------------------------------------------------------
 * Handles and ids
 * ------------------------------------------------------------------------------------- */
typedef struct boreas_world_s* boreas_world;

/* Every kind of object a world holds has its own id type, so the compiler refuses a tree id
 * where a meadow id is expected. All of them share one layout and one set of rules:
 *  - the all-zero id (BOREAS_NULL_ID, or a zero-initialized struct) is the null id of every
 *    kind: nothing is ever added under it (generations start at 1);
 *  - an id names one object of one world: used after the object was removed (or expired),
 *    with another world, or as another kind (a cast), it is BOREAS_ERROR_NOT_FOUND and the
 *    message names the kind expected and what the id was instead;
 *  - ids are values: compare them with boreas_*_id_equal, test them with boreas_*_id_is_null.
 * The fields are for messages and hashing; their meaning may change between versions. */
#define BOREAS_DECLARE_ID(kind)                                                            \
  typedef struct boreas_##kind##_id {                                                      \
    uint32_t index;      /* slot in the world's table of this kind */                      \
    uint32_t generation; /* >= 1, bumped each time the slot is reused; 0: null */          \
    uint32_t tag;        /* the issuing world and the kind; 0 only in the null id */       \
  } boreas_##kind##_id;                                                                    \
  static inline int boreas_##kind##_id_is_null(boreas_##kind##_id id) {                    \
    return id.index == 0 && id.generation == 0 && id.tag == 0;                             \
  }                                                                                        \
  static inline int boreas_##kind##_id_equal(boreas_##kind##_id a, boreas_##kind##_id b) { \
    return a.index == b.index && a.generation == b.generation && a.tag == b.tag;           \
  }

/* An initializer for the null id of any kind: boreas_tree_id none = BOREAS_NULL_ID; */
#define BOREAS_NULL_ID {0u, 0u, 0u}

BOREAS_DECLARE_ID(tree)      /* a Weber-Penn tree: boreas_world_add_tree */
BOREAS_DECLARE_ID(mesh_tree) /* an imported tree mesh: boreas_world_add_mesh_tree */
BOREAS_DECLARE_ID(blobtree)  /* a BlobTree surface over a tree: boreas_world_add_blobtree */
BOREAS_DECLARE_ID(meadow)    /* a patch of underbrush: boreas_world_add_meadow */
BOREAS_DECLARE_ID(collider)  /* a body pushing plants aside: boreas_world_add_collider */
BOREAS_DECLARE_ID(emitter)   /* a source of rain drops: boreas_world_add_emitter */
BOREAS_DECLARE_ID(primitive) /* a flow primitive of the wind grid: boreas_wind_add_primitive */
BOREAS_DECLARE_ID(gust)      /* a gust of the wind grid: boreas_wind_add_gust */
BOREAS_DECLARE_ID(lidar)     /* a spinning LiDAR: boreas_world_add_lidar */

/* ---------------------------------------------------------------------------------------
 * Devices
 * ------------------------------------------------------------------------------------- */
typedef struct boreas_device_info {
  int platform_index;
  int device_index;
  char platform_name[128];
  char device_name[128];
  char device_version[64];  /* "OpenCL 1.2 pocl 3.1 ..." */
  char driver_version[64];
  int is_gpu;               /* 1 for GPUs, 0 for CPUs and accelerators */
  int compute_units;
  uint64_t global_memory;   /* bytes */
  int has_gl_sharing;       /* cl_khr_gl_sharing */
  int has_fp64;             /* cl_khr_fp64 */
  int uses_fast_math;       /* 1 where boreas uses its polynomial math (CPU devices) */
} boreas_device_info;

/* Lists every OpenCL device (the output-array rule above: out NULL for the count).
 * BOREAS_ERROR_NO_DEVICE when there is no OpenCL platform at all. */
BOREAS_API boreas_status boreas_list_devices(boreas_device_info* out, int capacity, int* count);

/* Which entry of boreas_list_devices() a request picks. request: NULL or "" for the best
 * (a GPU over a CPU; BOREAS_DEVICE in the environment is honoured then), "gpu", "cpu",
 * "P:D" (platform and device index), or part of the device or platform name. */
BOREAS_API boreas_status boreas_choose_device(const char* request, int* list_index);

/* ---------------------------------------------------------------------------------------
 * World
 * ------------------------------------------------------------------------------------- */

/* How the plants (trees, imported trees, underbrush) read the sine sums at their points
 * each step. */
typedef enum boreas_wind_sampling {
  /* Evaluated at every point (default): the waves' exact sum. */
  BOREAS_WIND_SAMPLING_EXACT = 0,
  /* Read bilinearly between the grid's column centers, where the grid step evaluates the
     sums each step (an idle grid, with no primitives, gusts or solids, evaluates them for
     the plants alone), handing over smoothly to the exact sum within the outermost cell
     of centers and exact beyond it: no step in the wind where the two meet. Off by at
     most sum_i A_i e_i (m/s) for waves of amplitude A_i, wavelength L_i, sharpness k_i:
     e = min(1, (pi h / L)^2 k / 4) for k >= 1, e = min(1, (pi sqrt(2) h / L)^k) for
     0 < k < 1, e = 0 for k = 0, with h the grid's cell_size (README, "Wind sampling").
     For h = L / 20 and k = 1 that is 0.6 % of the amplitude; for the default grid and
     wave (h = L / 10, k = 2), 4.9 %. Only the plants read it: boreas_wind_sample and the
     grid's own step are exact in either mode. */
  BOREAS_WIND_SAMPLING_INTERPOLATED = 1
} boreas_wind_sampling;

/* The force-field grid over the terrain. Every field's default is
 * boreas_default_grid_def()'s: a 128 m x 32 m x 128 m box of 2 m cells centred on the
 * origin's vertical. */
typedef struct boreas_grid_def {
  float origin[3];      /* m, min corner of cell (0,0,0); each within
                           +-BOREAS_WORLD_MAX_COORDINATE (default -64, 0, -64) */
  float cell_size;      /* m, 1e-3..1e4 (default 2); cells are cubes */
  int resolution[3];    /* cells along x, y, z, each 2..BOREAS_GRID_MAX_RESOLUTION, at most
                           BOREAS_GRID_MAX_CELLS in all (default 64, 16, 64); the device
                           holds two buffers of 16 bytes per cell and 8 per column (x, z),
                           each within the device's largest allocation */
  float diffusion;      /* m^2/s, 0..1e6 (default 0.5): spreads the grid's wind to
                           neighbouring cells */
  float decay_rate;     /* 1/s, 0..1e6 (default 0.2): the grid's wind fades as
                           exp(-decay_rate t) */
  float response_time;  /* s, 1e-4..1e6 (default 0.5): how fast a primitive drives its cells
                           to its velocity */
  float edge_fade;      /* cells, 0..1e6 (default 2): beyond the grid's sides (x and z) its
                           wind fades to zero over this distance (smoothstep), so the grid
                           meets the sine sums outside without a seam; 0 stops it at the
                           sides. Above the top and below the bottom it goes on as in the
                           outermost cells. */
  int follow_focus;     /* 0 (default) or 1: the grid moves with the first focus point
                           (boreas_world_set_focus) in whole cells along x and z, keeping
                           its wind where old and new extents overlap: grid wind around the
                           camera on ground of any size. It moves once the focus is more
                           than an eighth of the grid's width (at least one cell) from its
                           middle; primitives, gusts and solid boxes are laid into the new
                           cells, which start calm. Such a grid takes solids as boxes only
                           (boreas_wind_set_solid_mask is refused: a cell mask has no place
                           once the grid moves). */
  boreas_wind_sampling wind_sampling; /* default BOREAS_WIND_SAMPLING_EXACT (above) */
} boreas_grid_def;

/* One sine wave of the wind (README, "The wind"). A wave is a value, not a def: waves
 * have no ids, a set of them is replaced whole (boreas_wind_set_waves). Defaults are
 * boreas_default_wave()'s. */
typedef struct boreas_wave {
  float direction[2]; /* (x, z) on the ground; normalized by the library; not zero
                         (default 1, 0: toward +x) */
  float amplitude;    /* m/s, 0..BOREAS_WIND_MAX_SPEED (default 3): the wave pushes along
                         +direction between 0 and this */
  float wavelength;   /* m, > 0 (default 20) */
  float speed;        /* m/s, |speed| <= BOREAS_WIND_MAX_SPEED (default 4): crests travel
                         along +direction at this speed (negative: against it). The phase
                         is w (D.x - speed t): Skjermo's eq. 11 with phi = -speed w, so
                         gust fronts move downwind. */
  float sharpness;    /* k >= 0, no unit (default 2): peaks sharpen as k grows; 0 gives a
                         steady wind */
} boreas_wave;

/* Defaults are boreas_default_world_def()'s. */
typedef struct boreas_world_def {
  const char* device;       /* NULL (default): the best device (or BOREAS_DEVICE); else a
                               request as boreas_choose_device takes it */
  const char* cache_dir;    /* NULL (default): BOREAS_CACHE_DIR, else $XDG_CACHE_HOME/boreas or
                               ~/.cache/boreas; "" turns the on-disk kernel cache off */
  boreas_grid_def grid;     /* default boreas_default_grid_def() */
  const boreas_wave* waves; /* initial sine-sum waves (copied); NULL (default) for calm */
  int wave_count;           /* 0..BOREAS_WIND_MAX_WAVES (default 0) */
  /* NULL (default); else extra OpenCL context properties as name, value pairs ending in 0,
     used as given (CL_CONTEXT_PLATFORM is added): CL_GL_CONTEXT_KHR with
     CL_GLX_DISPLAY_KHR or CL_EGL_DISPLAY_KHR makes the world's context share buffers with
     that OpenGL context (cl_khr_gl_sharing, boreas_cl.h). At most 16 pairs. */
  const intptr_t* cl_context_properties;
} boreas_world_def;

BOREAS_API boreas_grid_def boreas_default_grid_def(void);
BOREAS_API boreas_wave boreas_default_wave(void);
BOREAS_API boreas_world_def boreas_default_world_def(void);

BOREAS_API boreas_status boreas_world_create(const boreas_world_def* def, boreas_world* out);
BOREAS_API void boreas_world_destroy(boreas_world world);

/* Advances the world by dt seconds, 0 < dt <= BOREAS_STEP_MAX_SECONDS: wind layers,
 * primitives, gusts and the grid. Stable for every accepted dt. */
BOREAS_API boreas_status boreas_world_step(boreas_world world, float dt);

/* Simulated time in seconds since the world was created. */
BOREAS_API double boreas_world_get_time(boreas_world world);

/* The device the world runs on. */
BOREAS_API boreas_status boreas_world_get_device(boreas_world world, boreas_device_info* out);

/* Where the last boreas_world_step spent its time, measured on the device (OpenCL
 * profiling of markers between the stages of the in-order queue), in seconds. All zero
 * before the first step. */
typedef struct boreas_step_stats {
  double wind;       /* sine sums and the force-field grid */
  double trees;      /* re-attachment and bending of every tree, and the leaves */
  double underbrush; /* every meadow's components */
  double total;      /* wall clock of the whole call, host work included */
  int64_t trees_by_lod[4];   /* trees at full, reduced, far and frozen detail */
  int64_t branches_stepped;  /* branches bent by the wind in this step */
  int64_t branches_carried;  /* branches carried rigidly by their parents */
  int64_t branches_broken;   /* branches the wind broke in this step (boreas_branch.broken) */
  int64_t components_by_rate[4]; /* underbrush components stepped every step, every 4th,
                                    every 16th, and not at all (levels of detail) */
} boreas_step_stats;

BOREAS_API boreas_status boreas_world_get_step_stats(boreas_world world, boreas_step_stats* out);

/* What the world holds now, for a program that watches its memory over hours. Buffers
 * follow the population with hysteresis: they grow (doubling) only once the live objects
 * fill three quarters of them, and shrink (packed and halved) once the live objects fill
 * less than a quarter, so device_bytes stays within about 4 times what the present
 * population needs and within 8/3 of its largest size. */
typedef struct boreas_memory_info {
  uint64_t device_bytes;   /* in the world's device buffers */
  uint64_t device_limit;   /* what they may take: the device's global memory, or less where
                              BOREAS_DEVICE_MEMORY says so; past it an add is refused with
                              BOREAS_ERROR_OUT_OF_MEMORY */
  int32_t kernel_variants; /* kernel programs built and kept (one per set of loop counts;
                              at most 8 of each kernel: README, "Devices and
                              environment") */
} boreas_memory_info;

BOREAS_API boreas_status boreas_world_get_memory(boreas_world world, boreas_memory_info* out);

/* Everything the world simulates as one 64-bit number: its time, the grid's wind, every
 * tree's branch state and motion, every imported tree's branch wind and swayed vertices,
 * and every meadow's components, hashed by their bits in the order they were added. The
 * same world built and stepped with the same inputs on the same device has the same hash
 * after every step (README, "Determinism"). It reads the whole state back from the device:
 * for tests and debugging, not for every frame. */
BOREAS_API boreas_status boreas_world_get_state_hash(boreas_world world, uint64_t* out);

/* ---------------------------------------------------------------------------------------
 * Wind: sine sums
 * ------------------------------------------------------------------------------------- */

/* Replaces the wave set (at most BOREAS_WIND_MAX_WAVES waves). The new set blends in over
 * blend_seconds while everything sounding now blends out (smoothstep weights), so the wind
 * never jumps; 0 switches at once. count may be 0 (calm after the blend). */
BOREAS_API boreas_status boreas_wind_set_waves(boreas_world world, const boreas_wave* waves,
                                               int count, float blend_seconds);

/* ---------------------------------------------------------------------------------------
 * Wind: flow primitives and gusts (they act through the grid)
 * ------------------------------------------------------------------------------------- */
typedef enum boreas_flow_type {
  BOREAS_FLOW_UNIFORM = 0, /* velocity strength * direction */
  BOREAS_FLOW_SOURCE = 1,  /* outward from position */
  BOREAS_FLOW_SINK = 2,    /* inward to position */
  BOREAS_FLOW_VORTEX = 3   /* around the axis direction through position, right-handed */
} boreas_flow_type;

/* A flow primitive (Wejchert and Haumann): it drives the grid's cells toward its velocity.
 * Defaults are boreas_default_flow_primitive_def()'s: a uniform 1 m/s along +x everywhere,
 * for ever. */
typedef struct boreas_flow_primitive_def {
  boreas_flow_type type; /* default BOREAS_FLOW_UNIFORM */
  float position[3];     /* m, finite (default 0, 0, 0) */
  float direction[3];    /* flow direction (uniform) or axis (vortex); normalized; not zero
                            (default 1, 0, 0) */
  float strength;        /* m/s, |strength| <= BOREAS_WIND_MAX_SPEED (default 1): peak speed of
                            the primitive's flow */
  float radius;          /* m, >= 0 (default 0): smooth compact support; 0 (uniform only) =
                            everywhere */
  float lifetime;        /* s, >= 0 (default 0): removed automatically after this; 0 = until
                            removed */
} boreas_flow_primitive_def;

BOREAS_API boreas_flow_primitive_def boreas_default_flow_primitive_def(void);
BOREAS_API boreas_status boreas_wind_add_primitive(boreas_world world,
                                                   const boreas_flow_primitive_def* primitive,
                                                   boreas_primitive_id* out);
/* Removes a flow primitive before its lifetime ends (gusts: boreas_wind_remove_gust). */
BOREAS_API boreas_status boreas_wind_remove_primitive(boreas_world world,
                                                      boreas_primitive_id primitive);

/* A gust: a uniform push whose strength rises, holds and falls (smoothstep ramps).
 * Defaults are boreas_default_gust_def()'s: 5 m/s along +x over the whole grid, rising
 * at once for 1 s, held 1 s, falling over 2 s. */
typedef struct boreas_gust_def {
  float direction[3]; /* normalized; not zero (default 1, 0, 0) */
  float strength;     /* m/s at the peak, |strength| <= BOREAS_WIND_MAX_SPEED (default 5) */
  float delay;        /* s from now until the rise starts, >= 0 (default 0) */
  float rise;         /* s, >= 0 (default 1) */
  float hold;         /* s, >= 0 (default 1) */
  float fall;         /* s, >= 0 (default 2); the gust is removed at the end of its fall */
  float center[3];    /* m, finite (default 0, 0, 0) */
  float radius;       /* m, >= 0 (default 0); 0 = the whole grid */
} boreas_gust_def;

BOREAS_API boreas_gust_def boreas_default_gust_def(void);
BOREAS_API boreas_status boreas_wind_add_gust(boreas_world world, const boreas_gust_def* gust,
                                              boreas_gust_id* out);
/* Removes a gust before its fall ends. */
BOREAS_API boreas_status boreas_wind_remove_gust(boreas_world world, boreas_gust_id gust);

/* ---------------------------------------------------------------------------------------
 * Wind: obstacles
 * ------------------------------------------------------------------------------------- */

/* Marks solid every grid cell whose center lies in the box [min, max] (m). Solid cells
 * have zero wind (sine sums included) at once; from the next step on, no wind flows
 * through their faces. */
BOREAS_API boreas_status boreas_wind_add_solid_box(boreas_world world, const float min[3],
                                                   const float max[3]);

/* Replaces the solid mask: count must equal the number of grid cells, ordered x fastest,
 * then y, then z; nonzero bytes are solid. NULL with count 0 clears all solids (boxes
 * included). Refused on a grid that follows the focus (boreas_grid_def.follow_focus),
 * except to clear. */
BOREAS_API boreas_status boreas_wind_set_solid_mask(boreas_world world, const uint8_t* mask,
                                                    int64_t count);

/* ---------------------------------------------------------------------------------------
 * Wind: sampling
 * ------------------------------------------------------------------------------------- */

/* The wind at count points at the world's current time. xyz and force_xyz hold 3 * count
 * floats each (m and m/s); at most BOREAS_WIND_SAMPLE_MAX_POINTS points per call. */
BOREAS_API boreas_status boreas_wind_sample(boreas_world world, const float* xyz, int count,
                                            float* force_xyz);

/* The grid's definition as the world uses it (origin: where a grid that follows the
 * focus stands now). */
BOREAS_API boreas_status boreas_wind_get_grid(boreas_world world, boreas_grid_def* out);

/* Copies the grid's part of the wind: 4 floats per cell (x, y, z in m/s; 1 if solid, else
 * 0), cells ordered x fastest, then y, then z. capacity is in floats. */
BOREAS_API boreas_status boreas_wind_get_grid_values(boreas_world world, float* out,
                                                     int64_t capacity);

/* ---------------------------------------------------------------------------------------
 * Trees (Skjermo 2007): Weber-Penn trees whose branches are cubic Bezier curves, re-attached
 * to their parents and bent by the wind at their tips every step, all branches in parallel.
 * ------------------------------------------------------------------------------------- */
typedef enum boreas_tree_mode {
  BOREAS_TREE_LAGGED = 0, /* the paper: one launch per step; each level lags its parent
                             by one step */
  BOREAS_TREE_EXACT = 1   /* level by level within a step: no lag */
} boreas_tree_mode;

typedef enum boreas_tree_response {
  BOREAS_TREE_QUASI_STATIC = 0, /* the paper: the bend follows the wind at once */
  BOREAS_TREE_DAMPED = 1        /* the bend follows the wind as a damped oscillator at the
                                   branch's natural frequency: sway, lag, overshoot */
} boreas_tree_response;

/* How the wind loads a generated tree's branches. Zero (a zero-initialized def) is drag. */
typedef enum boreas_tree_load {
  BOREAS_TREE_LOAD_DRAG = 0,  /* aerodynamic drag 1/2 rho C_d A |u| u, as the underbrush and
                                 mesh trees take it: each branch a cantilever of its
                                 length, mean radius and the species' WoodModulus, loaded by
                                 its own area, its leaves' and everything it carries; the
                                 wind u relative to the branch's tip */
  BOREAS_TREE_LOAD_LINEAR = 1 /* the paper: the bend is proportional to the wind */
} boreas_tree_load;

/* Per branching level (0 trunk .. 3); defaults are boreas_default_tree_def()'s. */
typedef struct boreas_tree_level_def {
  float stiffness;       /* > 0, no unit, default 1: divides the bend. Drag load: multiplies the
                            species' WoodModulus. Linear load: a branch's tip turns by
                            about 0.01 rad per m/s of wind * sqrt(0.1 m / radius) /
                            stiffness, so thicker branches bend less; at equal force a
                            longer segment turns less (the bend is a displacement, eq. 17) */
  float damping_ratio;   /* damped response: 0.01..10, no unit, default 0.15 */
  float frequency_scale; /* damped response: multiplies the branch's cantilever frequency
                            (from its length and radius), 0.01..100, no unit, default 0.5
                            (the crown's mass lowers it) */
  int rings;             /* mesh: rings along the branch, 1..256 (default 12, 6, 4, 3) */
  int sides;             /* mesh: vertices around it, 3..256 (default 12, 8, 5, 4) */
} boreas_tree_level_def;

/* The outline of a tree's leaves: the shape the renderer draws on a leaf's quad and the one
 * a ray must cross to hit the leaf (a ray through an oak leaf's sinus misses). Zero (a
 * zero-initialized def) takes it from the species. The kinds are cl/shared/leaf_outline.h's
 * BOREAS_LEAF_OUTLINE_* plus one. */
typedef enum boreas_leaf_outline {
  BOREAS_LEAF_OUTLINE_SPECIES = 0, /* the kind named after a built-in species, matched on a
                                      species file's stem too (quaking_aspen: aspen,
                                      ca_black_oak: oak, weeping_willow: willow,
                                      black_tupelo: tupelo), broadleaf for any other */
  BOREAS_LEAF_BROADLEAF = 1,       /* ovate, serrate, a heart-shaped notch at the base */
  BOREAS_LEAF_ASPEN = 2,           /* nearly round, finely toothed, a short tip */
  BOREAS_LEAF_OAK = 3,             /* three deep lobes a side and a terminal one */
  BOREAS_LEAF_WILLOW = 4,          /* lanceolate, long-pointed, finely serrate */
  BOREAS_LEAF_TUPELO = 5           /* obovate, entire margin */
} boreas_leaf_outline;

/* Defaults are boreas_default_tree_def()'s: a quaking aspen of seed 1 at the origin. */
typedef struct boreas_tree_def {
  const char* species;   /* a built-in name (boreas_builtin_species) or a path to an Arbaro
                            species .xml or a boreas species .json (default
                            "quaking_aspen") */
  float position[3];     /* m: the trunk's base, each within +-BOREAS_WORLD_MAX_COORDINATE
                            (default 0, 0, 0) */
  float rotation;        /* rad, |rotation| <= 1e4 (default 0): turns the tree about the up
                            axis through its base (counter-clockwise seen from above) */
  float scale;           /* (0, 1000], no unit (default 1): multiplies every length of the
                            species */
  uint64_t seed;         /* default 1: the same seed grows the same tree. Trees whose species
                            and seed are equal share one grown model (a template): a forest
                            of many trees from a few (species, seed) pairs grows each pair
                            once; position, rotation and scale stay per tree */
  boreas_tree_mode mode; /* default BOREAS_TREE_LAGGED */
  boreas_tree_response response; /* default BOREAS_TREE_QUASI_STATIC */
  boreas_tree_load load;         /* default BOREAS_TREE_LOAD_DRAG */
  float bend_exponent;           /* gamma of b_i = F (i/3)^gamma, 0.1..10, no unit, default 1.8 (P2
                                    takes 0.48 of the bend; 4.88 gives the 0.14 that Skjermo's eq. 16
                                    prints, cl/tree_step.cl says why boreas keeps the former) */
  boreas_tree_level_def levels[4]; /* trunk, then levels 1..3 (defaults above) */
  /* Simulation level of detail (only where focus points are set: boreas_world_set_focus),
     m from the tree's base to the nearest focus point, not decreasing: past [0] the
     finest branch level is carried rigidly by its parent, past [1] only the trunk and the
     first level are stepped, past [2] the tree rests (frozen). Defaults 30, 80, 250 (for
     an eye 1.8 m above the ground); a distance of 1e9 or more never changes level
     (distances are finite). */
  float lod_distances[3];
  boreas_leaf_outline leaf_outline; /* default BOREAS_LEAF_OUTLINE_SPECIES */
} boreas_tree_def;

typedef struct boreas_branch {
  float control_points[4][3]; /* world space, m, as of the last step */
  float orientation[3];       /* the vector O the branch's Sloan frame starts from */
  int32_t level;              /* 0 trunk .. 3 */
  int32_t parent;             /* index of the parent in this tree's list, -1 for the trunk */
  float parent_v;             /* where P0 sits on the parent's curve, 0..1 */
  float radius;               /* m, at the base */
  float length;               /* m, of the unbent control polygon */
  int32_t broken;             /* 1 once the wind broke it (its bending stress at its base
                                 passed the species' WoodRupture): it hangs from its
                                 parent along the load; 0 while whole (boreas_tree_heal) */
} boreas_branch;

/* A leaf as the device places it. Its place on its branch is stored packed (8 bytes a
 * leaf): position along the branch within 1.2e-4 of the branch's Bezier parameter, the
 * three angles of its attachment within 0.11, 0.11 and 0.22 degrees (around the branch,
 * down from it, the blade's roll) of the generator's; exact for the same inputs. */
typedef struct boreas_leaf {
  float position[3]; /* m: where the blade starts (end of the petiole) */
  float axis[3];     /* unit: along the blade */
  float normal[3];   /* unit: the blade's normal */
  float length;      /* m */
  float width;       /* m */
  int32_t branch;    /* index of the branch it grows on in this tree's list */
} boreas_leaf;

typedef struct boreas_vertex {
  float position[3]; /* m */
  float normal[3];   /* unit, outward */
  float uv[2];       /* u: turns around the branch 0..1, v: along it 0..1 */
} boreas_vertex;

/* The name of built-in species number index (0, 1, ...), or NULL past the last. */
BOREAS_API const char* boreas_builtin_species(int index);

BOREAS_API boreas_tree_def boreas_default_tree_def(void);

/* The leaf outline a tree of this species has by default (BOREAS_LEAF_OUTLINE_SPECIES's
 * rule): never BOREAS_LEAF_OUTLINE_SPECIES itself. species may be NULL (broadleaf). */
BOREAS_API boreas_leaf_outline boreas_species_leaf_outline(const char* species);

/* Grows a tree and places it, unbent, in the world. Errors name the species file, line
 * and parameter where a species file is wrong. */
BOREAS_API boreas_status boreas_world_add_tree(boreas_world world, const boreas_tree_def* def,
                                               boreas_tree_id* out);
BOREAS_API boreas_status boreas_world_remove_tree(boreas_world world, boreas_tree_id tree);

/* Adds count trees in one call: every def checked and every (species, seed) grown once
 * before anything changes, then one upload for all of them. All or nothing: on an error
 * (which names defs[i]) no tree is added. ids (may be NULL) receives count ids. The cost
 * of adding trees is theirs alone: the trees already in the world are not touched. */
BOREAS_API boreas_status boreas_world_add_trees(boreas_world world, const boreas_tree_def* defs,
                                                int count, boreas_tree_id* ids);

/* Focus points for the simulation's level of detail (cameras, players, sensors): count
 * points of 3 floats (m), copied; each tree takes its level from its distance to the
 * nearest (boreas_tree_def.lod_distances), each patch of underbrush its rate
 * (boreas_meadow_def.lod_distances). count 0 (the default) steps everything at full detail.
 * A change of level never makes a branch jump: a branch that stops being stepped eases into
 * its rest shape on its parent (time constant 0.5 s) and is then carried by it, updated
 * every 4th step at reduced and every 8th at far detail; one that starts again eases from
 * where it is into the wind (0.2 s); a tree past the last distance is carried whole for
 * 3 s, then rests and costs nothing until it comes nearer. Underbrush stepped less often
 * takes longer steps (exact for any dt), so it goes on from where it is. Memory follows
 * the focus too: a tree's finest level, once carried, is kept in a compact form (28 bytes a
 * branch, 40 for a damped tree, against 152-176); set before boreas_world_add_trees, the
 * focus puts the finest levels of the trees added past lod_distances[0] in that form at
 * once, so a large forest never holds all its trees at full detail, not even while it is
 * added (after the first 3 s it steps to the same bits either way). */
BOREAS_API boreas_status boreas_world_set_focus(boreas_world world, const float* points, int count);

/* m: the origin of the positions the world hands back for meadows, imported trees and
 * trees (boreas_meadow_get_components, boreas_meadow_get_vertices and its enqueue twins,
 * boreas_mesh_tree_get_vertices, boreas_tree_get_branches, _get_leaves, _get_mesh, the
 * trees' enqueue_*_records and boreas_world_enqueue_tree_records' records and impostors),
 * kept in double: a renderer far from 0 passes a point near its camera and gets positions
 * relative to it, as precise as float is there, where world coordinates 100 km out keep
 * 8 mm (README "Far from the origin"). NULL or 0, 0, 0 (the default): world coordinates.
 * Each coordinate finite and within +-BOREAS_WORLD_MAX_COORDINATE. A record view's planes
 * and eye and the focus points stay in world coordinates. Rays count from it too
 * (boreas_ray's origin, boreas_hit's point, the LiDAR's points; the sensors' poses are in
 * world coordinates and moved to it in double), so a cast 100 km out near this origin
 * measures as it does near 0; a change of it rebuilds the ray structure at the next cast. */
BOREAS_API boreas_status boreas_world_set_output_origin(boreas_world world, const double origin[3]);

/* Mends every broken branch of the tree and puts it back at rest, unbent, as it was added
 * (its motion zero); the next step bends it from there. */
BOREAS_API boreas_status boreas_tree_heal(boreas_world world, boreas_tree_id tree);

/* The tree's template: trees with the same number share their grown model (species and
 * seed) and so their shape at rest at scale 1 (a renderer bakes one impostor per number;
 * boreas_world_enqueue_tree_records writes it into impostor records). A small integer
 * >= 0, the same while the tree lives; a number no living tree has any longer may be
 * given again to another template. */
BOREAS_API boreas_status boreas_tree_get_template(boreas_world world, boreas_tree_id tree,
                                                  int* out);

/* The tree's branches, levels in order (the trunk first). With out NULL, count receives
 * the total; otherwise capacity must hold them all (the output-array rule above). */
BOREAS_API boreas_status boreas_tree_get_branches(boreas_world world, boreas_tree_id tree,
                                                  boreas_branch* out, int capacity, int* count);
/* The tree's leaves, as of the last step (same contract as boreas_tree_get_branches): made
 * now from its branches (leaves are not stored; a count alone makes none). */
BOREAS_API boreas_status boreas_tree_get_leaves(boreas_world world, boreas_tree_id tree,
                                                boreas_leaf* out, int capacity, int* count);
/* The crown's ambient occlusion at each of the tree's leaves as they are now (call it at
 * rest, before stepping, as a renderer does once per tree): per leaf the fraction (r, g, b)
 * of a uniform sky's light that reaches it through the crown, for leaves that pass on
 * transmittance[c] (each in [0, 1]) of the light they intercept, so light deep in a crown
 * is dimmer and greener (Kusternig et al. sec. 3.4), taken at each leaf's centre. The
 * leaves' area density on a grid of 20 voxels along the crown's longest side, each leaf
 * counted at its centre with its blade's area (its outline's, as the wind's drag counts
 * it), scaled down to the species' LeafAreaIndex over the crown's projection on the ground
 * (Weber-Penn crowns carry several times a real one's leaf area; never scaled up), marched
 * along 32 sky directions on the device; the optical depth is the species' Clumping times
 * G times the leaf area crossed, G for each direction the projection of the leaves' area
 * from their normals (Ross). rgb receives 3 floats per leaf in the order of
 * boreas_tree_get_leaves; count and capacity are in leaves (the output-array rule). */
BOREAS_API boreas_status boreas_tree_get_leaf_occlusion(boreas_world world, boreas_tree_id tree,
                                                        const float transmittance[3], float* rgb,
                                                        int capacity, int* count);

/* The tree's branch mesh as of the last step, swept by the de Casteljau deformer: each
 * branch a grid of (rings + 1) x (sides + 1) vertices of its level, two triangles per
 * quad, counter-clockwise seen from outside. vertices or indices may be NULL to ask for
 * the counts only; each call writes both only if both capacities suffice (else
 * INVALID_ARGUMENT naming the size needed). */
BOREAS_API boreas_status boreas_tree_get_mesh(boreas_world world, boreas_tree_id tree,
                                              boreas_vertex* vertices, int vertex_capacity,
                                              int* vertex_count, uint32_t* indices,
                                              int index_capacity, int* index_count);

/* A tree's skin: one skeleton for engines, glTF files and Blender armatures, so that what
 * they play back bends as boreas bent it. Joints sit on the branches down to max_level,
 * segments + 1 per branch at equal steps of its curve's parameter u = k / segments (the
 * first at its base, the last at its tip), so a bent trunk bends in the skin too. A
 * joint's frame is the deformer's own there (cl/shared/tree_math.h): origin on the curve,
 * y along its tangent, x the Sloan handle S(u) made perpendicular to y, z = x cross y
 * (near T(u)). Every vertex and leaf is bound to the two joints around its place on its
 * branch (linear in u between them); a finer branch, and its leaves, to the joints around
 * the point where its ancestor of level max_level carries it. Linear blend skinning with
 * the joints at rest (before the first step, or after boreas_tree_heal) as the bind pose
 * reproduces the mesh at rest, and after steps follows boreas_tree_get_mesh within the
 * bend of a segment (tests/host/trees/test_tree_skin.cpp states how close). */
typedef struct boreas_skin_def {
  int max_level; /* deepest branch level with joints of its own, 0 (trunk) .. 3 (default 3);
                    finer branches are carried rigidly by their ancestor of this level */
  int segments;  /* joints per branch minus one, 1..BOREAS_SKIN_MAX_SEGMENTS (default 4) */
} boreas_skin_def;

typedef struct boreas_joint {
  float position[3]; /* m, world: the point of its branch's curve at u, as of the last step */
  float rotation[4]; /* unit quaternion (x, y, z, w) taking the joint's axes to world */
  int32_t parent;    /* index in this list: the joint before it on its branch, or for a
                        branch's first joint the parent branch's joint at or below parent_v;
                        -1 for the trunk's first */
  int32_t branch;    /* index in boreas_tree_get_branches' list */
  float u;           /* its place on the branch: the curve's parameter, k / segments */
} boreas_joint;

/* Up to four joints and their weights for one vertex or leaf. */
typedef struct boreas_skin_weight {
  int32_t joints[4]; /* indices in boreas_tree_get_joints' list */
  float weights[4];  /* >= 0, summing to 1, largest first; an unused slot weighs 0 */
} boreas_skin_weight;

BOREAS_API boreas_skin_def boreas_default_skin_def(void);

/* The skeleton as of the last step: branches in boreas_tree_get_branches' order, each
 * one's joints from base to tip (the output-array rule). def NULL takes the defaults. */
BOREAS_API boreas_status boreas_tree_get_joints(boreas_world world, boreas_tree_id tree,
                                                const boreas_skin_def* def, boreas_joint* out,
                                                int capacity, int* count);
/* The binding of boreas_tree_get_mesh's vertices, one weight per vertex in its order (it
 * depends on the tree's shape alone, not on the step). A vertex's place is its ring's:
 * evenly along the branch, but for the last 1-3 rings of a piece that ends in a rounded
 * tip (nTaper over 1), which go round the tip's hemisphere as the mesh's do. */
BOREAS_API boreas_status boreas_tree_get_skin_weights(boreas_world world, boreas_tree_id tree,
                                                      const boreas_skin_def* def,
                                                      boreas_skin_weight* out, int capacity,
                                                      int* count);
/* The binding of boreas_tree_get_leaves' leaves, one weight per leaf in its order: every
 * corner of a leaf takes its leaf's (a leaf moves rigidly with its branch). Each leaf's
 * place on its branch is the curve's point nearest to it as of the last step. */
BOREAS_API boreas_status boreas_tree_get_leaf_skin_weights(boreas_world world,
                                                           boreas_tree_id tree,
                                                           const boreas_skin_def* def,
                                                           boreas_skin_weight* out,
                                                           int capacity, int* count);

/* An animated glTF file (.glb) of trees, meadows and imported trees in the wind, for
 * engines, three.js and Blender:
 * every tree a skinned mesh (the skin above), trees of one template sharing its meshes (a
 * template's mesh is its first tree's; call it while the trees are at rest, just added
 * or healed, for the others to match exactly; it is cut into pieces of at most 65,535
 * vertices and 256 joints, each a mesh skinned by a skin of its own over the tree's
 * joints, a node "treeN_pieceK" per tree and piece), leaves as flat quads (no normals:
 * viewers compute them) bound to the skin, and one
 * animation "wind" with a rotation (and, where a joint's offset changes, a translation)
 * channel per joint, a key per frame. Positions and normals are quantized
 * (KHR_mesh_quantization, required by the file); keys are floats (a joint's place
 * compounds its parents' rotations). */
typedef struct boreas_animation_def {
  int frames;           /* keys written, 1..BOREAS_ANIMATION_MAX_FRAMES (default 48); key 0 is
                           the world as the call finds it (the bind pose), or as warmup
                           below left it */
  float frame_time;     /* s between keys, (0, BOREAS_STEP_MAX_SECONDS] (default 1/24) */
  int steps_per_frame;  /* world steps of frame_time / steps_per_frame between keys, 1..1000
                           (default 1) */
  boreas_skin_def skin; /* the joints (default: max_level 1, segments 2: trunks and limbs
                           keyed, finer branches and leaves riding on them; a finer skin
                           follows the twigs too and makes a larger file: the default
                           scene's 12 trees take 240 MB at max_level 2, bench/RESULTS.md) */
  int leaves;           /* 1 (default): the leaves as geometry; 0: the branches only */
  const boreas_meadow_id* meadows; /* meadows written (default NULL: none): each cut into
                           meshes of whole components' strips (at most 65,535 vertices,
                           full detail), every component a triangle strip as
                           boreas_meadow_get_vertices builds it, colored by its part;
                           frames then at most BOREAS_ANIMATION_MAX_MORPH_FRAMES */
  int meadow_count;     /* entries of meadows, >= 0 (default 0) */
  const boreas_mesh_tree_id* mesh_trees; /* imported trees written (default NULL: none):
                           trunk and leaves as meshes whose geometry (accessors) trees of
                           one model share, each tree's motion its own morph targets */
  int mesh_tree_count;  /* entries of mesh_trees, >= 0 (default 0) */
  float morph_tolerance; /* m, 1e-4..1 (default 1e-3): meadows and imported trees move as
                           a few morph targets (their motion's principal components, int16,
                           int8 where small) weighted per key, as many as it takes for every
                           vertex at every key to lie within this distance of boreas's
                           position (a target a key at most; int16 in a mesh's box bounds
                           how close). A meadow's motion is nearly of full rank: about 8
                           bytes a strip vertex a key at 1 mm (bench/RESULTS.md) */
  int meadow_clumps;    /* 0..BOREAS_ANIMATION_MAX_CLUMPS (default 0: every component
                           exactly, as above). n > 0: each meadow as n representative clumps:
                           its cells with plants (squares of about clump_size) ranked by
                           their plants' count in n equal shares, a share's clump the cell
                           nearest its mean count (then species counts), stepped by boreas in the
                           meadow's wind, its motion made a loop and instanced on every cell
                           of its share. The loop: the world is stepped 2 (frames - 1) keys
                           past the last key, and each clump takes the window of `frames`
                           keys (of those 3 frames - 2) whose last key is nearest its first,
                           the drift between them spread linearly back over the window's
                           keys, so the last key is the first. An instance is node
                           "meadowN_clumpK_cellC": the cell's center and ground height, a
                           phase of its own in the loop. Far smaller; not every blade as
                           simulated (bench/RESULTS.md) */
  float clump_size;     /* m, 0.1..100 (default 1): the side of a clump's square cell */
  float warmup;         /* s, 0..BOREAS_ANIMATION_MAX_WARMUP_SECONDS (default 0): the world
                           stepped round(warmup / (frame_time / steps_per_frame)) steps of
                           frame_time / steps_per_frame after the bind pose is taken (the
                           trees' meshes and joints, the meadows' and imported trees' bases:
                           the world as the call finds it) and before key 0, so the keys
                           start in the wind's sway rather than in the first bend from rest
                           (a clump's loop then closes on a sway, not on that bend) */
} boreas_animation_def;

BOREAS_API boreas_animation_def boreas_default_animation_def(void);

/* Steps the world (frames - 1) * steps_per_frame times (after the def's warmup; with
 * meadow_clumps, 2 (frames - 1) keys' steps more for the clumps' loops), keying the joints of the
 * tree_count trees after every steps_per_frame, and writes the file at path (.glb,
 * replaced if there). Everything is checked before the first step: a bad field or
 * trees[i] is named and the world is left as it was; BOREAS_ERROR_IO if path cannot be
 * written (after the steps). Meadows and imported trees (the def's meadows and mesh_trees)
 * are keyed after the same steps, as morphed meshes: node "meadowN_pieceK" (world space;
 * "meadowN_clumpK_cellC" with meadow_clumps)
 * and "mesh_treeN_trunk" / "_leaves" (placed as the tree), each with a "weights" channel
 * in "wind". */
BOREAS_API boreas_status boreas_world_export_animation(boreas_world world,
                                                       const boreas_animation_def* def,
                                                       const boreas_tree_id* trees,
                                                       int tree_count, const char* path);

/* ---------------------------------------------------------------------------------------
 * Underbrush (Endo, Morimoto and Fabris 2003): grass, leaves and flowers as components —
 * vector sets fixed at their base, bent by gravity into precomputed rest shapes and moved
 * by the wind, colliders and impulses through a critically damped dynamic constraint on
 * their center of mass. A meadow plants species over a terrain by their nutrient needs.
 * ------------------------------------------------------------------------------------- */
/* Pixels passed in, copied during the call: width x height pixels of `channels` floats each,
 * channel fastest, then x, then rows. A meadow stretches them over its rectangle: column 0
 * on its -x side and the last column on its +x side, row 0 (the top row of an image file)
 * on its -z side and the last row on its +z side, one pixel per sample, bilinear between.
 * The all-zero boreas_image (pixels NULL, sizes 0) is none. Read files however you like;
 * the boreas command reads PNG, EXR, TIFF, ... through OpenImageIO (values 0..1). */
typedef struct boreas_image {
  int width, height;   /* pixels, >= 1 each; at most BOREAS_IMAGE_MAX_FLOATS floats */
  int channels;        /* floats per pixel, 1..16 */
  const float* pixels; /* width * height * channels finite floats */
} boreas_image;

typedef struct boreas_meadow_species {
  const char* species; /* a built-in name (boreas_builtin_underbrush_species) or a path to
                          a species .json (format in the README) */
  float weight;        /* 1e-9..1e9, no unit: its share of the plants (the default mix
                          weighs grass 6, clover 2, daisies 1) */
} boreas_meadow_species;

/* Defaults are boreas_default_meadow_def()'s: a 10 m x 10 m meadow of the default mix at
 * the origin. */
typedef struct boreas_meadow_def {
  const boreas_meadow_species* species; /* NULL (default): the default mix (grass, clover,
                                           daisies) */
  int species_count;    /* 0..BOREAS_MEADOW_MAX_SPECIES entries of species (default 0) */
  float center[3];      /* m: the middle of the meadow's rectangle on the ground, each
                           within +-BOREAS_WORLD_MAX_COORDINATE (default 0, 0, 0) */
  float size[2];        /* m: its extent along x and z, each 0.01..1e5 (default 10, 10) */
  float density;        /* components per square meter, 0..BOREAS_MEADOW_MAX_DENSITY (default
                           400), where the ground allows; size[0] * size[1] * density at
                           most BOREAS_MEADOW_MAX_COMPONENTS */
  uint64_t seed;        /* default 1: the same seed plants the same meadow */
  boreas_image terrain; /* none (default): procedural rolling ground; else a height map: the
                           ground's y is center[1] + terrain_relief * its first channel
                           (an image's black 0 .. white 1; heights in m with relief 1) */
  float terrain_relief; /* m, 0..1e4 (default 0): height range of the ground (0: flat) */
  boreas_image nutrients; /* none (default): procedural nutrients; else its first three
                             channels are the nutrients, clamped to 0..1 */
  int seed_points;      /* propagation starts per species, 1..BOREAS_MEADOW_MAX_SEED_POINTS
                           (default 8) */
  int shape_angles;     /* precomputed shapes: load angles per part, 3..181 (default 19) */
  int shape_norms;      /* and load norms per angle, 3..256 (default 24) */
  float lod_distances[3]; /* m from the camera where the vertex kernel drops to every other
                             joint, to base and tip only, and culls (default 15, 40, 120).
                             The same distances from the nearest focus point
                             (boreas_world_set_focus) set the step's level of detail:
                             components are stepped every step, every 4th step (over 4 dt),
                             every 16th step, and not at all past the last */
} boreas_meadow_def;

typedef struct boreas_component {
  float base[3];           /* m: where it is fixed now (moves with a parent component) */
  float center_of_mass[3]; /* X, m */
  float velocity[3];       /* m/s: dX/dt relative to the base (for a component fixed to
                              the ground, the same as its world velocity) */
  float rest_center_of_mass[3]; /* X at rest under gravity, m */
  int32_t broken;          /* 0 intact; else 1 + the section where it broke (it stays so) */
  int32_t species;         /* index into the meadow's species list */
  int32_t part;            /* index into the species' parts */
  int32_t parent;          /* index of the component it is fixed to, -1 for the ground */
} boreas_component;

/* Where a body is: a sensor, a collider. Defaults are boreas_default_pose()'s: at the
 * origin, its axes the world's. Its place in the world is origin + position, summed in
 * double: a body far from 0 (100 km out a float is 8 mm apart) is placed exactly by an
 * origin near it and a small position (README "Far from the origin"). */
typedef struct boreas_pose {
  float position[3];    /* m, from origin, each within +-BOREAS_WORLD_MAX_COORDINATE
                           (default 0, 0, 0) */
  float orientation[4]; /* unit quaternion x, y, z, w: finite, |q| within 1e-3 of 1 (then
                           normalized by the library) (default 0, 0, 0, 1) */
  double origin[3];     /* m, world: where position counts from, each finite and within
                           +-BOREAS_WORLD_MAX_COORDINATE (default 0, 0, 0) */
} boreas_pose;

/* The shapes of colliders. */
typedef enum boreas_collider_shape {
  BOREAS_COLLIDER_SPHERE = 0,  /* radius about the pose's position */
  BOREAS_COLLIDER_CAPSULE = 1, /* radius about a segment along the pose's local Y, from
                                  -half_height to +half_height (a walker stands upright) */
  BOREAS_COLLIDER_BOX = 2      /* half_extents along the pose's local X, Y, Z */
} boreas_collider_shape;

/* A kinematic body that pushes plants aside (a vehicle, a walker, a ball) and feels them
 * push back (boreas_collider_get_contact). The caller moves it, as a physics engine moves
 * its kinematic bodies: each step it sweeps from its pose along velocity * dt, so what it
 * passes over in a step is what it touches however fast it goes, and then the world moves
 * it there (position += velocity dt, orientation turned by angular_velocity dt); a caller
 * that sets its pose every step (boreas_collider_set_pose) overrides that. A turn within
 * one step is taken at the step's middle orientation, not swept. Defaults are
 * boreas_default_collider_def()'s: a soccer ball resting on the ground at the origin.
 * Fields a shape does not use are not read. */
typedef struct boreas_collider_def {
  boreas_collider_shape shape; /* default BOREAS_COLLIDER_SPHERE */
  boreas_pose pose;            /* default: position 0, 0.11, 0; orientation 0, 0, 0, 1 */
  float radius;                /* sphere, capsule: m, 1e-3..1e3 (default 0.11) */
  float half_height;           /* capsule: m, 0..1e3 (default 0.5) */
  float half_extents[3];       /* box: m, each 1e-3..1e3 (default 0.5, 0.5, 0.5) */
  float velocity[3];           /* m/s, world frame, each within +-BOREAS_COLLIDER_MAX_SPEED
                                  (default 0, 0, 0) */
  float angular_velocity[3];   /* rad/s, world frame, about its position, each within
                                  +-BOREAS_COLLIDER_MAX_SPIN (default 0, 0, 0) */
} boreas_collider_def;

/* What the plants did to a collider over the last step. */
typedef struct boreas_collider_contact {
  float force[3];   /* N, world frame: the sum of what the bent branches and pressed
                       components it touched push back with (README "Colliders") */
  float torque[3];  /* N m: those pushes' moment about the collider's position at the end
                       of the step */
  int32_t contacts; /* how many plant parts touched it: tree and mesh-tree branches and
                       underbrush components */
  int32_t pad;
} boreas_collider_contact;

/* An impulse emitter: events (rain drops, footsteps) that push components. Each event
 * gives components within event_radius of it a velocity change of impulse / mass, fading
 * linearly with distance. Defaults are boreas_default_emitter_def()'s: rain of 3 mm drops
 * at 50 a second over a 1 m disk around the origin. */
typedef struct boreas_emitter_def {
  float center[3];    /* m, each within +-BOREAS_WORLD_MAX_COORDINATE (default 0, 0, 0) */
  float area_radius;  /* m, 0..1e5 (default 1): events fall uniformly in this disk around
                         center (horizontal); 0: always at center */
  float event_radius; /* m, 1e-4..1e3 (default 0.05) */
  float impulse[3];   /* N s per event, each -1e3..1e3 (default 0, -2e-4, 0: a 3 mm rain
                         drop at 7 m/s) */
  float rate;         /* events per second, 0..1e6 (default 50); 0: one event at the next
                         step */
  float lifetime;     /* s, 0..1e9 (default 0): removed after this; 0 = until removed (or
                         after its one event when rate is 0) */
  uint64_t seed;      /* default 1: the same seed places the same events */
  double origin[3];   /* m, double, each within +-BOREAS_WORLD_MAX_COORDINATE (default 0, 0,
                         0): what center counts from, as a pose's origin (boreas_pose): an
                         emitter far out is placed exactly by an origin near it and a small
                         center (README "Far from the origin") */
} boreas_emitter_def;

typedef struct boreas_meadow_vertex {
  float position[3]; /* m */
  float normal[3];   /* unit, the side facing +normal is the component's upper side */
  float uv[2];       /* u: 0 left border .. 1 right border; v: 0 base .. 1 tip */
} boreas_meadow_vertex;

/* The name of built-in underbrush species number index (0, 1, ...), or NULL past the last. */
BOREAS_API const char* boreas_builtin_underbrush_species(int index);

BOREAS_API boreas_meadow_def boreas_default_meadow_def(void);
/* Plants a meadow (distribution, rest shapes and tables are computed here; about a second
 * per million components). Components start at rest. */
BOREAS_API boreas_status boreas_world_add_meadow(boreas_world world, const boreas_meadow_def* def,
                                                 boreas_meadow_id* out);
/* Plants count meadows and adds them in one call (one upload for all); all or nothing: on
 * an error (which names defs[i]) no meadow is added. ids (may be NULL) receives count ids.
 * Adding meadows touches no meadow already in the world. */
BOREAS_API boreas_status boreas_world_add_meadows(boreas_world world, const boreas_meadow_def* defs,
                                                  int count, boreas_meadow_id* ids);
BOREAS_API boreas_status boreas_world_remove_meadow(boreas_world world, boreas_meadow_id meadow);
/* The meadow's components as of the last step. With out NULL, count receives the total;
 * otherwise capacity must hold them all (the output-array rule above). */
BOREAS_API boreas_status boreas_meadow_get_components(boreas_world world, boreas_meadow_id meadow,
                                                      boreas_component* out, int capacity,
                                                      int* count);
/* How one part of a meadow's species looks, from its species file ("color" and
 * "translucency" of the part; the physics ignores both): for renderers, which find a
 * component's look by its species and part. */
typedef struct boreas_meadow_part {
  int32_t species;    /* index into the meadow's species list (boreas_component.species) */
  int32_t part;       /* index into the species' parts (boreas_component.part) */
  char name[32];      /* the part's name in its file, NUL-terminated (cut at 31 bytes) */
  float color[3];     /* sRGB, 0..1: the upper side in daylight (default: green; petals white) */
  float translucency; /* 0..1: the share of light through the tissue, per channel of color */
} boreas_meadow_part;

/* Every part of every species of the meadow, species by species in the meadow's order,
 * parts in their file's order. out NULL: *count receives the count; else capacity must
 * reach it (the rule of every list getter). */
BOREAS_API boreas_status boreas_meadow_get_parts(boreas_world world, boreas_meadow_id meadow,
                                                 boreas_meadow_part* out, int capacity, int* count);

/* Vertices reserved per component: a strip of two per joint, at most 9 joints. */
#define BOREAS_MEADOW_VERTEX_STRIDE 18

/* The components' triangle strips as of the last step, rebuilt from each center of mass,
 * at the distance LOD seen from camera[3] (NULL: full detail everywhere). Component i's
 * strip starts at vertex i * BOREAS_MEADOW_VERTEX_STRIDE and has strip_counts[i]
 * vertices: 2 (S + 1) near, 2 (ceil(S/2) + 1) past lod_distances[0], 4 past [1], 0 past
 * [2] (S: its sections); the rest of its range repeats its tip. With vertices NULL,
 * vertex_count receives the component count * BOREAS_MEADOW_VERTEX_STRIDE; else
 * vertex_capacity must reach it. strip_counts may be NULL; else it holds one int per
 * component. */
BOREAS_API boreas_status boreas_meadow_get_vertices(boreas_world world, boreas_meadow_id meadow,
                                                    const float camera[3],
                                                    boreas_meadow_vertex* vertices,
                                                    int vertex_capacity, int* vertex_count,
                                                    int32_t* strip_counts);

BOREAS_API boreas_collider_def boreas_default_collider_def(void);
BOREAS_API boreas_status boreas_world_add_collider(boreas_world world,
                                                   const boreas_collider_def* def,
                                                   boreas_collider_id* out);
BOREAS_API boreas_status boreas_world_remove_collider(boreas_world world,
                                                      boreas_collider_id collider);
/* Moves a collider to center (m, world: its pose's origin becomes 0 and its position
 * center; the orientation and velocities stay); it acts there from the next step on.
 * boreas_collider_set_pose places one far from 0 in double. */
BOREAS_API boreas_status boreas_collider_set_position(boreas_world world,
                                                      boreas_collider_id collider,
                                                      const float center[3]);
/* Puts a collider at pose (checked as the def's, errors naming pose); the next step sweeps
 * from there. */
BOREAS_API boreas_status boreas_collider_set_pose(boreas_world world, boreas_collider_id collider,
                                                  const boreas_pose* pose);
/* Sets a collider's velocity (m/s) and angular velocity (rad/s), world frame, checked as
 * the def's; either may be NULL to keep it. */
BOREAS_API boreas_status boreas_collider_set_velocity(boreas_world world,
                                                      boreas_collider_id collider,
                                                      const float velocity[3],
                                                      const float angular_velocity[3]);
/* A collider's pose now (where the next step starts). */
BOREAS_API boreas_status boreas_collider_get_pose(boreas_world world, boreas_collider_id collider,
                                                  boreas_pose* out);
/* What the plants did to the collider over the last step (all zero before the first step,
 * and for a collider added since). */
BOREAS_API boreas_status boreas_collider_get_contact(boreas_world world,
                                                     boreas_collider_id collider,
                                                     boreas_collider_contact* out);

BOREAS_API boreas_emitter_def boreas_default_emitter_def(void);
BOREAS_API boreas_status boreas_world_add_emitter(boreas_world world, const boreas_emitter_def* def,
                                                  boreas_emitter_id* out);
BOREAS_API boreas_status boreas_world_remove_emitter(boreas_world world, boreas_emitter_id emitter);
BOREAS_API boreas_status boreas_emitter_set_position(boreas_world world, boreas_emitter_id emitter,
                                                     const float center[3]);

/* ---------------------------------------------------------------------------------------
 * Mesh trees (Kusternig 2007 sec. 5): a tree mesh made elsewhere (OBJ or glTF), with
 * no bones or branch data, animated by the world's wind. Preprocessing splits the trunk
 * part into branches (connected runs of triangles; the thickest is the stem; each branch
 * hangs on the thicker branch it grows out of), gives every vertex weights for up to four
 * levels and every branch a noise phase and two sway directions; each step, every vertex
 * moves by its levels' downwind bend and 1/f-noise sway, and leaves turn into the wind
 * and flutter as a rolling noise passes through the crown.
 * ------------------------------------------------------------------------------------- */

/* Per level (0 stem .. 3). A point of weight 1 (the tip of the level's longest branch)
 * moves by bend + sway in 10 m/s of wind normal to its branch; displacements grow with
 * the square of the wind speed and level off from about 20 m/s. Defaults (per level) are
 * boreas_default_mesh_tree_def()'s. */
typedef struct boreas_mesh_level_def {
  float bend;          /* m, 0..1e3: downwind displacement (defaults 0.3, 0.25, 0.15, 0.08) */
  float sway;          /* m, 0..1e3: noise sway amplitude (defaults 0.08, 0.08, 0.05, 0.03) */
  float frequency;     /* Hz, 0.001..50: how fast the sway runs (defaults 0.25, 0.5, 1, 2) */
  float response_time; /* s, 0..60: the level follows the wind with this lag (defaults 1.5,
                          0.8, 0.4, 0.2) */
} boreas_mesh_level_def;

/* Defaults are boreas_default_mesh_tree_def()'s; model has none and must be set. */
typedef struct boreas_mesh_tree_def {
  const char* model;       /* path: .obj, .gltf or .glb (a .glb written by
                              boreas_preprocess_mesh_tree loads without preprocessing);
                              default NULL, which is refused */
  const char* trunk_part;  /* the trunk's objects, groups or materials: comma-separated
                              names matched case-insensitively as substrings; NULL for
                              "trunk,bark,branch,stem,wood" (default NULL) */
  const char* leaves_part; /* likewise; NULL (default) for "leaf,leaves,foliage,needle" */
  float position[3];       /* m: where the model's origin goes, each within +-1e6 (default
                              0, 0, 0) */
  float yaw;               /* rad, about +Y, -1e3..1e3 (default 0) */
  float scale;             /* 1e-4..1e4, no unit: multiplies the model's lengths (default 1) */
  uint64_t seed;           /* branch phases and the noise (default 1) */
  float noise_beta;        /* each branch's sway over time has a spectrum falling as
                              1/f^beta (Kusternig), 0..4, no unit (default 2) */
  float bend_exponent;     /* weights are raised to it, 0.25..4, no unit (default 2: branches
                              bend more towards their tips, as a loaded cantilever) */
  boreas_mesh_level_def levels[4]; /* stem, then levels 1..3 (defaults above) */
  float leaf_flutter;              /* m, 0..1e3: a leaf tip's flutter in 10 m/s (default 0.04) */
  float leaf_turn;                 /* 0..1, no unit: how far leaves turn into a strong wind (default
                                      0.5) */
  float flutter_wavelength;        /* m, 1e-3..1e5: size of the rolling noise's tile (default 8) */
  int cache;               /* 1 (default): keep the preprocessing in <model>.boreas.glb
                              beside the model and reuse it while the model is unchanged */
} boreas_mesh_tree_def;

typedef enum boreas_mesh_part {
  BOREAS_MESH_TRUNK = 0, /* trunk and branches */
  BOREAS_MESH_LEAVES = 1
} boreas_mesh_part;

typedef struct boreas_mesh_tree_info {
  int trunk_vertices, trunk_triangles;
  int leaf_vertices, leaf_triangles;
  int branches; /* connected runs of trunk triangles */
  int leaves;   /* connected runs of leaf triangles */
  int levels;   /* levels found (may exceed 4: deeper branches move with their parent) */
  int orphans;  /* branches that touched no thicker branch: hung on the nearest one */
  int from_cache; /* 1 when the preprocessing was read, not computed */
} boreas_mesh_tree_info;

BOREAS_API boreas_mesh_tree_def boreas_default_mesh_tree_def(void);

/* Loads (or reads preprocessed) and places an imported tree, at rest until the next step.
 * Errors name the file and what is wrong with it. */
BOREAS_API boreas_status boreas_world_add_mesh_tree(boreas_world world,
                                                    const boreas_mesh_tree_def* def,
                                                    boreas_mesh_tree_id* out);
BOREAS_API boreas_status boreas_world_remove_mesh_tree(boreas_world world,
                                                       boreas_mesh_tree_id tree);
BOREAS_API boreas_status boreas_mesh_tree_get_info(boreas_world world, boreas_mesh_tree_id tree,
                                                   boreas_mesh_tree_info* out);
/* The part's vertices as of the last step, world space (same contract as
 * boreas_tree_get_branches). Trunk normals are the rest normals. */
BOREAS_API boreas_status boreas_mesh_tree_get_vertices(boreas_world world, boreas_mesh_tree_id tree,
                                                       boreas_mesh_part part, boreas_vertex* out,
                                                       int capacity, int* count);
/* The part's triangles: three indices each into its vertices (same contract). */
BOREAS_API boreas_status boreas_mesh_tree_get_indices(boreas_world world, boreas_mesh_tree_id tree,
                                                      boreas_mesh_part part, uint32_t* out,
                                                      int capacity, int* count);
/* Preprocesses a model without a world and writes it as a binary glTF whose vertices
 * carry the weights (_BOREAS_WEIGHTS, _BOREAS_BRANCH, ...) and whose trunk mesh's extras
 * carry the branch table, for engines to read; info may be NULL. Only the def's model,
 * trunk_part, leaves_part and seed are used. */
BOREAS_API boreas_status boreas_preprocess_mesh_tree(const boreas_mesh_tree_def* def,
                                                     const char* out_path,
                                                     boreas_mesh_tree_info* info);

/* ---------------------------------------------------------------------------------------
 * BlobTree trees (Galbraith, MacMurchy and Wyvill 2004): a tree of the world as one
 * implicit surface — a skeletal cone per internode, summed so branches blend smoothly
 * into their parents, the branches leaving one branching point combined by Precise
 * Contact Modeling so the bark rises in a ridge between them and small branches wear a
 * collar — with pruning cuts (CSG) and scars (negative fields), polygonized on the device
 * into a watertight, manifold triangle mesh.
 * ------------------------------------------------------------------------------------- */

typedef enum boreas_blobtree_junction {
  BOREAS_BLOBTREE_PCM = 0,  /* the paper's: PCM between the branches, then summed with the
                               basal internode (eq. 4-5): branch bark ridges and collars */
  BOREAS_BLOBTREE_BLEND = 1 /* every internode summed: smooth junctions, no ridges */
} boreas_blobtree_junction;

/* A pruning cut: the branch is sawn off flat at `at` of its length; what grew beyond goes. */
typedef struct boreas_blobtree_cut {
  int32_t branch; /* index in boreas_tree_get_branches' list; 0 is the trunk */
  float at;       /* 0.01..1 along the branch (its curve's parameter) */
} boreas_blobtree_cut;

/* A scar: the branch was lost; a stub remains in a hollow of negative field. */
typedef struct boreas_blobtree_scar {
  int32_t branch; /* index as above; not the trunk */
  float stub;     /* 0.01..1: the stub's length as a fraction of the branch's */
  float depth;    /* 0..1: how deep the hollow is (default 0.5) */
} boreas_blobtree_scar;

/* Defaults are boreas_default_blobtree_def()'s: the paper's junctions on a 256-point grid,
 * no cuts or scars. */
typedef struct boreas_blobtree_def {
  int resolution;      /* grid points along the tree's longest side, 16..1024 (default 256:
                          branches from ~3 cm radius on a 14 m tree; each doubling halves
                          that and costs ~8x) */
  int cubic;           /* 1: resolution^3 points (a cube around the tree), for benchmarks;
                          0 (default): the tree's box */
  int max_level;       /* deepest branch level modeled, 0..3 (default 3) */
  float min_radius;    /* m: thinner branches are left out; 0 (default): half a grid cell.
                          Every surface is at least 0.9 cells from its skeleton, so thin
                          branches stay whole tubes on the grid instead of strings of beads */
  boreas_blobtree_junction junctions; /* default BOREAS_BLOBTREE_PCM */
  int offsets;         /* 1 (default): shorten and displace internodes at junctions (eq. 3,
                          6, 7 with PCM; eq. 3 alone, children kept at the branching point,
                          when blending) against bulging; 0 to see the bulge */
  float ridge;         /* PCM's largest expansion M, 0..0.45 field units (default 0.2):
                          the height of the bark ridges */
  float ridge_width;   /* PCM's propagation width as a multiple of each branch's surface
                          distance (its radius, or the 0.9-cell floor), 0.01..10 (default
                          0.5); with 3 ridge > ~0.8 ridge_width the seam rises */
  float bend;          /* rad, 0..pi/2: each lateral branch's first internode bends away
                          from its parent and back, keeping its ends (default 0) */
  const boreas_blobtree_cut* cuts;   /* cut_count cuts (default NULL: none) */
  int cut_count;                     /* >= 0 (default 0) */
  const boreas_blobtree_scar* scars; /* scar_count scars (default NULL: none) */
  int scar_count;                    /* >= 0 (default 0) */
} boreas_blobtree_def;

/* Progress of a long call: fraction 0..1, and the stage ("field", "count", ...). Called
 * on the caller's thread, between device stages; a call into the same world from it is
 * refused ("the world is locked"). */
typedef void (*boreas_progress_fn)(void* user, float fraction, const char* stage);

typedef struct boreas_blobtree_info {
  int vertices, triangles;
  int primitives;    /* skeletal primitives in the BlobTree */
  int branches;      /* tree branches modeled (the rest were thinner than min_radius) */
  int grid[3];       /* grid points along x, y, z */
  float cell;        /* m: grid spacing */
  float min_radius;  /* m: the one used */
  float bounds_min[3], bounds_max[3]; /* m: the mesh's box */
} boreas_blobtree_info;

BOREAS_API boreas_blobtree_def boreas_default_blobtree_def(void);

/* Builds the BlobTree of a tree of the world (its rest pose) and polygonizes it; the mesh
 * stays in the world under *out until removed. progress may be NULL. Errors name the field
 * of the def that is wrong (a cut's branch that does not exist, a resolution out of range)
 * or the size that does not fit the device; nothing is added then. */
BOREAS_API boreas_status boreas_world_add_blobtree(boreas_world world, boreas_tree_id tree,
                                                   const boreas_blobtree_def* def,
                                                   boreas_progress_fn progress, void* user,
                                                   boreas_blobtree_id* out);
BOREAS_API boreas_status boreas_world_remove_blobtree(boreas_world world,
                                                      boreas_blobtree_id blobtree);
BOREAS_API boreas_status boreas_blobtree_get_info(boreas_world world, boreas_blobtree_id blobtree,
                                                  boreas_blobtree_info* out);
/* The mesh (same contract as boreas_tree_get_mesh): vertices with outward normals from the
 * field's gradient and texture coordinates blended from the primitives' (u turns around a
 * branch 0..1, v runs along it, one unit per circumference at the branch's base);
 * triangles counter-clockwise seen from outside. */
BOREAS_API boreas_status boreas_blobtree_get_mesh(boreas_world world, boreas_blobtree_id blobtree,
                                                  boreas_vertex* vertices, int vertex_capacity,
                                                  int* vertex_count, uint32_t* indices,
                                                  int index_capacity, int* index_count);

/* ---------------------------------------------------------------------------------------
 * Rays: what a range sensor or a camera sees of the world as of the last step — branches
 * as the deformer sweeps them (each branch's (rings + 1) x (sides + 1) grid of
 * boreas_tree_get_mesh, two triangles a quad), leaves as their outline on the quad the
 * renderer draws (a ray through a notch between an oak leaf's lobes passes), underbrush as
 * its strips at full detail (boreas_meadow_get_vertices with camera NULL), imported trees'
 * swayed triangles, BlobTree meshes, each meadow's ground and the wind grid's solid boxes.
 * ------------------------------------------------------------------------------------- */

/* A ray: from origin along direction (normalized by the call; it need not be unit, but
 * finite and not zero) up to max_distance (m, >= 0; INFINITY: unbounded). */
typedef struct boreas_ray {
  float origin[3];    /* m, finite, relative to the world's output origin
                         (boreas_world_set_output_origin; world coordinates by default) */
  float direction[3]; /* finite, not zero */
  float max_distance; /* m, >= 0, not NaN */
} boreas_ray;

/* What a ray hit. */
typedef enum boreas_hit_kind {
  BOREAS_HIT_NONE = 0,       /* nothing within max_distance */
  BOREAS_HIT_BRANCH = 1,     /* a generated tree's branch: object a boreas_tree_id, part the
                                branch's index in boreas_tree_get_branches */
  BOREAS_HIT_LEAF = 2,       /* a generated tree's leaf: part its index in
                                boreas_tree_get_leaves */
  BOREAS_HIT_MESH_TRUNK = 3, /* an imported tree's trunk: object a boreas_mesh_tree_id, part
                                the triangle's index in its BOREAS_MESH_TRUNK indices / 3 */
  BOREAS_HIT_MESH_LEAF = 4,  /* an imported tree's leaves: part as above, BOREAS_MESH_LEAVES */
  BOREAS_HIT_UNDERBRUSH = 5, /* a component: object a boreas_meadow_id, part its index in
                                boreas_meadow_get_components */
  BOREAS_HIT_BLOBTREE = 6,   /* a BlobTree surface: object a boreas_blobtree_id, part the
                                triangle's index in boreas_blobtree_get_mesh's indices / 3 */
  BOREAS_HIT_GROUND = 7,     /* a meadow's ground: object its boreas_meadow_id, part the
                                triangle of its height grid */
  BOREAS_HIT_SOLID_BOX = 8   /* a solid box of the wind grid: object null, part the box's
                                index among boreas_wind_add_solid_box's boxes in the order
                                added */
} boreas_hit_kind;

/* The id of whatever kind of object hit.kind names: its fields are those of the typed id
 * (boreas_tree_id, boreas_meadow_id, ...); boreas_hit_tree() and its siblings below make
 * the typed id. */
BOREAS_DECLARE_ID(object)

typedef struct boreas_hit {
  float distance;     /* m from the ray's origin along its normalized direction; INFINITY
                         when kind is BOREAS_HIT_NONE */
  float point[3];     /* m: where the ray met the surface, relative to the output origin as
                         the ray's origin is (0 on a miss) */
  float normal[3];    /* unit: the normal of the triangle (or box face) hit, turned to face
                         the ray (every surface is seen from both sides); 0 on a miss */
  int32_t kind;       /* boreas_hit_kind */
  boreas_object_id object; /* the object hit (null on a miss and for solid boxes) */
  int32_t part;       /* which part of it (boreas_hit_kind says which list); -1 on a miss */
} boreas_hit;

/* The typed id of the object a hit names, or the null id when the hit is of another kind:
 * boreas_hit_tree (branches, leaves), boreas_hit_mesh_tree (imported trunks and leaves),
 * boreas_hit_meadow (underbrush, ground), boreas_hit_blobtree. */
#define BOREAS_HIT_ID(name, first, second)                                                  \
  static inline boreas_##name##_id boreas_hit_##name(const boreas_hit* hit) {                \
    boreas_##name##_id id = {0, 0, 0};                                                      \
    if (hit->kind == (first) || hit->kind == (second)) {                                    \
      id.index = hit->object.index;                                                         \
      id.generation = hit->object.generation;                                               \
      id.tag = hit->object.tag;                                                             \
    }                                                                                       \
    return id;                                                                              \
  }
BOREAS_HIT_ID(tree, BOREAS_HIT_BRANCH, BOREAS_HIT_LEAF)
BOREAS_HIT_ID(mesh_tree, BOREAS_HIT_MESH_TRUNK, BOREAS_HIT_MESH_LEAF)
BOREAS_HIT_ID(meadow, BOREAS_HIT_UNDERBRUSH, BOREAS_HIT_GROUND)
BOREAS_HIT_ID(blobtree, BOREAS_HIT_BLOBTREE, BOREAS_HIT_BLOBTREE)
#undef BOREAS_HIT_ID

/* Casts count rays into the world as of the last step and writes count hits (the nearest
 * surface along each ray). The first cast after a step updates the world's ray structure
 * (a world nobody casts into pays nothing for it); casts in one state give the same bits.
 * Bad input (a NULL array with count > 0, count < 0, a ray with a non-finite origin, a zero
 * or non-finite direction, a negative or NaN max_distance) is refused naming the ray's
 * index, and nothing is written. */
BOREAS_API boreas_status boreas_world_cast_rays(boreas_world world, const boreas_ray* rays,
                                                int count, boreas_hit* hits);

/* ---------------------------------------------------------------------------------------
 * Sensors: a spinning LiDAR and a depth camera, both made of the rays above, so they see
 * what boreas_world_cast_rays sees (README, "Sensors").
 *
 * Frames. A sensor's pose places its own axes in the world: position (m) and orientation,
 * a unit quaternion (x, y, z, w) turning the sensor's axes into the world's. A LiDAR spins
 * about its local +Y (up, like the world's), azimuth 0 along its local +X and growing
 * counter-clockwise seen from above (a positive turn about +Y: azimuth a points along
 * (cos a, 0, -sin a)); a channel's vertical angle is its elevation above the local XZ
 * plane. A camera looks along its local -Z with +Y up and +X right, like OpenGL's. Every
 * point and every hit comes out in the world frame, relative to the world's output origin
 * (boreas_world_set_output_origin; world coordinates by default).
 * ------------------------------------------------------------------------------------- */

/* boreas_pose (where a sensor is) is declared with the colliders, which have one too. */

/* The surfaces a LiDAR tells apart by their reflectivity (boreas_lidar_def.reflectivity):
 * bark is a tree's branches (BOREAS_HIT_BRANCH, BOREAS_HIT_MESH_TRUNK, BOREAS_HIT_BLOBTREE),
 * leaf a tree's leaves (BOREAS_HIT_LEAF, BOREAS_HIT_MESH_LEAF), grass the underbrush,
 * ground a meadow's ground, solid the wind grid's solid boxes. */
typedef enum boreas_lidar_surface {
  BOREAS_LIDAR_BARK = 0,
  BOREAS_LIDAR_LEAF = 1,
  BOREAS_LIDAR_GRASS = 2,
  BOREAS_LIDAR_GROUND = 3,
  BOREAS_LIDAR_SOLID = 4,
  BOREAS_LIDAR_SURFACES = 5 /* how many there are */
} boreas_lidar_surface;

/* The surface a hit of kind hit_kind (boreas_hit_kind) is, by the grouping above. */
static inline boreas_lidar_surface boreas_lidar_surface_of(int32_t hit_kind) {
  switch (hit_kind) {
    case BOREAS_HIT_LEAF:
    case BOREAS_HIT_MESH_LEAF:
      return BOREAS_LIDAR_LEAF;
    case BOREAS_HIT_UNDERBRUSH:
      return BOREAS_LIDAR_GRASS;
    case BOREAS_HIT_GROUND:
      return BOREAS_LIDAR_GROUND;
    case BOREAS_HIT_SOLID_BOX:
      return BOREAS_LIDAR_SOLID;
    default: /* branches, imported trunks, BlobTree surfaces */
      return BOREAS_LIDAR_BARK;
  }
}

/* A spinning LiDAR. Defaults are boreas_default_lidar_def()'s: a 16-channel unit like the
 * "VLP-16" preset, at the origin. Each step casts the firings whose times fall in the
 * step (README, "Sensors"). */
typedef struct boreas_lidar_def {
  int channels;                 /* 1..BOREAS_LIDAR_MAX_CHANNELS (default 16) */
  const float* vertical_angles; /* rad, `channels` elevations, each in [-pi/2, pi/2],
                                   copied; ring i fires at vertical_angles[i]. NULL
                                   (default): spread evenly over vertical_fov */
  float vertical_fov[2];        /* rad, the lowest and highest elevation when
                                   vertical_angles is NULL, -pi/2 <= [0] <= [1] <= pi/2
                                   (default -0.261799, 0.261799: +-15 degrees); ring 0
                                   fires at [0], the last ring at [1] (one channel: the
                                   middle) */
  int points_per_turn;          /* firings of each channel per turn, >= 1, with channels *
                                   points_per_turn <= BOREAS_LIDAR_MAX_RAYS_PER_TURN
                                   (default 1800: 0.2 degrees apart) */
  float rotation_rate;          /* Hz, turns per second, 0.01..1000 (default 10) */
  float min_range;              /* m: nearer hits give no point, 0 <= min_range <
                                   max_range (default 0.5) */
  float max_range;              /* m, <= 1e5 (default 100): farther is a miss */
  float range_noise;            /* m, standard deviation of Gaussian noise added to each
                                   range along its ray, 0..100 (default 0.015) */
  float dropout;                /* 0..1, no unit: the chance a hit gives no point
                                   (default 0) */
  float reflectivity[BOREAS_LIDAR_SURFACES]; /* 0..1 per boreas_lidar_surface (defaults
                                   bark 0.35, leaf 0.5, grass 0.45, ground 0.3, solid 0.35:
                                   near-infrared reflectances at 905 nm, README says where
                                   from) */
  boreas_pose pose;             /* the mounting pose (default boreas_default_pose()) */
  uint64_t seed;                /* noise and dropout (default 1): the same seed gives the
                                   same points, however the steps cut the sweep */
} boreas_lidar_def;

/* One LiDAR return. The first six fields are laid out as a ROS PointCloud2 of x, y, z,
 * intensity (FLOAT32 at offsets 0, 4, 8, 12), ring (UINT16 at 16) and time (FLOAT32 at
 * 20) reads them; 44 bytes a point. */
typedef struct boreas_lidar_point {
  float x, y, z;         /* m, world axes, relative to the world's output origin: origin +
                            range * direction of its ray */
  float intensity;       /* 0..1: the surface's reflectivity times |cos| of the angle
                            between the ray and the surface's normal */
  uint16_t ring;         /* the channel, index into the def's vertical angles */
  uint16_t reserved;     /* 0 */
  float time;            /* s since the sweep the point belongs to began */
  int32_t kind;          /* boreas_hit_kind (never BOREAS_HIT_NONE: a miss gives no point) */
  boreas_object_id object; /* as boreas_hit.object */
  int32_t part;          /* as boreas_hit.part */
} boreas_lidar_point;

/* Which points boreas_lidar_get_points returns. */
typedef enum boreas_lidar_points {
  BOREAS_LIDAR_LAST_STEP = 0, /* the firings of the last step (a slice of a sweep, or the
                                 end of one sweep and the start of the next) */
  BOREAS_LIDAR_LAST_SWEEP = 1 /* the last complete turn, gathered over the steps it took */
} boreas_lidar_points;

/* Where a LiDAR's sweep stands. */
typedef struct boreas_lidar_info {
  double sweep_start;     /* s, world time the last complete sweep began (0 before one) */
  double next_sweep_start; /* s, world time the sweep under way began */
  int64_t sweeps;         /* complete sweeps so far */
  int64_t firings;        /* firings (of all channels at one azimuth) so far */
  int32_t last_step_rays; /* rays the last step cast */
} boreas_lidar_info;

BOREAS_API boreas_pose boreas_default_pose(void);
/* The pose a fraction s (0..1) of the way from a to b: origin linear (in double), position
 * linear, orientation
 * spherical linear along the shorter arc (as a LiDAR's pose moves across a step), for
 * callers that move sensors along paths of keyframes. Both poses are checked as
 * boreas_lidar_set_pose checks one; errors name a or b. */
BOREAS_API boreas_status boreas_pose_between(const boreas_pose* a, const boreas_pose* b, float s,
                                             boreas_pose* out);
BOREAS_API boreas_lidar_def boreas_default_lidar_def(void);

/* The def of a common unit by name: "VLP-16", "HDL-32E", "HDL-64E", "OS1-128" (their
 * published vertical angles, rate, resolution and range; the README lists the sources).
 * vertical_angles points into the library's own table (valid for the process's life);
 * vertical_fov holds the lowest and highest of them.
 * An unknown name is BOREAS_ERROR_INVALID_ARGUMENT listing the known ones. */
BOREAS_API boreas_status boreas_lidar_preset(const char* name, boreas_lidar_def* out);
/* The name of preset number index (0, 1, ...), or NULL past the last. */
BOREAS_API const char* boreas_lidar_preset_name(int index);

/* Adds a LiDAR; its first sweep begins at the world's time now, and the next step casts
 * its first firings. A step longer than a turn casts only its last two turns' firings. */
BOREAS_API boreas_status boreas_world_add_lidar(boreas_world world, const boreas_lidar_def* def,
                                                boreas_lidar_id* out);
BOREAS_API boreas_status boreas_world_remove_lidar(boreas_world world, boreas_lidar_id lidar);
/* Moves a LiDAR: the pose it reaches at the end of the next step. Over that step each
 * firing takes the pose in between at its time (position linear, orientation spherical
 * linear), as a unit on a moving vehicle does; a pose set once and left stays. */
BOREAS_API boreas_status boreas_lidar_set_pose(boreas_world world, boreas_lidar_id lidar,
                                               const boreas_pose* pose);
/* Its points (the output-array rule: out NULL for the count), in firing order, channels in
 * ring order within a firing. */
BOREAS_API boreas_status boreas_lidar_get_points(boreas_world world, boreas_lidar_id lidar,
                                                 boreas_lidar_points which,
                                                 boreas_lidar_point* out, int capacity,
                                                 int* count);
BOREAS_API boreas_status boreas_lidar_get_info(boreas_world world, boreas_lidar_id lidar,
                                               boreas_lidar_info* out);

/* A pinhole depth camera. Defaults are boreas_default_depth_camera_def()'s: 640 x 480
 * pixels, 525 pixels focal length (about 63 degrees across), at the origin. Pixel (u, v)
 * is column u from the left and row v from the top; its center is at (u, v) in the
 * intrinsics' coordinates (OpenCV's), so its ray runs along ((u - cx) / fx,
 * -(v - cy) / fy, -1) in the camera's frame. */
typedef struct boreas_depth_camera_def {
  int width, height;  /* pixels, >= 1 each, width * height <= BOREAS_DEPTH_CAMERA_MAX_PIXELS
                         (default 640, 480) */
  float fx, fy;       /* pixels, focal lengths, 1e-3..1e7 (default 525, 525) */
  float cx, cy;       /* pixels, the principal point, each within +-1e7 (default 319.5,
                         239.5: the middle) */
  float max_depth;    /* m, along the optical axis, 1e-3..1e5 (default 100): farther is
                         nothing */
  boreas_pose pose;   /* default boreas_default_pose() */
} boreas_depth_camera_def;

/* What a pixel sees: the hit's kind, object and part (boreas_hit's fields; kind
 * BOREAS_HIT_NONE, object null, part -1 where nothing). */
typedef struct boreas_pixel_label {
  int32_t kind;
  boreas_object_id object;
  int32_t part;
} boreas_pixel_label;

BOREAS_API boreas_depth_camera_def boreas_default_depth_camera_def(void);

/* One depth image of the world as of the last step: width * height rays, row by row from
 * the top. depth (width * height floats, or NULL) receives each pixel's depth along the
 * optical axis (m; INFINITY where nothing lies within max_depth); labels (width * height,
 * or NULL) what each pixel sees. */
BOREAS_API boreas_status boreas_world_capture_depth(boreas_world world,
                                                    const boreas_depth_camera_def* camera,
                                                    float* depth, boreas_pixel_label* labels);

#ifdef __cplusplus
}
#endif

#endif
