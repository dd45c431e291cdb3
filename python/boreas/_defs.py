"""Plain data of boreas: the grid and the waves a world is made with, and what a world
reports (its device, step statistics, memory, mesh trees and BlobTrees).

The defaults of :class:`Grid` and :class:`Wave` are the C library's own
(``boreas_default_grid_def()``, ``boreas_default_wave()``).
"""
from __future__ import annotations

import copy
import dataclasses
from typing import Any, Dict, Mapping, Optional, Tuple

from . import _boreas

_DEFAULTS: Dict[str, Dict[str, Any]] = _boreas.defaults()


def defaults() -> Dict[str, Dict[str, Any]]:
    """The C library's default of every definition, by kind.

    Returns
    -------
    dict
        ``{"grid": {...}, "wave": {...}, "gust": {...}, "primitive": {...},
        "tree": {...}, "meadow": {...}, "collider": {...}, "emitter": {...},
        "mesh_tree": {...}, "blobtree": {...}}``: each the ``boreas_default_*()``
        struct as a dict under the C field names (enums as lowercase strings). A keyword
        argument left as None in this package takes the value listed here.
    """
    return copy.deepcopy(_DEFAULTS)


@dataclasses.dataclass
class Grid:
    """The force-field grid over the terrain (``boreas_grid_def``).

    Parameters
    ----------
    origin : tuple of 3 float
        m, the min corner of cell (0, 0, 0); each within +-``WORLD_MAX_COORDINATE``.
    cell_size : float
        m, 1e-3..1e4; cells are cubes.
    resolution : tuple of 3 int
        Cells along x, y and z, each 2..``GRID_MAX_RESOLUTION``, at most
        ``GRID_MAX_CELLS`` in all.
    diffusion : float
        m^2/s, 0..1e6: spreads the grid's wind to neighbouring cells.
    decay_rate : float
        1/s, 0..1e6: the grid's wind fades as exp(-decay_rate t).
    response_time : float
        s, 1e-4..1e6: how fast a flow primitive drives its cells to its velocity.
    edge_fade : float
        Cells, 0..1e6: beyond the grid's sides (x and z) its wind fades to zero over this
        distance, so it meets the sine sums outside without a seam.
    follow_focus : bool
        The grid moves with the first focus point (:meth:`World.set_focus`) in whole
        cells along x and z. Such a grid takes solids as boxes only.
    wind_sampling : str
        How the plants (trees, mesh trees, underbrush) read the sine sums at their points:
        ``"exact"`` evaluates them at every point; ``"interpolated"`` reads them bilinearly
        between the grid's column centers, where the grid step evaluates them anyway:
        cheaper per point, off by at most the bound given in ``boreas.h``
        (``boreas_wind_sampling``), exact beyond the outermost column centers.
        :meth:`Wind.sample` and the grid are exact either way. Another string is a
        ValueError (when the world is made).
    """

    origin: Tuple[float, float, float] = _DEFAULTS["grid"]["origin"]
    cell_size: float = _DEFAULTS["grid"]["cell_size"]
    resolution: Tuple[int, int, int] = _DEFAULTS["grid"]["resolution"]
    diffusion: float = _DEFAULTS["grid"]["diffusion"]
    decay_rate: float = _DEFAULTS["grid"]["decay_rate"]
    response_time: float = _DEFAULTS["grid"]["response_time"]
    edge_fade: float = _DEFAULTS["grid"]["edge_fade"]
    follow_focus: bool = bool(_DEFAULTS["grid"]["follow_focus"])
    wind_sampling: str = _DEFAULTS["grid"]["wind_sampling"]  # "exact" | "interpolated"

    @classmethod
    def _from_c(cls, fields: Mapping[str, Any]) -> "Grid":
        values = dict(fields)
        values["follow_focus"] = bool(values["follow_focus"])
        return cls(**values)


@dataclasses.dataclass
class Wave:
    """One sine-sum wave of the analytic wind (``boreas_wave``, Skjermo 2007 eq. 14).

    The wave pushes along +direction with a strength between 0 and `amplitude`:
    ``direction * amplitude * ((sin(w dot(direction, (x, z)) - speed w t) + 1) / 2) **
    sharpness`` with ``w = 2 pi / wavelength``.

    Parameters
    ----------
    direction : tuple of 2 float
        (x, z) on the ground; normalized by the library; not zero.
    amplitude : float
        m/s, >= 0.
    wavelength : float
        m, > 0.
    speed : float
        m/s: crests travel along +direction at this speed (negative: against it).
    sharpness : float
        >= 0: peaks sharpen as it grows; 0 gives a steady wind of `amplitude`.
    """

    direction: Tuple[float, float] = _DEFAULTS["wave"]["direction"]
    amplitude: float = _DEFAULTS["wave"]["amplitude"]
    wavelength: float = _DEFAULTS["wave"]["wavelength"]
    speed: float = _DEFAULTS["wave"]["speed"]
    sharpness: float = _DEFAULTS["wave"]["sharpness"]


