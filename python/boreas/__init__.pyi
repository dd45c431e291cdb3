"""Type stubs of the package boreas (its public API; docstrings in the modules)."""
import os
from dataclasses import dataclass
from typing import (Any, Callable, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple,
                    Union)

import numpy as np

from ._boreas import (BRANCH_DTYPE as BRANCH_DTYPE, COMPONENT_DTYPE as COMPONENT_DTYPE,
                      HIT_DTYPE as HIT_DTYPE, LIDAR_POINT_DTYPE as LIDAR_POINT_DTYPE,
                      PIXEL_LABEL_DTYPE as PIXEL_LABEL_DTYPE,
                      MEADOW_PART_DTYPE as MEADOW_PART_DTYPE,
                      LEAF_DTYPE as LEAF_DTYPE, MEADOW_VERTEX_DTYPE as MEADOW_VERTEX_DTYPE,
                      MEADOW_VERTEX_STRIDE as MEADOW_VERTEX_STRIDE,
                      VERTEX_DTYPE as VERTEX_DTYPE, Error as Error, FileError as FileError,
                      InternalError as InternalError,
                      InvalidArgumentError as InvalidArgumentError,
                      KernelBuildError as KernelBuildError, NoDeviceError as NoDeviceError,
                      NotFoundError as NotFoundError, OpenCLError as OpenCLError,
                      OutOfMemoryError as OutOfMemoryError)
from ._boreas import (JOINT_DTYPE as JOINT_DTYPE, SKIN_WEIGHT_DTYPE as SKIN_WEIGHT_DTYPE,
                      SKIN_MAX_SEGMENTS as SKIN_MAX_SEGMENTS,
                      ANIMATION_MAX_FRAMES as ANIMATION_MAX_FRAMES,
                      ANIMATION_MAX_MORPH_FRAMES as ANIMATION_MAX_MORPH_FRAMES,
                      ANIMATION_MAX_CLUMPS as ANIMATION_MAX_CLUMPS,
                      ANIMATION_MAX_WARMUP_SECONDS as ANIMATION_MAX_WARMUP_SECONDS)
from ._boreas import (GRID_MAX_CELLS as GRID_MAX_CELLS,
                      GRID_MAX_RESOLUTION as GRID_MAX_RESOLUTION,
                      IMAGE_MAX_FLOATS as IMAGE_MAX_FLOATS,
                      COLLIDER_MAX_SPEED as COLLIDER_MAX_SPEED,
                      COLLIDER_MAX_SPIN as COLLIDER_MAX_SPIN,
                      DEPTH_CAMERA_MAX_PIXELS as DEPTH_CAMERA_MAX_PIXELS,
                      LIDAR_MAX_CHANNELS as LIDAR_MAX_CHANNELS,
                      LIDAR_MAX_RAYS_PER_TURN as LIDAR_MAX_RAYS_PER_TURN,
                      MEADOW_MAX_COMPONENTS as MEADOW_MAX_COMPONENTS,
                      MEADOW_MAX_DENSITY as MEADOW_MAX_DENSITY,
                      MEADOW_MAX_SEED_POINTS as MEADOW_MAX_SEED_POINTS,
                      MEADOW_MAX_SPECIES as MEADOW_MAX_SPECIES,
                      PLANT_MAX_COMPONENTS as PLANT_MAX_COMPONENTS,
                      STEP_MAX_SECONDS as STEP_MAX_SECONDS, WIND_MAX_SPEED as WIND_MAX_SPEED,
                      WIND_MAX_WAVES as WIND_MAX_WAVES,
                      WIND_SAMPLE_MAX_POINTS as WIND_SAMPLE_MAX_POINTS,
                      WORLD_MAX_COORDINATE as WORLD_MAX_COORDINATE)

__version__: str

PathLike = Union[str, os.PathLike[str]]
Vec3 = Sequence[float]
Id = Tuple[int, int, int]
ProgressCallback = Callable[[float, str], Any]

def defaults() -> Dict[str, Dict[str, Any]]: ...
def devices() -> List[DeviceInfo]: ...
def builtin_species() -> List[str]: ...
def builtin_underbrush_species() -> List[str]: ...
def lidar_presets() -> List[str]: ...
def lidar_preset(name: str) -> Dict[str, Any]: ...
def preprocess_mesh_tree(model: PathLike, out_path: PathLike, *,
                         trunk_part: Optional[str] = ..., leaves_part: Optional[str] = ...,
                         seed: Optional[int] = ...) -> MeshTreeInfo: ...

