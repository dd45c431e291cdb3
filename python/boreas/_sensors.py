"""Sensors: a spinning LiDAR held by a world, and the presets of common units. Rays and
depth images are :class:`World` methods (:meth:`World.cast_rays`,
:meth:`World.capture_depth`).

Frames (``boreas.h``, "Sensors"): a pose is a position (m) and a unit quaternion
``(x, y, z, w)`` turning the sensor's axes into the world's, and an optional ``origin``
(m, kept in double) the position counts from, for a sensor far from 0. A LiDAR spins about its local
+Y, azimuth 0 along local +X, counter-clockwise seen from above; a camera looks along its
local -Z with +Y up. Points come out in the world frame, relative to the world's output
origin (:meth:`World.set_output_origin`; world coordinates by default), as rays do.
"""
from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any, Dict, List, Optional, Sequence

import numpy as np

from . import _boreas
from ._handles import Handle, Id

if TYPE_CHECKING:
    from ._world import World


def pose_fields(pose: Any, what: str = "pose") -> Optional[Dict[str, Any]]:
    """A pose given as a mapping with ``position`` and/or ``orientation`` (None: the
    default), as the dict the core takes."""
    if pose is None:
        return None
    if not isinstance(pose, Mapping):
        raise TypeError(f"{what} must be a mapping with 'position' and 'orientation', "
                        f"not {type(pose).__name__}")
    return dict(pose)


class Lidar(Handle):
    """A spinning LiDAR (``boreas_lidar_id``). Made by :meth:`World.add_lidar`. Each step
    casts the firings of its sweep that fall in the step; :meth:`points` reads them."""

    __slots__ = ("_pose",)
    _remove = "remove_lidar"

    def __init__(self, world: "World", id: Id, pose: Optional[Dict[str, Any]]) -> None:
        super().__init__(world, id)
        self._pose = pose

    @property
    def pose(self) -> Optional[Dict[str, Any]]:
        """dict or None: the last pose set from Python (None: the one it was added with).
        Setting it moves the LiDAR: the pose is reached at the end of the next step, each
        firing of that step taking the pose in between at its time
        (``boreas_lidar_set_pose``)."""
        return self._pose

    @pose.setter
    def pose(self, pose: Mapping) -> None:
        fields = pose_fields(pose)
        self._world._core.lidar_set_pose(self._id, fields)
        self._pose = fields

    def points(self, which: str = "sweep") -> np.ndarray:
        """The points (``boreas_lidar_get_points``) as a structured array of
        :data:`LIDAR_POINT_DTYPE`: x, y, z, intensity (float32), ring (uint16), time
        (float32, s since the sweep began) laid out as a ROS PointCloud2 reads them, then
        kind (a hit kind), object (index, generation, tag) and part.

        Parameters
        ----------
        which : {"sweep", "step"}
            The last complete sweep, or the last step's firings.
        """
        return self._world._core.lidar_points(self._id, which)

    def info(self) -> Dict[str, Any]:
        """Where the sweep stands (``boreas_lidar_get_info``): sweep_start and
        next_sweep_start (s, world time), sweeps and firings so far, last_step_rays."""
        return self._world._core.lidar_info(self._id)


def lidar_presets() -> List[str]:
    """The names of the LiDAR presets (``boreas_lidar_preset_name``), for
    :meth:`World.add_lidar`."""
    return _boreas.lidar_preset_names()


def lidar_preset(name: str) -> Dict[str, Any]:
    """A preset's def (``boreas_lidar_preset``) as a dict: its published vertical angles
    (rad, lowest first), points per turn, rate, range and noise."""
    return _boreas.lidar_preset(name)


def rays_as_arrays(origins: Any, directions: Any,
                   max_distance: Any) -> Sequence[Any]:
    """origins and directions as (N, 3) float32 (one origin for all may be given as 3
    numbers) and max_distance as a number or N numbers."""
    directions = np.asarray(directions, dtype=np.float32)
    origins = np.asarray(origins, dtype=np.float32)
    if origins.shape == (3,) and directions.ndim == 2:
        origins = np.broadcast_to(origins, directions.shape)
    return (np.ascontiguousarray(origins), np.ascontiguousarray(directions),
            np.asarray(max_distance, dtype=np.float32))