@dataclasses.dataclass(frozen=True)
class DeviceInfo:
    """An OpenCL device (``boreas_device_info``).

    Attributes
    ----------
    name, platform : str
        The device's and its platform's names.
    version, driver_version : str
        The device's OpenCL version string and its driver's version.
    is_gpu : bool
        True for GPUs, False for CPUs and accelerators.
    compute_units : int
    global_memory : int
        Bytes.
    has_gl_sharing, has_fp64 : bool
        ``cl_khr_gl_sharing``, ``cl_khr_fp64``.
    uses_fast_math : bool
        True where boreas uses its polynomial math (CPU devices).
    platform_index, device_index : int
        Where it is in the platform list; :attr:`request` names it for ``World(device=)``.
    """

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
    def request(self) -> str:
        """str: ``"P:D"``, the request that picks this device (``World(device=...)``)."""
        return f"{self.platform_index}:{self.device_index}"


@dataclasses.dataclass(frozen=True)
class StepStats:
    """Where the last :meth:`World.step` spent its time (``boreas_step_stats``).

    Attributes
    ----------
    wind, trees, underbrush : float
        s, measured on the device: the wind (sine sums and grid), the trees (branches and
        leaves), every meadow's components.
    total : float
        s, wall clock of the whole call, host work included.
    trees_by_lod : tuple of 4 int
        Trees at full, reduced, far and frozen detail.
    branches_stepped, branches_carried : int
        Branches bent by the wind, and branches carried rigidly by their parents.
    branches_broken : int
        Branches the wind broke in this step (they hang from their parents until
        :meth:`Tree.heal`).
    components_by_rate : tuple of 4 int
        Underbrush components stepped every step, every 4th, every 16th, and not at all.
    """

    wind: float
    trees: float
    underbrush: float
    total: float
    trees_by_lod: Tuple[int, int, int, int]
    branches_stepped: int
    branches_carried: int
    branches_broken: int
    components_by_rate: Tuple[int, int, int, int]


@dataclasses.dataclass(frozen=True)
class MemoryInfo:
    """What a world holds on its device (``boreas_memory_info``).

    Attributes
    ----------
    device_bytes : int
        Bytes in the world's device buffers (they follow the population with
        hysteresis: grown past three quarters full, packed and halved below a quarter).
    device_limit : int
        Bytes they may take; past it an add raises :class:`OutOfMemoryError`.
    kernel_variants : int
        Kernel programs built and kept.
    """

    device_bytes: int
    device_limit: int
    kernel_variants: int


@dataclasses.dataclass(frozen=True)
class MeshTreeInfo:
    """What preprocessing found in an imported tree mesh (``boreas_mesh_tree_info``).

    Attributes
    ----------
    trunk_vertices, trunk_triangles, leaf_vertices, leaf_triangles : int
    branches : int
        Connected runs of trunk triangles.
    leaves : int
        Connected runs of leaf triangles.
    levels : int
        Levels found (may exceed 4: deeper branches move with their parent).
    orphans : int
        Branches that touched no thicker branch (hung on the nearest one).
    from_cache : bool
        True when the preprocessing was read from ``<model>.boreas.glb``.
    """

    trunk_vertices: int
    trunk_triangles: int
    leaf_vertices: int
    leaf_triangles: int
    branches: int
    leaves: int
    levels: int
    orphans: int
    from_cache: bool


@dataclasses.dataclass(frozen=True)
class ColliderContact:
    """What the plants did to a collider over the last step (``boreas_collider_contact``).

    Attributes
    ----------
    force : tuple of 3 float
        N, world frame: the sum of what the bent branches and pressed components it touched
        push it with.
    torque : tuple of 3 float
        N m: those pushes' moment about the collider's position at the end of the step.
    contacts : int
        Plant parts (tree and mesh-tree branches, underbrush components) that touched it.
    """

    force: Tuple[float, float, float]
    torque: Tuple[float, float, float]
    contacts: int


@dataclasses.dataclass(frozen=True)
class BlobTreeInfo:
    """A polygonized BlobTree (``boreas_blobtree_info``).

    Attributes
    ----------
    vertices, triangles : int
    primitives : int
        Skeletal primitives in the BlobTree.
    branches : int
        Tree branches modeled (the rest were thinner than `min_radius`).
    grid : tuple of 3 int
        Grid points along x, y, z.
    cell : float
        m, the grid spacing.
    min_radius : float
        m, the one used.
    bounds_min, bounds_max : tuple of 3 float
        m, the mesh's box.
    """

    vertices: int
    triangles: int
    primitives: int
    branches: int
    grid: Tuple[int, int, int]
    cell: float
    min_radius: float
    bounds_min: Tuple[float, float, float]
    bounds_max: Tuple[float, float, float]


def as_fields(value: Any, cls: Optional[type], what: str) -> Optional[Dict[str, Any]]:
    """A definition given as a dataclass of `cls`, a mapping or None, as a dict of fields."""
    if value is None:
        return None
    if cls is not None and isinstance(value, cls):
        return dataclasses.asdict(value)
    if isinstance(value, Mapping):
        return dict(value)
    expected = f"a boreas.{cls.__name__} or a mapping" if cls else "a mapping"
    raise TypeError(f"{what} must be {expected}, not {type(value).__name__}")


def given(**fields: Any) -> Dict[str, Any]:
    """The fields that are not None (None: the library's default)."""
    return {key: value for key, value in fields.items() if value is not None}