@dataclass
class Grid:
    origin: Tuple[float, float, float]
    cell_size: float
    resolution: Tuple[int, int, int]
    diffusion: float
    decay_rate: float
    response_time: float
    edge_fade: float
    follow_focus: bool
    wind_sampling: str
    def __init__(self, origin: Tuple[float, float, float] = ..., cell_size: float = ...,
                 resolution: Tuple[int, int, int] = ..., diffusion: float = ...,
                 decay_rate: float = ..., response_time: float = ..., edge_fade: float = ...,
                 follow_focus: bool = ..., wind_sampling: str = ...) -> None: ...

@dataclass
class Wave:
    direction: Tuple[float, float]
    amplitude: float
    wavelength: float
    speed: float
    sharpness: float
    def __init__(self, direction: Tuple[float, float] = ..., amplitude: float = ...,
                 wavelength: float = ..., speed: float = ..., sharpness: float = ...) -> None: ...

@dataclass(frozen=True)
class DeviceInfo:
    name: str
    platform: str
    version: str
    driver_version: str
    is_gpu: bool
    compute_units: int
    global_memory: int
    has_gl_sharing: bool
    has_fp64: bool
    uses_fast_math: bool
    platform_index: int
    device_index: int
    @property
    def request(self) -> str: ...

@dataclass(frozen=True)
class StepStats:
    wind: float
    trees: float
    underbrush: float
    total: float
    trees_by_lod: Tuple[int, int, int, int]
    branches_stepped: int
    branches_carried: int
    branches_broken: int
    components_by_rate: Tuple[int, int, int, int]

@dataclass(frozen=True)
class MemoryInfo:
    device_bytes: int
    device_limit: int
    kernel_variants: int

@dataclass(frozen=True)
class MeshTreeInfo:
    trunk_vertices: int
    trunk_triangles: int
    leaf_vertices: int
    leaf_triangles: int
    branches: int
    leaves: int
    levels: int
    orphans: int
    from_cache: bool

@dataclass(frozen=True)
class ColliderContact:
    force: Tuple[float, float, float]
    torque: Tuple[float, float, float]
    contacts: int

@dataclass(frozen=True)
class BlobTreeInfo:
    vertices: int
    triangles: int
    primitives: int
    branches: int
    grid: Tuple[int, int, int]
    cell: float
    min_radius: float
    bounds_min: Tuple[float, float, float]
    bounds_max: Tuple[float, float, float]

class Handle:
    def __init__(self, world: World, id: Id) -> None: ...
    @property
    def world(self) -> World: ...
    @property
    def id(self) -> Id: ...
    def remove(self) -> None: ...
    def __eq__(self, other: object) -> bool: ...
    def __hash__(self) -> int: ...

class Tree(Handle):
    @property
    def branches(self) -> np.ndarray: ...
    @property
    def leaves(self) -> np.ndarray: ...
    def leaf_occlusion(self, transmittance: Sequence[float] = ...) -> np.ndarray: ...
    def heal(self) -> None: ...
    def mesh(self) -> Tuple[np.ndarray, np.ndarray]: ...
    def skin(self, max_level: int = ..., segments: int = ...) -> Tuple[np.ndarray, np.ndarray, np.ndarray]: ...
    def joints(self, max_level: int = ..., segments: int = ...) -> np.ndarray: ...
    def add_blobtree(self, *, resolution: Optional[int] = ..., cubic: Optional[bool] = ...,
                     max_level: Optional[int] = ..., min_radius: Optional[float] = ...,
                     junctions: Optional[str] = ..., offsets: Optional[bool] = ...,
                     ridge: Optional[float] = ..., ridge_width: Optional[float] = ...,
                     bend: Optional[float] = ..., cuts: Optional[Sequence[Any]] = ...,
                     scars: Optional[Sequence[Any]] = ...,
                     progress: Optional[ProgressCallback] = ...) -> BlobTree: ...

class Meadow(Handle):
    @property
    def components(self) -> np.ndarray: ...
    @property
    def parts(self) -> np.ndarray: ...
    def vertices(self, camera: Optional[Vec3] = ...) -> Tuple[np.ndarray, np.ndarray]: ...

