"""boreas: vegetation in wind, simulated with OpenCL, for Python.

Wind (analytic sine sums plus a force-field grid with gusts, flow primitives and solids),
Weber-Penn trees bent as Bezier curves, underbrush as constrained vector sets, imported
tree meshes and BlobTree surfaces, on a GPU or a CPU (PoCL). Y is up, the ground is the
XZ plane, units are SI (m, s, m/s). Arrays are NumPy arrays: points and vectors float32
of shape (N, 3), lists of C structs as structured arrays (``BRANCH_DTYPE``, ...).

Examples
--------
>>> import boreas
>>> with boreas.World(waves=[boreas.Wave(direction=(1, 0), amplitude=6.0)]) as world:
...     tree = world.add_tree("black_tupelo", position=(0, 0, 0))
...     for _ in range(30):
...         world.step(1 / 30)
...     tip = tree.branches["control_points"][:, 3]     # (B, 3) float32, m
...     wind = world.wind.sample([[0, 2, 0], [5, 2, 0]])  # (2, 3) float32, m/s

Threads: every long call (steps, samples, adds) releases the GIL. Calls on one world take
turns; for parallel work give each thread its own world.
"""
from . import _boreas
from ._boreas import (BRANCH_DTYPE, COMPONENT_DTYPE, HIT_DTYPE, LEAF_DTYPE, LIDAR_POINT_DTYPE,
                      MEADOW_PART_DTYPE, MEADOW_VERTEX_DTYPE, MEADOW_VERTEX_STRIDE,
                      PIXEL_LABEL_DTYPE, VERTEX_DTYPE, Error, FileError, InternalError,
                      InvalidArgumentError, KernelBuildError, NoDeviceError, NotFoundError,
                      OpenCLError, OutOfMemoryError)
# A tree's skin (boreas_tree_get_joints): the skeleton glTF files and Blender share.
from ._boreas import (ANIMATION_MAX_FRAMES, ANIMATION_MAX_MORPH_FRAMES, JOINT_DTYPE, SKIN_MAX_SEGMENTS,
                      SKIN_WEIGHT_DTYPE, ANIMATION_MAX_CLUMPS, ANIMATION_MAX_WARMUP_SECONDS)
# The library's limits (boreas.h, "Limits"): the C names less BOREAS_.
from ._boreas import (GRID_MAX_CELLS, GRID_MAX_RESOLUTION, IMAGE_MAX_FLOATS,
                      COLLIDER_MAX_SPEED, COLLIDER_MAX_SPIN, DEPTH_CAMERA_MAX_PIXELS,
                      LIDAR_MAX_CHANNELS, LIDAR_MAX_RAYS_PER_TURN,
                      MEADOW_MAX_COMPONENTS, MEADOW_MAX_DENSITY, MEADOW_MAX_SEED_POINTS,
                      MEADOW_MAX_SPECIES, PLANT_MAX_COMPONENTS, STEP_MAX_SECONDS,
                      WIND_MAX_SPEED, WIND_MAX_WAVES, WIND_SAMPLE_MAX_POINTS,
                      WORLD_MAX_COORDINATE)
from ._defs import (BlobTreeInfo, ColliderContact, DeviceInfo, Grid, MemoryInfo, MeshTreeInfo,
                    StepStats, Wave, defaults)
from ._handles import (BlobTree, Collider, Emitter, FlowPrimitive, Gust, Handle, Meadow,
                       MeshTree, Tree)
from ._sensors import Lidar, lidar_preset, lidar_presets
from ._wind import Wind
from ._world import (World, builtin_underbrush_species, builtin_species, devices,
                     preprocess_mesh_tree)

#: str: the loaded C library's version, "MAJOR.MINOR.PATCH" (``boreas_version()``).
__version__: str = _boreas.__version__

__all__ = [
    "JOINT_DTYPE", "SKIN_WEIGHT_DTYPE", "SKIN_MAX_SEGMENTS", "ANIMATION_MAX_FRAMES", "ANIMATION_MAX_MORPH_FRAMES",
    "ANIMATION_MAX_CLUMPS", "ANIMATION_MAX_WARMUP_SECONDS", "BRANCH_DTYPE", "COMPONENT_DTYPE", "LEAF_DTYPE", "MEADOW_PART_DTYPE", "MEADOW_VERTEX_DTYPE",
    "MEADOW_VERTEX_STRIDE", "VERTEX_DTYPE", "HIT_DTYPE", "LIDAR_POINT_DTYPE", "PIXEL_LABEL_DTYPE",
    "GRID_MAX_CELLS", "GRID_MAX_RESOLUTION", "IMAGE_MAX_FLOATS", "MEADOW_MAX_COMPONENTS",
    "MEADOW_MAX_DENSITY", "MEADOW_MAX_SEED_POINTS", "MEADOW_MAX_SPECIES", "PLANT_MAX_COMPONENTS",
    "STEP_MAX_SECONDS", "WIND_MAX_SPEED", "WIND_MAX_WAVES", "WIND_SAMPLE_MAX_POINTS",
    "WORLD_MAX_COORDINATE", "LIDAR_MAX_CHANNELS", "LIDAR_MAX_RAYS_PER_TURN",
    "DEPTH_CAMERA_MAX_PIXELS", "COLLIDER_MAX_SPEED", "COLLIDER_MAX_SPIN",
    "Error", "FileError", "InternalError", "InvalidArgumentError", "KernelBuildError",
    "NoDeviceError", "NotFoundError", "OpenCLError", "OutOfMemoryError",
    "BlobTreeInfo", "ColliderContact", "DeviceInfo", "Grid", "MemoryInfo", "MeshTreeInfo", "StepStats", "Wave",
    "BlobTree", "Collider", "Emitter", "FlowPrimitive", "Gust", "Handle", "Meadow", "MeshTree",
    "Tree", "Wind", "World", "Lidar",
    "builtin_underbrush_species", "builtin_species", "defaults", "devices", "preprocess_mesh_tree",
    "lidar_preset", "lidar_presets",
    "__version__",
]
