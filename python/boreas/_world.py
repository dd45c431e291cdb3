"""The world: one simulation of wind and vegetation on one OpenCL device, and everything
added to it."""
from __future__ import annotations

import os
from collections.abc import Mapping
from typing import Any, Dict, Iterable, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _boreas
from ._defs import (DeviceInfo, Grid, MemoryInfo, MeshTreeInfo, StepStats, Wave, as_fields,
                    given)
from ._handles import (BlobTree, Collider, Emitter, Meadow, MeshTree, ProgressCallback,
                       Tree)
from ._sensors import Lidar, pose_fields, rays_as_arrays
from ._wind import Wind, waves_as_fields

PathLike = Union[str, "os.PathLike[str]"]

# add_trees' columns: how many dimensions one tree's value has (None: a string field;
# "levels": a sequence of mappings).
_TREE_FIELD_NDIM: Dict[str, Any] = {
    "species": None, "position": 1, "rotation": 0, "scale": 0, "seed": 0, "mode": None,
    "response": None, "load": None, "bend_exponent": 0, "levels": "levels",
    "lod_distances": 1, "leaf_outline": None,
}


def _per_tree(key: str, value: Any) -> Optional[int]:
    """The number of trees a column gives values for, or None when it is one shared value."""
    kind = _TREE_FIELD_NDIM.get(key)
    if key not in _TREE_FIELD_NDIM:
        raise TypeError(f"add_trees() got an unexpected keyword argument '{key}'")
    if kind is None:
        return None if isinstance(value, str) else len(value)
    if kind == "levels":
        first = next(iter(value), None)
        return None if first is None or isinstance(first, Mapping) else len(value)
    ndim = np.ndim(value)
    if ndim == kind:
        return None
    if ndim == kind + 1:
        return len(value)
    raise ValueError(f"add_trees(): {key} must hold one value per tree or one for all")


def _columns_to_defs(columns: Dict[str, Any]) -> List[Dict[str, Any]]:
    counts = {key: _per_tree(key, value) for key, value in columns.items() if value is not None}
    lengths = {n for n in counts.values() if n is not None}
    if not lengths:
        raise ValueError("add_trees() needs one column with a value per tree, e.g. "
                         "position=[(x, y, z), ...]")
    if len(lengths) > 1:
        raise ValueError("add_trees(): the per-tree columns differ in length: "
                         + ", ".join(f"{k}: {n}" for k, n in counts.items() if n is not None))
    n = lengths.pop()
    return [{key: (columns[key][i] if per is not None else columns[key])
             for key, per in counts.items()} for i in range(n)]