class Collider(Handle):
    @property
    def pose(self) -> Dict[str, Tuple[float, ...]]: ...
    @property
    def position(self) -> Tuple[float, float, float]: ...
    @position.setter
    def position(self, center: Vec3) -> None: ...
    def set_pose(self, position: Vec3, orientation: Optional[Sequence[float]] = ...,
                 origin: Optional[Vec3] = ...) -> None: ...
    def set_velocity(self, velocity: Optional[Vec3] = ...,
                     angular_velocity: Optional[Vec3] = ...) -> None: ...
    @property
    def contact(self) -> ColliderContact: ...

class Emitter(Handle):
    def __init__(self, world: World, id: Id, position: Vec3) -> None: ...
    @property
    def position(self) -> Tuple[float, float, float]: ...
    @position.setter
    def position(self, center: Vec3) -> None: ...

class Lidar(Handle):
    def __init__(self, world: World, id: Id, pose: Optional[Dict[str, Any]]) -> None: ...
    @property
    def pose(self) -> Optional[Dict[str, Any]]: ...
    @pose.setter
    def pose(self, pose: Mapping[str, Any]) -> None: ...
    def points(self, which: str = ...) -> np.ndarray: ...
    def info(self) -> Dict[str, Any]: ...

class Gust(Handle): ...
class FlowPrimitive(Handle): ...

class MeshTree(Handle):
    @property
    def info(self) -> MeshTreeInfo: ...
    def vertices(self, part: str = ...) -> np.ndarray: ...
    def indices(self, part: str = ...) -> np.ndarray: ...

class BlobTree(Handle):
    @property
    def info(self) -> BlobTreeInfo: ...
    def mesh(self) -> Tuple[np.ndarray, np.ndarray]: ...

class Wind:
    def __init__(self, world: World) -> None: ...
    def sample(self, points: Any, out: Optional[np.ndarray] = ...) -> np.ndarray: ...
    def set_waves(self, waves: Iterable[Union[Wave, Mapping[str, Any]]],
                  blend: float = ...) -> None: ...
    def add_gust(self, direction: Optional[Vec3] = ..., strength: Optional[float] = ..., *,
                 delay: Optional[float] = ..., rise: Optional[float] = ...,
                 hold: Optional[float] = ..., fall: Optional[float] = ...,
                 center: Optional[Vec3] = ..., radius: Optional[float] = ...) -> Gust: ...
    def add_primitive(self, type: str = ..., position: Optional[Vec3] = ...,
                      direction: Optional[Vec3] = ..., *, strength: Optional[float] = ...,
                      radius: Optional[float] = ...,
                      lifetime: Optional[float] = ...) -> FlowPrimitive: ...
    def add_solid_box(self, min: Vec3, max: Vec3) -> None: ...
    def set_solid_mask(self, mask: Optional[Any]) -> None: ...
    @property
    def grid(self) -> Grid: ...
    def grid_values(self) -> np.ndarray: ...

