"""Handles to the objects a world holds: trees, meadows, colliders, emitters, gusts, flow
primitives, mesh trees and BlobTrees.

A handle keeps its world alive and names its object by the C library's id. Once the object
is removed (or expired, as a gust does at the end of its fall) every call on the handle
raises :class:`NotFoundError`; once the world is closed, :class:`Error`.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable, Dict, Iterable, Optional, Sequence, Tuple

import numpy as np

from ._defs import BlobTreeInfo, ColliderContact, MeshTreeInfo

if TYPE_CHECKING:
    from ._world import World

Id = Tuple[int, int, int]


class Handle:
    """An object in a world, named by its id.

    Handles compare equal when they name the same object of the same world, and hash
    accordingly.
    """

    __slots__ = ("_world", "_id")
    _remove = ""  # the core World's method that removes this kind

    def __init__(self, world: "World", id: Id) -> None:
        self._world = world
        self._id = tuple(id)

    @property
    def world(self) -> "World":
        """World: the world the object is in."""
        return self._world

    @property
    def id(self) -> Id:
        """tuple of 3 int: the C id (index, generation, tag), for messages and hashing."""
        return self._id

    def remove(self) -> None:
        """Removes the object from its world.

        Raises
        ------
        NotFoundError
            The object was already removed (or expired).
        """
        getattr(self._world._core, self._remove)(self._id)

    def __eq__(self, other: object) -> bool:
        return (
            type(other) is type(self)
            and other._world is self._world  # type: ignore[attr-defined]
            and other._id == self._id  # type: ignore[attr-defined]
        )

    def __hash__(self) -> int:
        return hash((type(self).__name__, id(self._world), self._id))

    def __repr__(self) -> str:
        return f"<boreas.{type(self).__name__} id={self._id}>"


class Tree(Handle):
    """A Weber-Penn tree (``boreas_tree_id``): one cubic Bezier curve per branch, bent by the
    wind every step. Made by :meth:`World.add_tree` and :meth:`World.add_trees`."""

    __slots__ = ()
    _remove = "remove_tree"

    @property
    def branches(self) -> np.ndarray:
        """numpy.ndarray: the branches as of the last step, levels in order (the trunk
        first), shape (B,), dtype :data:`BRANCH_DTYPE`.

        Fields: ``control_points`` (4, 3) float32, m, world space; ``orientation`` (3,)
        float32, the vector the branch's Sloan frame starts from; ``level`` int32 (0 trunk
        .. 3); ``parent`` int32 (index in this array, -1 for the trunk); ``parent_v``
        float32 (where P0 sits on the parent's curve, 0..1); ``radius`` float32 (m, at the
        base); ``length`` float32 (m, of the unbent control polygon); ``broken`` int32 (1
        once the wind broke the branch: it hangs from its parent; 0 while whole).
        """
        return self._world._core.tree_branches(self._id)

    def heal(self) -> None:
        """Mends every broken branch and puts the tree back at rest, unbent
        (``boreas_tree_heal``)."""
        self._world._core.heal_tree(self._id)

    @property
    def leaves(self) -> np.ndarray:
        """numpy.ndarray: the leaves as of the last step, shape (L,), dtype
        :data:`LEAF_DTYPE`: ``position`` (3,) float32 m (where the blade starts),
        ``axis`` and ``normal`` (3,) float32 unit vectors, ``length`` and ``width`` float32
        m, ``branch`` int32 (index into :attr:`branches`)."""
        return self._world._core.tree_leaves(self._id)

    def leaf_occlusion(self, transmittance: Sequence[float] = (0.06, 0.13, 0.02)) -> np.ndarray:
        """The crown's ambient occlusion at each leaf as the tree is now (call it at rest),
        computed on the device: shape (L, 3) float32, per leaf the share (r, g, b) of a
        uniform sky's light that reaches it through the crown, for leaves passing on
        ``transmittance`` (three values in [0, 1]; the default is a typical lamina's) of
        the light they intercept, in the order of :attr:`leaves`."""
        return self._world._core.tree_leaf_occlusion(self._id, tuple(float(t) for t in transmittance))

    def mesh(self) -> Tuple[np.ndarray, np.ndarray]:
        """The branch mesh as of the last step, swept by the de Casteljau deformer.

        Returns
        -------
        vertices : numpy.ndarray
            Shape (V,), dtype :data:`VERTEX_DTYPE`: ``position`` (3,) float32 m,
            ``normal`` (3,) float32 unit and outward, ``uv`` (2,) float32.
        triangles : numpy.ndarray
            Shape (T, 3), uint32 indices into `vertices`, counter-clockwise seen from
            outside.
        """
        return self._world._core.tree_mesh(self._id)

    def skin(self, max_level: int = 3, segments: int = 4) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The tree's skin (``boreas_tree_get_joints``): joints on the branches down to
        `max_level` (0..3), `segments` + 1 along each branch from base to tip, and every
        mesh vertex and leaf bound to the two joints around its place; finer branches ride
        on their ancestor of `max_level`. Call it before the first step (or after
        :meth:`heal`) for the bind pose; the joints alone each frame for the motion.

        Returns
        -------
        joints : numpy.ndarray
            Shape (J,), dtype :data:`JOINT_DTYPE`: ``position`` (3,) float32 m and
            ``rotation`` (4,) float32 unit quaternion (x, y, z, w) of the joint's frame in
            world (y along the branch), ``parent`` int32 (-1 for the root), ``branch``
            int32 (index into :attr:`branches`), ``u`` float32 (place on the branch, 0..1).
        vertex_weights : numpy.ndarray
            Shape (V,), dtype :data:`SKIN_WEIGHT_DTYPE`: ``joints`` (4,) int32 and
            ``weights`` (4,) float32 per vertex of :meth:`mesh`.
        leaf_weights : numpy.ndarray
            The same per leaf of :attr:`leaves`.
        """
        core, i = self._world._core, self._id
        return (core.tree_joints(i, max_level, segments), core.tree_skin_weights(i, max_level, segments),
                core.tree_leaf_skin_weights(i, max_level, segments))

    def joints(self, max_level: int = 3, segments: int = 4) -> np.ndarray:
        """The joints of :meth:`skin` alone, as of the last step (``boreas_tree_get_joints``):
        what an animation reads every frame, without the bindings.

        Returns
        -------
        numpy.ndarray
            Shape (J,), dtype :data:`JOINT_DTYPE`, as :meth:`skin`'s first array.
        """
        return self._world._core.tree_joints(self._id, max_level, segments)

    def add_blobtree(
        self,
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
        progress: Optional["ProgressCallback"] = None,
    ) -> "BlobTree":
        """This tree as a BlobTree surface: :meth:`World.add_blobtree` with this tree and
        the same keyword arguments.

        Returns
        -------
        BlobTree
        """
        return self._world.add_blobtree(
            self, resolution=resolution, cubic=cubic, max_level=max_level,
            min_radius=min_radius, junctions=junctions, offsets=offsets, ridge=ridge,
            ridge_width=ridge_width, bend=bend, cuts=cuts, scars=scars, progress=progress)


class Meadow(Handle):
    """A patch of underbrush (``boreas_meadow_id``): components of grass, clover, daisies
    and ferns moved by the wind, colliders and emitters. Made by :meth:`World.add_meadow`."""

    __slots__ = ()
    _remove = "remove_meadow"

    @property
    def components(self) -> np.ndarray:
        """numpy.ndarray: the components as of the last step, shape (C,), dtype
        :data:`COMPONENT_DTYPE`: ``base``, ``center_of_mass``, ``rest_center_of_mass``
        (3,) float32 m; ``velocity`` (3,) float32 m/s (relative to the base); ``broken``
        int32 (0 intact, else 1 + the section where it broke); ``species`` int32 (index in
        the meadow's species list); ``part`` int32; ``parent`` int32 (index of the
        component it is fixed to, -1 for the ground)."""
        return self._world._core.meadow_components(self._id)

    @property
    def parts(self) -> np.ndarray:
        """numpy.ndarray: how each part of the meadow's species looks, from the species
        files, shape (P,), dtype :data:`MEADOW_PART_DTYPE`: ``species`` and ``part`` int32
        (a component's look is the row with its species and part); ``name`` bytes (32);
        ``color`` (3,) float32 sRGB 0..1; ``translucency`` float32 0..1."""
        return self._world._core.meadow_parts(self._id)

    def vertices(self, camera: Optional[Iterable[float]] = None) -> Tuple[np.ndarray, np.ndarray]:
        """The components' triangle strips as of the last step.

        Parameters
        ----------
        camera : sequence of 3 float, optional
            m: strips get coarser with the distance from it (the meadow's
            ``lod_distances``). None: full detail everywhere.

        Returns
        -------
        vertices : numpy.ndarray
            Shape (C, 18), dtype :data:`MEADOW_VERTEX_DTYPE` (``position`` (3,) float32 m,
            ``normal`` (3,) float32, ``uv`` (2,) float32): row i is component i's strip.
        strip_counts : numpy.ndarray
            Shape (C,), int32: the vertices of row i that are drawn (the rest repeat its
            tip; 0 past the last LOD distance).
        """
        return self._world._core.meadow_vertices(self._id, camera)


class _Movable(Handle):
    __slots__ = ("_position",)
    _set_position = ""

    def __init__(self, world: "World", id: Id, position: Iterable[float]) -> None:
        super().__init__(world, id)
        self._position = tuple(float(x) for x in position)

    @property
    def position(self) -> Tuple[float, float, float]:
        """tuple of 3 float: m, where it is (the last position set from Python); setting
        it moves the object, which acts there from the next step on."""
        return self._position  # type: ignore[return-value]

    @position.setter
    def position(self, center: Iterable[float]) -> None:
        center = tuple(float(x) for x in center)
        getattr(self._world._core, self._set_position)(self._id, center)
        self._position = center


class Collider(Handle):
    """A kinematic sphere, capsule or box that pushes plants aside and feels them push back
    (``boreas_collider_id``). Made by :meth:`World.add_collider`. Each step it sweeps along
    its velocity and the world moves it there (turned by its angular velocity); a caller
    that sets its pose every step overrides that."""

    __slots__ = ()
    _remove = "remove_collider"

    @property
    def pose(self) -> Dict[str, Tuple[float, ...]]:
        """dict: ``position`` (3 floats, m, from ``origin``), ``orientation`` (unit
        quaternion x, y, z, w) and ``origin`` (3 floats, m, world, kept in double) where
        the next step starts (``boreas_collider_get_pose``)."""
        return self._world._core.collider_pose(self._id)

    @property
    def position(self) -> Tuple[float, float, float]:
        """tuple of 3 float: m, where the next step starts; setting it moves the collider
        there and keeps its orientation (``boreas_collider_set_position``). The world
        position: the pose's origin + position, summed in double."""
        pose = self.pose
        return tuple(o + p for o, p in zip(pose["origin"], pose["position"]))  # type: ignore[return-value]

    @position.setter
    def position(self, center: Iterable[float]) -> None:
        self._world._core.collider_set_position(self._id, tuple(float(x) for x in center))

    def set_pose(self, position: Sequence[float],
                 orientation: Optional[Sequence[float]] = None,
                 origin: Optional[Sequence[float]] = None) -> None:
        """Moves the collider (``boreas_collider_set_pose``).

        Parameters
        ----------
        position : sequence of 3 float
            m.
        orientation : sequence of 4 float, optional
            Unit quaternion x, y, z, w (within 1e-3 of unit length; normalized). None keeps
            the current one.
        origin : sequence of 3 float, optional
            m, world, kept in double: what position counts from (far from 0, an origin near
            the collider and a small position place it exactly). None: 0, 0, 0.
        """
        pose: Dict[str, Any] = {"position": position}
        if origin is not None:
            pose["origin"] = origin
        if orientation is not None:
            pose["orientation"] = orientation
        else:
            pose["orientation"] = self.pose["orientation"]
        self._world._core.collider_set_pose(self._id, pose)

    def set_velocity(self, velocity: Optional[Sequence[float]] = None,
                     angular_velocity: Optional[Sequence[float]] = None) -> None:
        """Sets the velocity (m/s) and angular velocity (rad/s, about its position), world
        frame (``boreas_collider_set_velocity``); None keeps either."""
        self._world._core.collider_set_velocity(self._id, velocity, angular_velocity)

    @property
    def contact(self) -> ColliderContact:
        """ColliderContact: what the plants pushed it with over the last step (zeros before
        the first step and for a collider added since; ``boreas_collider_get_contact``)."""
        return ColliderContact(**self._world._core.collider_contact(self._id))


class Emitter(_Movable):
    """A source of impulses (rain drops, footsteps) that push underbrush
    (``boreas_emitter_id``). Made by :meth:`World.add_emitter`."""

    __slots__ = ()
    _remove = "remove_emitter"
    _set_position = "emitter_set_position"


class Gust(Handle):
    """A gust of the wind grid (``boreas_gust_id``): a push that rises, holds and falls, and
    is removed at the end of its fall. Made by :meth:`Wind.add_gust`."""

    __slots__ = ()
    _remove = "wind_remove_gust"


class FlowPrimitive(Handle):
    """A flow primitive of the wind grid (``boreas_primitive_id``): uniform, source, sink or
    vortex. Made by :meth:`Wind.add_primitive`."""

    __slots__ = ()
    _remove = "wind_remove_primitive"


class MeshTree(Handle):
    """An imported tree mesh (OBJ or glTF) swaying in the wind (``boreas_mesh_tree_id``).
    Made by :meth:`World.add_mesh_tree`."""

    __slots__ = ()
    _remove = "remove_mesh_tree"

    @property
    def info(self) -> MeshTreeInfo:
        """MeshTreeInfo: what preprocessing found in the model."""
        return MeshTreeInfo(**self._world._core.mesh_tree_info(self._id))

    def vertices(self, part: str = "trunk") -> np.ndarray:
        """The part's vertices as of the last step, world space.

        Parameters
        ----------
        part : {"trunk", "leaves"}

        Returns
        -------
        numpy.ndarray
            Shape (V,), dtype :data:`VERTEX_DTYPE` (``position`` (3,) float32 m, ``normal``
            (3,) float32, ``uv`` (2,) float32). Trunk normals are the rest normals.
        """
        return self._world._core.mesh_tree_vertices(self._id, part)

    def indices(self, part: str = "trunk") -> np.ndarray:
        """The part's triangles.

        Parameters
        ----------
        part : {"trunk", "leaves"}

        Returns
        -------
        numpy.ndarray
            Shape (T, 3), uint32 indices into :meth:`vertices` of the same part.
        """
        return self._world._core.mesh_tree_indices(self._id, part)


class BlobTree(Handle):
    """A tree of the world as one implicit surface, polygonized (``boreas_blobtree_id``).
    Made by :meth:`World.add_blobtree` or :meth:`Tree.add_blobtree`."""

    __slots__ = ()
    _remove = "remove_blobtree"

    @property
    def info(self) -> BlobTreeInfo:
        """BlobTreeInfo: sizes of the BlobTree and its mesh."""
        return BlobTreeInfo(**self._world._core.blobtree_info(self._id))

    def mesh(self) -> Tuple[np.ndarray, np.ndarray]:
        """The watertight mesh of the surface.

        Returns
        -------
        vertices : numpy.ndarray
            Shape (V,), dtype :data:`VERTEX_DTYPE`: ``position`` (3,) float32 m,
            ``normal`` (3,) float32 outward (from the field's gradient), ``uv`` (2,)
            float32 (u around a branch 0..1, v along it).
        triangles : numpy.ndarray
            Shape (T, 3), uint32, counter-clockwise seen from outside.
        """
        return self._world._core.blobtree_mesh(self._id)


ProgressCallback = Callable[[float, str], Any]