class World:
    """A world of wind and vegetation on one OpenCL device (``boreas_world``).

    Use it as a context manager, or call :meth:`close`; afterwards every call on it or on
    its handles raises :class:`Error`.

    Parameters
    ----------
    device : str or DeviceInfo, optional
        None: the best device (a GPU over a CPU; ``BOREAS_DEVICE`` in the environment is
        honoured). ``"gpu"``, ``"cpu"``, ``"P:D"`` (platform and device index), part of a
        device or platform name, or an entry of :func:`devices`.
    grid : Grid or dict, optional
        The force-field grid over the terrain; None: ``Grid()``. A dict gives some of its
        fields (the rest default).
    waves : sequence of Wave or dict, optional
        The initial sine-sum waves; None: calm.
    cache_dir : str or os.PathLike, optional
        Where compiled kernels are cached. None: ``BOREAS_CACHE_DIR``, else
        ``$XDG_CACHE_HOME/boreas`` or ``~/.cache/boreas``; ``""`` turns the cache off.

    Raises
    ------
    NoDeviceError
        No OpenCL device matches `device`.
    InvalidArgumentError
        A field of `grid` or of a wave is out of range.

    Examples
    --------
    >>> with boreas.World(grid=boreas.Grid(resolution=(8, 4, 8), cell_size=1.0),
    ...                   waves=[boreas.Wave(direction=(1, 0), amplitude=5.0)]) as world:
    ...     tree = world.add_tree("weeping_willow", position=(2, 0, 3))
    ...     world.step(1 / 30)
    ...     wind = world.wind.sample([[0.0, 1.0, 0.0]])

    Notes
    -----
    Calls on one world take turns (a lock), with the GIL released while the library runs:
    other Python threads run during long steps, samples and adds, and threads may share a
    world. For work in parallel, give each thread its own world.
    """

    def __init__(
        self,
        device: Union[str, DeviceInfo, None] = None,
        grid: Union[Grid, Dict[str, Any], None] = None,
        waves: Optional[Iterable[Union[Wave, Dict[str, Any]]]] = None,
        cache_dir: Optional[PathLike] = None,
    ) -> None:
        if isinstance(device, DeviceInfo):
            device = device.request
        self._core = _boreas.World(
            device=device,
            cache_dir=None if cache_dir is None else os.fspath(cache_dir),
            grid=as_fields(grid, Grid, "grid"),
            waves=waves_as_fields(waves))

    # -- lifetime -------------------------------------------------------------------------

    def close(self) -> None:
        """Destroys the world and frees its device memory (``boreas_world_destroy``).

        Closing twice is fine. Later calls on the world or its handles raise
        :class:`Error`.
        """
        self._core.close()

    @property
    def closed(self) -> bool:
        """bool: True once :meth:`close` was called."""
        return self._core.closed

    def __enter__(self) -> "World":
        return self

    def __exit__(self, *exc_info: Any) -> None:
        self.close()

    def __repr__(self) -> str:
        if self.closed:
            return "<boreas.World (closed)>"
        return f"<boreas.World t={self.time:.6g} s on {self.device.name!r}>"

    # -- stepping and state ---------------------------------------------------------------

    def step(self, dt: float) -> None:
        """Advances the world by `dt` seconds (``boreas_world_step``): the wind and its
        grid, the trees, the underbrush.

        Runs with the GIL released. Stable for every accepted `dt`.

        Parameters
        ----------
        dt : float
            s, 0 < dt <= ``STEP_MAX_SECONDS``.

        Raises
        ------
        InvalidArgumentError
            `dt` is out of range or not finite (the world is left as it was).
        """
        self._core.step(dt)

    @property
    def time(self) -> float:
        """float: s, simulated time since the world was created."""
        return self._core.time()

    @property
    def device(self) -> DeviceInfo:
        """DeviceInfo: the device the world runs on."""
        return DeviceInfo(**self._core.device())

    @property
    def step_stats(self) -> StepStats:
        """StepStats: where the last :meth:`step` spent its time (all zero before the
        first step)."""
        return StepStats(**self._core.step_stats())

    @property
    def memory(self) -> MemoryInfo:
        """MemoryInfo: the device memory the world holds and may hold."""
        return MemoryInfo(**self._core.memory())

    def state_hash(self) -> int:
        """Everything the world simulates as one 64-bit number (``boreas_world_get_state_hash``).

        The same world built and stepped with the same inputs on the same device has the
        same hash after every step. It reads the whole state back from the device: for
        tests and debugging, not for every frame.

        Returns
        -------
        int
            0 .. 2**64 - 1.
        """
        return self._core.state_hash()

    @property
    def wind(self) -> Wind:
        """Wind: the world's wind (sampling, waves, gusts, primitives, solids, grid)."""
        return Wind(self)

    def set_focus(self, points: Any) -> None:
        """Sets the focus points of the level of detail (``boreas_world_set_focus``).

        Cameras, players, sensors: each tree takes its detail from its distance to the
        nearest (its ``lod_distances``), each meadow its step rate; a grid that follows
        the focus moves with the first.

        Parameters
        ----------
        points : array_like, shape (N, 3) or (3,)
            m; empty or None steps everything at full detail.
        """
        if points is None:
            points = np.zeros((0, 3), np.float32)
        points = np.asarray(points, dtype=np.float32)
        if points.ndim == 1 and points.shape[0] == 3:
            points = points.reshape(1, 3)
        elif points.size == 0:
            points = points.reshape(0, 3)
        self._core.set_focus(points)

    def set_output_origin(self, origin: Optional[Sequence[float]]) -> None:
        """Sets where handed-back positions count from (``boreas_world_set_output_origin``).

        Trees' branches, leaves and meshes, meadows' components and strips and imported
        trees' vertices come back relative to ``origin`` (float32 there, so as precise
        near it as near 0): a renderer far from 0 sets it to its camera's position (or a
        floating origin it moves now and then). The state is kept relative to each
        plant's own origin, so this changes only the outputs. Rays (:meth:`cast_rays`)
        are given and their hits and LiDAR points come back relative to it too; moving
        it rebuilds the ray structure at the next cast.

        Parameters
        ----------
        origin : sequence of 3 floats, or None
            m, kept in double; within ``BOREAS_WORLD_MAX_COORDINATE`` of 0 and finite
            (``BoreasError`` naming the coordinate otherwise). None: world coordinates.
        """
        if origin is None:
            self._core.set_output_origin(None)
            return
        values = [float(v) for v in origin]
        if len(values) != 3:
            raise ValueError(f"origin: expected 3 coordinates, got {len(values)}")
        self._core.set_output_origin(values)

    # -- trees ----------------------------------------------------------------------------

    def add_tree(
        self,
        species: Optional[PathLike] = None,
        position: Optional[Sequence[float]] = None,
        *,
        rotation: Optional[float] = None,
        scale: Optional[float] = None,
        seed: Optional[int] = None,
        mode: Optional[str] = None,
        response: Optional[str] = None,
        load: Optional[str] = None,
        bend_exponent: Optional[float] = None,
        levels: Optional[Sequence[Optional[Dict[str, Any]]]] = None,
        lod_distances: Optional[Sequence[float]] = None,
        leaf_outline: Optional[str] = None,
    ) -> Tree:
        """Grows a Weber-Penn tree and places it, unbent, in the world
        (``boreas_world_add_tree``). Runs with the GIL released.

        The arguments are the fields of ``boreas_tree_def``; None leaves the library's
        default (``boreas.defaults()["tree"]``).

        Parameters
        ----------
        species : str or os.PathLike, optional
            A built-in name (:func:`builtin_species`; default ``"quaking_aspen"``) or a
            path to an Arbaro species ``.xml`` or a boreas species ``.json``.
        position : sequence of 3 float, optional
            m, the trunk's base.
        rotation : float, optional
            rad, abs <= 1e4: about the up axis through the base, counter-clockwise seen
            from above.
        scale : float, optional
            (0, 1000]: multiplies every length of the species.
        seed : int, optional
            0 .. 2**64 - 1: the same seed grows the same tree (trees of one species and
            seed share one grown model).
        mode : {"lagged", "exact"}, optional
            ``"lagged"`` (the paper): one launch per step, each level a step behind its
            parent; ``"exact"``: level by level, children on their parents' current curves.
        response : {"quasi_static", "damped"}, optional
            ``"quasi_static"``: the bend follows the wind at once; ``"damped"``: as a damped
            oscillator at each branch's natural frequency.
        load : {"drag", "linear"}, optional
            ``"drag"``: aerodynamic drag on a cantilever; ``"linear"``: the paper's bend
            proportional to the wind.
        bend_exponent : float, optional
            gamma of ``b_i = F (i/3)**gamma``, 0.1..10.
        levels : sequence of up to 4 dicts, optional
            Per branching level (0 trunk .. 3), the fields of ``boreas_tree_level_def``
            to change: ``stiffness`` (> 0), ``damping_ratio`` (0.01..10),
            ``frequency_scale`` (0.01..100), ``rings`` (1..256), ``sides`` (3..256). None
            entries keep a level's defaults.
        lod_distances : sequence of 3 float, optional
            m from the nearest focus point where the tree drops detail (not decreasing).
        leaf_outline : {"species", "broadleaf", "aspen", "oak", "willow", "tupelo"}, optional
            The outline of the tree's leaves, which rays must cross to hit one;
            ``"species"`` (default): the kind named after a built-in species, broadleaf for
            any other.

        Returns
        -------
        Tree

        Raises
        ------
        FileError
            The species file cannot be read or is malformed (the message names the file,
            line and parameter); an unknown species name is looked up as a path.
        InvalidArgumentError
            A field is out of range.
        """
        fields = given(species=None if species is None else os.fspath(species),
                       position=position, rotation=rotation, scale=scale, seed=seed,
                       mode=mode, response=response, load=load, bend_exponent=bend_exponent,
                       levels=levels, lod_distances=lod_distances, leaf_outline=leaf_outline)
        return Tree(self, self._core.add_tree(fields))

    def export_animation(self, trees: Iterable["Tree"], path: "os.PathLike[str] | str", *,
                         frames: int = 48, frame_time: float = 1.0 / 24.0, steps_per_frame: int = 1,
                         max_level: int = 1, segments: int = 2, leaves: bool = True,
                         meadows: Iterable["Meadow"] = (), mesh_trees: Iterable["MeshTree"] = (),
                         morph_tolerance: float = 1e-3, meadow_clumps: int = 0,
                         clump_size: float = 1.0, warmup: float = 0.0) -> None:
        """Steps the world (frames - 1) * steps_per_frame times and writes `trees` as an
        animated glTF binary at `path` (``boreas_world_export_animation``): each tree a
        skinned mesh (:meth:`Tree.skin` with `max_level` and `segments`), trees of one
        species and seed sharing one mesh, leaves as quads, a key per frame every
        `frame_time` seconds. Call it while the trees are at rest (just added or healed):
        that pose is the bind pose. `meadows` and `mesh_trees` are written as morph targets
        weighted per key, every vertex within `morph_tolerance` m of boreas's at every key
        (frames then at most 256); with `meadow_clumps` > 0, each meadow as that many looped
        clumps (cells of about `clump_size` m) instanced over it (README, "Animated glTF").
        `warmup` seconds are stepped after the bind pose is taken and before the first key,
        so the keys start in the wind's sway rather than in the first bend from rest."""
        self._core.export_animation([t._id for t in trees], os.fspath(path), frames, frame_time,
                                    steps_per_frame, max_level, segments, leaves,
                                    [m._id for m in meadows], [m._id for m in mesh_trees],
                                    morph_tolerance, meadow_clumps, clump_size, warmup)

    def add_trees(self, trees: Optional[Iterable[Dict[str, Any]]] = None,
                  **columns: Any) -> List[Tree]:
        """Adds many trees in one call (``boreas_world_add_trees``): every definition is
        checked and every (species, seed) grown once before anything changes; all or
        nothing. Runs with the GIL released.

        Give either `trees`, a sequence of dicts of :meth:`add_tree`'s arguments, or
        columns: keyword arguments of :meth:`add_tree` whose values are either one value
        per tree or one value for all (``position=[(0, 0, 0), (5, 0, 0)],
        species="black_tupelo"``).

        Returns
        -------
        list of Tree
            In the order given.

        Raises
        ------
        InvalidArgumentError, FileError
            A definition is wrong (the message names it); no tree is added.
        """
        if trees is not None and columns:
            raise TypeError("add_trees() takes a list of definitions or columns, not both")
        defs = list(trees) if trees is not None else _columns_to_defs(columns)
        for i, d in enumerate(defs):
            if not isinstance(d, Mapping):
                raise TypeError(f"trees[{i}] must be a mapping, not {type(d).__name__}")
        defs = [dict(d) for d in defs]
        for d in defs:
            if d.get("species") is not None:
                d["species"] = os.fspath(d["species"])
        return [Tree(self, i) for i in self._core.add_trees(defs)]

    # -- underbrush -----------------------------------------------------------------------

    def add_meadow(
        self,
        species: Union[Sequence[Union[str, Tuple[str, float]]], Dict[str, float], None] = None,
        center: Optional[Sequence[float]] = None,
        size: Optional[Sequence[float]] = None,
        *,
        density: Optional[float] = None,
        seed: Optional[int] = None,
        terrain: Optional[Any] = None,
        terrain_relief: Optional[float] = None,
        nutrients: Optional[Any] = None,
        seed_points: Optional[int] = None,
        shape_angles: Optional[int] = None,
        shape_norms: Optional[int] = None,
        lod_distances: Optional[Sequence[float]] = None,
    ) -> Meadow:
        """Plants a meadow of underbrush (``boreas_world_add_meadow``; about a second per
        million components). Components start at rest. Runs with the GIL released.

        None leaves the library's default (``boreas.defaults()["meadow"]``). Without
        ``terrain`` and ``nutrients`` the ground is procedural (rolling, with procedural
        nutrients).

        Parameters
        ----------
        species : sequence or dict, optional
            The species and their shares: names (:func:`builtin_underbrush_species` or paths to
            species ``.json``), ``(name, weight)`` pairs, or ``{name: weight}``; weights
            > 0. None: the default mix (grass, clover, daisies).
        center : sequence of 3 float, optional
            m, the middle of the meadow's rectangle on the ground.
        size : sequence of 2 float, optional
            m, its extent along x and z, each 0.01..1e5.
        density : float, optional
            Components per square meter, 0..``MEADOW_MAX_DENSITY``, where the ground allows;
            ``size[0] * size[1] * density`` at most ``MEADOW_MAX_COMPONENTS``.
        seed : int, optional
            The same seed plants the same meadow.
        terrain : array_like, shape (H, W) or (H, W, C), optional
            A height map stretched over the rectangle (row 0 on its -z side, column 0 on
            its -x side, bilinear between): the ground's y is ``center[1] +
            terrain_relief * terrain[..., 0]``. Image values 0..1 with a relief in m, or
            heights in m with ``terrain_relief=1``. Copied (as float32) during the call.
        terrain_relief : float, optional
            m, 0..1e4: height range of the ground (0: flat).
        nutrients : array_like, shape (H, W) or (H, W, C), optional
            Nutrient maps laid out as ``terrain``: the first three channels are the
            nutrients the species need, clamped to 0..1. Copied during the call.
        seed_points : int, optional
            Propagation starts per species, 1..``MEADOW_MAX_SEED_POINTS``.
        shape_angles, shape_norms : int, optional
            Precomputed rest shapes: load angles per part (3..181) and load norms per angle
            (3..256).
        lod_distances : sequence of 3 float, optional
            m from the camera (or the nearest focus point) where strips and steps get
            coarser.

        Returns
        -------
        Meadow
        """
        fields = given(species=species, center=center, size=size, density=density, seed=seed,
                       terrain=terrain, terrain_relief=terrain_relief, nutrients=nutrients,
                       seed_points=seed_points,
                       shape_angles=shape_angles, shape_norms=shape_norms,
                       lod_distances=lod_distances)
        return Meadow(self, self._core.add_meadow(fields))

    def add_meadows(self, meadows: Iterable[Dict[str, Any]]) -> List[Meadow]:
        """Plants several meadows in one call (``boreas_world_add_meadows``); all or
        nothing.

        Parameters
        ----------
        meadows : sequence of dict
            Each the keyword arguments of :meth:`add_meadow`.

        Returns
        -------
        list of Meadow
        """
        return [Meadow(self, i) for i in self._core.add_meadows(list(meadows))]

    def add_collider(
        self,
        center: Optional[Sequence[float]] = None,
        radius: Optional[float] = None,
        *,
        shape: Optional[str] = None,
        orientation: Optional[Sequence[float]] = None,
        half_height: Optional[float] = None,
        half_extents: Optional[Sequence[float]] = None,
        velocity: Optional[Sequence[float]] = None,
        angular_velocity: Optional[Sequence[float]] = None,
        origin: Optional[Sequence[float]] = None,
    ) -> Collider:
        """Adds a kinematic collider that pushes plants aside and feels them push back
        (``boreas_world_add_collider``). None leaves a field at the library's default
        (:func:`defaults` ``["collider"]``: a 0.11 m sphere resting at the origin).

        Parameters
        ----------
        center : sequence of 3 float, optional
            m, its position.
        radius : float, optional
            m, 1e-3..1e3: the sphere's or the capsule's.
        shape : {"sphere", "capsule", "box"}, optional
            A capsule runs along its local Y axis; a box has half extents along its axes.
        orientation : sequence of 4 float, optional
            Unit quaternion x, y, z, w.
        half_height : float, optional
            m, 0..1e3: the capsule's segment's half length.
        half_extents : sequence of 3 float, optional
            m, each 1e-3..1e3: the box's.
        velocity : sequence of 3 float, optional
            m/s, world frame, each within +-``COLLIDER_MAX_SPEED``: the world moves it on
            by this each step.
        angular_velocity : sequence of 3 float, optional
            rad/s, world frame, about its position, each within +-``COLLIDER_MAX_SPIN``.
        origin : sequence of 3 float, optional
            m, world, kept in double: what center counts from (default 0, 0, 0); far from 0
            an origin near the collider and a small center place it exactly.

        Returns
        -------
        Collider
        """
        fields = {k: v for k, v in {
            "center": center, "radius": radius, "shape": shape, "orientation": orientation,
            "half_height": half_height, "half_extents": half_extents, "velocity": velocity,
            "angular_velocity": angular_velocity, "origin": origin}.items() if v is not None}
        return Collider(self, self._core.add_collider(fields))

    def add_emitter(
        self,
        center: Sequence[float],
        *,
        area_radius: Optional[float] = None,
        event_radius: Optional[float] = None,
        impulse: Optional[Sequence[float]] = None,
        rate: Optional[float] = None,
        lifetime: Optional[float] = None,
        seed: Optional[int] = None,
        origin: Optional[Sequence[float]] = None,
    ) -> Emitter:
        """Adds an impulse emitter (rain drops, footsteps) that pushes underbrush
        (``boreas_world_add_emitter``).

        Each event gives components within `event_radius` of it a velocity change of
        impulse / mass, fading linearly with distance. None leaves the library's default
        (``boreas.defaults()["emitter"]``).

        Parameters
        ----------
        center : sequence of 3 float
            m.
        area_radius : float, optional
            m, >= 0: events fall uniformly in this horizontal disk around `center`.
        event_radius : float, optional
            m, > 0.
        impulse : sequence of 3 float, optional
            N s per event (a rain drop: about (0, -2e-4, 0)).
        rate : float, optional
            Events per second, >= 0; 0: one event at the next step.
        lifetime : float, optional
            s, >= 0: removed after this; 0: until removed.
        seed : int, optional
        origin : sequence of 3 float, optional
            m, kept in double: what `center` counts from (default 0); far from 0, an
            origin near the emitter and a small center place it exactly.

        Returns
        -------
        Emitter
        """
        center = tuple(float(x) for x in center)
        fields = given(center=center, area_radius=area_radius, event_radius=event_radius,
                       impulse=impulse, rate=rate, lifetime=lifetime, seed=seed, origin=origin)
        return Emitter(self, self._core.add_emitter(fields), center)

    # -- trees made elsewhere -------------------------------------------------------------

    def add_mesh_tree(
        self,
        model: PathLike,
        position: Optional[Sequence[float]] = None,
        *,
        trunk_part: Optional[str] = None,
        leaves_part: Optional[str] = None,
        yaw: Optional[float] = None,
        scale: Optional[float] = None,
        seed: Optional[int] = None,
        noise_beta: Optional[float] = None,
        bend_exponent: Optional[float] = None,
        levels: Optional[Sequence[Optional[Dict[str, float]]]] = None,
        leaf_flutter: Optional[float] = None,
        leaf_turn: Optional[float] = None,
        flutter_wavelength: Optional[float] = None,
        cache: Optional[bool] = None,
    ) -> MeshTree:
        """Loads an imported tree mesh (OBJ or glTF, no bones needed) and places it, at rest
        until the next step (``boreas_world_add_mesh_tree``, Kusternig 2007). Runs with the
        GIL released.

        None leaves the library's default (``boreas.defaults()["mesh_tree"]``).

        Parameters
        ----------
        model : str or os.PathLike
            ``.obj``, ``.gltf`` or ``.glb`` (a ``.glb`` written by
            :func:`preprocess_mesh_tree` loads without preprocessing).
        position : sequence of 3 float, optional
            m, where the model's origin goes.
        trunk_part, leaves_part : str, optional
            The parts' objects, groups or materials: comma-separated names matched
            case-insensitively as substrings.
        yaw : float, optional
            rad, about +Y.
        scale : float, optional
            > 0, multiplies the model's lengths.
        seed : int, optional
            Branch phases and the noise.
        noise_beta : float, optional
            0..4: each branch's sway has a spectrum falling as 1/f**beta.
        bend_exponent : float, optional
            0.25..4: weights are raised to it.
        levels : sequence of up to 4 dicts, optional
            Per level (0 stem .. 3) the fields of ``boreas_mesh_level_def`` to change:
            ``bend`` and ``sway`` (m, >= 0, in 10 m/s of wind), ``frequency`` (Hz,
            0.001..50), ``response_time`` (s, 0..60).
        leaf_flutter : float, optional
            m, >= 0: a leaf tip's flutter in 10 m/s.
        leaf_turn : float, optional
            0..1: how far leaves turn into a strong wind.
        flutter_wavelength : float, optional
            m, > 0: size of the rolling noise's tile.
        cache : bool, optional
            Keep the preprocessing in ``<model>.boreas.glb`` beside the model and reuse it.

        Returns
        -------
        MeshTree

        Raises
        ------
        FileError
            The model cannot be read or is malformed (the message names the file).
        """
        fields = given(model=os.fspath(model), position=position, trunk_part=trunk_part,
                       leaves_part=leaves_part, yaw=yaw, scale=scale, seed=seed,
                       noise_beta=noise_beta, bend_exponent=bend_exponent, levels=levels,
                       leaf_flutter=leaf_flutter, leaf_turn=leaf_turn,
                       flutter_wavelength=flutter_wavelength,
                       cache=None if cache is None else int(bool(cache)))
        return MeshTree(self, self._core.add_mesh_tree(fields))

    def add_blobtree(
        self,
        tree: Tree,
        *,
        resolution: Optional[int] = None,
        cubic: Optional[bool] = None,
        max_level: Optional[int] = None,
        min_radius: Optional[float] = None,
        junctions: Optional[str] = None,
        offsets: Optional[bool] = None,
        ridge: Optional[float] = None,
        ridge_width: Optional[float] = None,
        bend: Optional[float] = None,
        cuts: Optional[Sequence[Any]] = None,
        scars: Optional[Sequence[Any]] = None,
        progress: Optional[ProgressCallback] = None,
    ) -> BlobTree:
        """Builds the BlobTree of a tree of this world (its rest pose) and polygonizes it on
        the device (``boreas_world_add_blobtree``, Galbraith et al. 2004). Runs with the
        GIL released, but for `progress`.

        None leaves the library's default (``boreas.defaults()["blobtree"]``).

        Parameters
        ----------
        tree : Tree
            A tree of this world.
        resolution : int, optional
            Grid points along the tree's longest side, 16..1024 (each doubling costs ~8x).
        cubic : bool, optional
            ``resolution**3`` points, a cube around the tree (for benchmarks).
        max_level : int, optional
            Deepest branch level modeled, 0..3.
        min_radius : float, optional
            m: thinner branches are left out; 0: half a grid cell.
        junctions : {"pcm", "blend"}, optional
            ``"pcm"``: Precise Contact Modeling between branches (bark ridges, collars);
            ``"blend"``: every internode summed.
        offsets : bool, optional
            Shorten and displace internodes at junctions against bulging.
        ridge : float, optional
            0..0.45 field units: the height of the bark ridges.
        ridge_width : float, optional
            0.01..10: PCM's propagation width per branch surface distance.
        bend : float, optional
            rad, 0..pi/2: lateral branches' first internodes bend away and back.
        cuts : sequence, optional
            Pruning cuts: ``(branch, at)`` tuples or dicts; `branch` indexes
            :attr:`Tree.branches` (0 is the trunk), `at` is 0.01..1 along it.
        scars : sequence, optional
            ``(branch, stub, depth)`` tuples or dicts: a lost branch's stub (0.01..1 of its
            length) in a hollow of `depth` (0..1).
        progress : callable, optional
            ``progress(fraction, stage)``, called on this thread between device stages with
            fraction in 0..1 and a stage name. It must not call into this world. If it
            raises, the BlobTree is not added and the exception propagates.

        Returns
        -------
        BlobTree
        """
        if not isinstance(tree, Tree):
            raise TypeError(f"tree must be a boreas.Tree, not {type(tree).__name__}")
        fields = given(resolution=resolution, cubic=None if cubic is None else int(bool(cubic)),
                       max_level=max_level, min_radius=min_radius, junctions=junctions,
                       offsets=None if offsets is None else int(bool(offsets)), ridge=ridge,
                       ridge_width=ridge_width, bend=bend, cuts=cuts, scars=scars)
        return BlobTree(self, self._core.add_blobtree(tree.id, fields, progress))

    def cast_rays(self, origins: Any, directions: Any, max_distance: Any = np.inf) -> np.ndarray:
        """The nearest surface along each ray as of the last step
        (``boreas_world_cast_rays``).

        Parameters
        ----------
        origins : array-like, shape (N, 3) or (3,)
            m, relative to the world's output origin (:meth:`set_output_origin`; world
            coordinates by default); one origin for every ray may be given as 3 numbers.
        directions : array-like, shape (N, 3)
            Not zero; normalized by the library.
        max_distance : float or array-like of N floats, optional
            m, >= 0 (default infinity).

        Returns
        -------
        numpy.ndarray
            N hits of :data:`HIT_DTYPE`: distance (m; inf on a miss), point (relative to
            the output origin), normal (facing
            the ray), kind (0 none, 1 branch, 2 leaf, 3 mesh trunk, 4 mesh leaf, 5
            underbrush, 6 BlobTree, 7 ground, 8 solid box), object (index, generation, tag)
            and part.
        """
        return self._core.cast_rays(*rays_as_arrays(origins, directions, max_distance))

    def add_lidar(
        self,
        preset: Optional[str] = None,
        *,
        pose: Optional[Mapping] = None,
        channels: Optional[int] = None,
        vertical_angles: Optional[Sequence[float]] = None,
        vertical_fov: Optional[Sequence[float]] = None,
        points_per_turn: Optional[int] = None,
        rotation_rate: Optional[float] = None,
        min_range: Optional[float] = None,
        max_range: Optional[float] = None,
        range_noise: Optional[float] = None,
        dropout: Optional[float] = None,
        reflectivity: Optional[Sequence[float]] = None,
        seed: Optional[int] = None,
    ) -> Lidar:
        """Adds a spinning LiDAR (``boreas_world_add_lidar``); its first sweep begins now.

        None leaves the preset's value, or the library's default
        (``boreas.defaults()["lidar"]``, a 16-channel unit).

        Parameters
        ----------
        preset : str, optional
            One of :func:`lidar_presets` ("VLP-16", "HDL-32E", "HDL-64E", "OS1-128"). Its
            vertical angles are kept unless `channels` or `vertical_fov` is given (then
            the channels spread over that span).
        pose : mapping, optional
            ``{"position": (x, y, z), "orientation": (x, y, z, w)}``: the mounting pose.
        channels : int, optional
            1..LIDAR_MAX_CHANNELS.
        vertical_angles : sequence of float, optional
            rad, one per channel (ring), each in [-pi/2, pi/2].
        vertical_fov : (float, float), optional
            rad, the lowest and highest elevation the channels spread over.
        points_per_turn : int, optional
            Firings of each channel per turn.
        rotation_rate : float, optional
            Hz, 0.01..1000.
        min_range, max_range : float, optional
            m: nearer hits give no point; farther is a miss.
        range_noise : float, optional
            m, the standard deviation of Gaussian noise along each ray.
        dropout : float, optional
            0..1: the chance a hit gives no point.
        reflectivity : sequence of 5 float, optional
            0..1 for bark, leaf, grass, ground and solid boxes.
        seed : int, optional
            Noise and dropout: the same seed gives the same points.

        Returns
        -------
        Lidar
        """
        poses = pose_fields(pose)
        fields = given(pose=poses, channels=channels, vertical_angles=vertical_angles,
                       vertical_fov=vertical_fov, points_per_turn=points_per_turn,
                       rotation_rate=rotation_rate, min_range=min_range, max_range=max_range,
                       range_noise=range_noise, dropout=dropout, reflectivity=reflectivity,
                       seed=seed)
        return Lidar(self, self._core.add_lidar(fields, preset), poses)

    def capture_depth(
        self,
        width: Optional[int] = None,
        height: Optional[int] = None,
        *,
        fx: Optional[float] = None,
        fy: Optional[float] = None,
        cx: Optional[float] = None,
        cy: Optional[float] = None,
        max_depth: Optional[float] = None,
        pose: Optional[Mapping] = None,
    ) -> Tuple[np.ndarray, np.ndarray]:
        """A pinhole depth image of the world as of the last step
        (``boreas_world_capture_depth``). None leaves the library's default
        (``boreas.defaults()["depth_camera"]``: 640 x 480, 525 px focal length).

        Parameters
        ----------
        width, height : int, optional
            Pixels.
        fx, fy, cx, cy : float, optional
            Pixels: focal lengths and principal point; pixel (u, v)'s ray runs along
            ((u - cx) / fx, -(v - cy) / fy, -1) in the camera's frame (it looks along -Z).
        max_depth : float, optional
            m along the optical axis: farther is nothing.
        pose : mapping, optional
            ``{"position": ..., "orientation": (x, y, z, w)}``.

        Returns
        -------
        (numpy.ndarray, numpy.ndarray)
            depth (height, width) float32, m along the optical axis (inf where nothing),
            and labels (height, width) of :data:`PIXEL_LABEL_DTYPE` (kind, object, part).
        """
        fields = given(width=width, height=height, fx=fx, fy=fy, cx=cx, cy=cy,
                       max_depth=max_depth, pose=pose_fields(pose))
        return self._core.capture_depth(fields)