class World:
    def __init__(self, device: Union[str, DeviceInfo, None] = ...,
                 grid: Union[Grid, Mapping[str, Any], None] = ...,
                 waves: Optional[Iterable[Union[Wave, Mapping[str, Any]]]] = ...,
                 cache_dir: Optional[PathLike] = ...) -> None: ...
    def close(self) -> None: ...
    @property
    def closed(self) -> bool: ...
    def __enter__(self) -> World: ...
    def __exit__(self, *exc_info: Any) -> None: ...
    def step(self, dt: float) -> None: ...
    @property
    def time(self) -> float: ...
    @property
    def device(self) -> DeviceInfo: ...
    @property
    def step_stats(self) -> StepStats: ...
    @property
    def memory(self) -> MemoryInfo: ...
    def state_hash(self) -> int: ...
    @property
    def wind(self) -> Wind: ...
    def set_focus(self, points: Any) -> None: ...
    def set_output_origin(self, origin: Optional[Sequence[float]]) -> None: ...
    def add_tree(self, species: Optional[PathLike] = ..., position: Optional[Vec3] = ..., *,
                 rotation: Optional[float] = ..., scale: Optional[float] = ...,
                 seed: Optional[int] = ..., mode: Optional[str] = ...,
                 response: Optional[str] = ..., load: Optional[str] = ...,
                 bend_exponent: Optional[float] = ...,
                 levels: Optional[Sequence[Optional[Mapping[str, Any]]]] = ...,
                 lod_distances: Optional[Vec3] = ...,
                 leaf_outline: Optional[str] = ...) -> Tree: ...
    def add_trees(self, trees: Optional[Iterable[Mapping[str, Any]]] = ...,
                  **columns: Any) -> List[Tree]: ...
    def export_animation(self, trees: Iterable[Tree], path: Union[str, "os.PathLike[str]"], *,
                         frames: int = ..., frame_time: float = ..., steps_per_frame: int = ...,
                         max_level: int = ..., segments: int = ..., leaves: bool = ...,
                         meadows: Iterable[Meadow] = ..., mesh_trees: Iterable[MeshTree] = ...,
                         morph_tolerance: float = ..., meadow_clumps: int = ...,
                         clump_size: float = ..., warmup: float = ...) -> None: ...
    def add_meadow(self,
                   species: Union[Sequence[Union[str, Tuple[str, float]]], Mapping[str, float],
                                  None] = ...,
                   center: Optional[Vec3] = ..., size: Optional[Sequence[float]] = ..., *,
                   density: Optional[float] = ..., seed: Optional[int] = ...,
                   terrain: Optional[Any] = ..., terrain_relief: Optional[float] = ...,
                   nutrients: Optional[Any] = ..., seed_points: Optional[int] = ...,
                   shape_angles: Optional[int] = ..., shape_norms: Optional[int] = ...,
                   lod_distances: Optional[Vec3] = ...) -> Meadow: ...
    def add_meadows(self, meadows: Iterable[Mapping[str, Any]]) -> List[Meadow]: ...
    def add_collider(self, center: Optional[Vec3] = ..., radius: Optional[float] = ..., *,
                     shape: Optional[str] = ..., orientation: Optional[Sequence[float]] = ...,
                     half_height: Optional[float] = ..., half_extents: Optional[Vec3] = ...,
                     velocity: Optional[Vec3] = ...,
                     angular_velocity: Optional[Vec3] = ...,
                     origin: Optional[Vec3] = ...) -> Collider: ...
    def add_emitter(self, center: Vec3, *, area_radius: Optional[float] = ...,
                    event_radius: Optional[float] = ..., impulse: Optional[Vec3] = ...,
                    rate: Optional[float] = ..., lifetime: Optional[float] = ...,
                    seed: Optional[int] = ..., origin: Optional[Vec3] = ...) -> Emitter: ...
    def add_mesh_tree(self, model: PathLike, position: Optional[Vec3] = ..., *,
                      trunk_part: Optional[str] = ..., leaves_part: Optional[str] = ...,
                      yaw: Optional[float] = ..., scale: Optional[float] = ...,
                      seed: Optional[int] = ..., noise_beta: Optional[float] = ...,
                      bend_exponent: Optional[float] = ...,
                      levels: Optional[Sequence[Optional[Mapping[str, float]]]] = ...,
                      leaf_flutter: Optional[float] = ..., leaf_turn: Optional[float] = ...,
                      flutter_wavelength: Optional[float] = ...,
                      cache: Optional[bool] = ...) -> MeshTree: ...
    def add_blobtree(self, tree: Tree, *, resolution: Optional[int] = ...,
                     cubic: Optional[bool] = ..., max_level: Optional[int] = ...,
                     min_radius: Optional[float] = ..., junctions: Optional[str] = ...,
                     offsets: Optional[bool] = ..., ridge: Optional[float] = ...,
                     ridge_width: Optional[float] = ..., bend: Optional[float] = ...,
                     cuts: Optional[Sequence[Any]] = ..., scars: Optional[Sequence[Any]] = ...,
                     progress: Optional[ProgressCallback] = ...) -> BlobTree: ...
    def cast_rays(self, origins: Any, directions: Any, max_distance: Any = ...) -> np.ndarray: ...
    def add_lidar(self, preset: Optional[str] = ..., *, pose: Optional[Mapping[str, Any]] = ...,
                  channels: Optional[int] = ..., vertical_angles: Optional[Sequence[float]] = ...,
                  vertical_fov: Optional[Sequence[float]] = ...,
                  points_per_turn: Optional[int] = ..., rotation_rate: Optional[float] = ...,
                  min_range: Optional[float] = ..., max_range: Optional[float] = ...,
                  range_noise: Optional[float] = ..., dropout: Optional[float] = ...,
                  reflectivity: Optional[Sequence[float]] = ...,
                  seed: Optional[int] = ...) -> Lidar: ...
    def capture_depth(self, width: Optional[int] = ..., height: Optional[int] = ..., *,
                      fx: Optional[float] = ..., fy: Optional[float] = ...,
                      cx: Optional[float] = ..., cy: Optional[float] = ...,
                      max_depth: Optional[float] = ...,
                      pose: Optional[Mapping[str, Any]] = ...) -> Tuple[np.ndarray, np.ndarray]: ...