def preprocess_mesh_tree(model: PathLike, out_path: PathLike, *,
                         trunk_part: Optional[str] = None, leaves_part: Optional[str] = None,
                         seed: Optional[int] = None) -> MeshTreeInfo:
    """Preprocesses an imported tree mesh without a world and writes it as a binary glTF
    whose vertices carry the wind weights, for engines (``boreas_preprocess_mesh_tree``).

    Releases the GIL. May be called from any thread at any time.

    Parameters
    ----------
    model : str or os.PathLike
        ``.obj``, ``.gltf`` or ``.glb``.
    out_path : str or os.PathLike
        The ``.glb`` to write.
    trunk_part, leaves_part : str, optional
        As in :meth:`World.add_mesh_tree`.
    seed : int, optional
        Branch phases.

    Returns
    -------
    MeshTreeInfo
    """
    fields = given(model=os.fspath(model), trunk_part=trunk_part, leaves_part=leaves_part,
                   seed=seed)
    return MeshTreeInfo(**_boreas.preprocess_mesh_tree(fields, os.fspath(out_path)))


def devices() -> List[DeviceInfo]:
    """Every OpenCL device (``boreas_list_devices``).

    Returns
    -------
    list of DeviceInfo

    Raises
    ------
    NoDeviceError
        There is no OpenCL platform at all.
    """
    return [DeviceInfo(**d) for d in _boreas.devices()]


def builtin_species() -> List[str]:
    """The built-in Weber-Penn tree species' names (``boreas_builtin_species``), for
    :meth:`World.add_tree`."""
    return _boreas.builtin_species()


def builtin_underbrush_species() -> List[str]:
    """The built-in underbrush species' names (``boreas_builtin_underbrush_species``), for
    :meth:`World.add_meadow`."""
    return _boreas.builtin_underbrush_species()
