"""The wind of a world: sampling it, its sine-sum waves, gusts and flow primitives, solid
obstacles, and the force-field grid.

The wind at a point p and time t is ``sine_sum(p.x, p.z, t) + grid(p, t)`` in m/s, zero
inside solid cells.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Iterable, Optional, Sequence, Union

import numpy as np

from ._defs import Grid, Wave, as_fields, given
from ._handles import FlowPrimitive, Gust

if TYPE_CHECKING:
    from ._world import World

WaveLike = Union[Wave, "dict[str, Any]"]


def waves_as_fields(waves: Optional[Iterable[Any]], what: str = "waves") -> Optional[list]:
    """Waves given as :class:`Wave` objects or mappings, as dicts of fields."""
    if waves is None:
        return None
    if isinstance(waves, (Wave, dict)):
        raise TypeError(f"{what} must be a sequence of waves, not one wave (wrap it in a list)")
    return [as_fields(w, Wave, f"{what}[{i}]") for i, w in enumerate(waves)]


class Wind:
    """The wind of a :class:`World` (``world.wind``)."""

    __slots__ = ("_world",)

    def __init__(self, world: "World") -> None:
        self._world = world

    def sample(self, points: Any, out: Optional[np.ndarray] = None) -> np.ndarray:
        """The wind at points, at the world's current time (``boreas_wind_sample``).

        Runs with the GIL released: other Python threads go on meanwhile.

        Parameters
        ----------
        points : array_like, shape (N, 3)
            m. A C-contiguous float32 array is read in place; anything else is converted
            once. At most ``WIND_SAMPLE_MAX_POINTS`` points per call.
        out : numpy.ndarray, optional
            Shape (N, 3), C-contiguous, writeable float32: the wind is written into it, with
            no copy, and it is returned.

        Returns
        -------
        numpy.ndarray
            Shape (N, 3), float32, m/s.

        Raises
        ------
        ValueError
            `points` or `out` has the wrong shape, or `out` the wrong dtype or layout.
        TypeError
            `points` is not numeric, or `out` is not a numpy.ndarray.
        InvalidArgumentError
            A point is not finite.
        """
        return self._world._core.wind_sample(points, out)

    def set_waves(self, waves: Iterable[WaveLike], blend: float = 0.0) -> None:
        """Replaces the sine-sum waves (``boreas_wind_set_waves``; at most ``WIND_MAX_WAVES``).

        Parameters
        ----------
        waves : sequence of Wave or dict
            The new set; may be empty (calm after the blend).
        blend : float
            s: the new set blends in over this time while the old one blends out
            (smoothstep weights), so the wind never jumps; 0 switches at once.
        """
        self._world._core.wind_set_waves(waves_as_fields(waves) or [], blend)

    def add_gust(
        self,
        direction: Optional[Sequence[float]] = None,
        strength: Optional[float] = None,
        *,
        delay: Optional[float] = None,
        rise: Optional[float] = None,
        hold: Optional[float] = None,
        fall: Optional[float] = None,
        center: Optional[Sequence[float]] = None,
        radius: Optional[float] = None,
    ) -> Gust:
        """Adds a gust to the grid (``boreas_wind_add_gust``): a uniform push whose
        strength rises, holds and falls (smoothstep ramps), removed at the end of its fall.

        Parameters
        ----------
        direction : sequence of 3 float, optional
            Normalized by the library; not zero.
        strength : float, optional
            m/s at the peak, abs <= ``WIND_MAX_SPEED``.
        delay, rise, hold, fall : float, optional
            s, >= 0: from now until the rise starts, then the ramps and the hold.
        center : sequence of 3 float, optional
            m.
        radius : float, optional
            m, >= 0; 0 is the whole grid.

        None leaves the library's default (``boreas.defaults()["gust"]``).

        Returns
        -------
        Gust
        """
        fields = given(direction=direction, strength=strength, delay=delay, rise=rise,
                       hold=hold, fall=fall, center=center, radius=radius)
        return Gust(self._world, self._world._core.wind_add_gust(fields))

    def add_primitive(
        self,
        type: str = "uniform",
        position: Optional[Sequence[float]] = None,
        direction: Optional[Sequence[float]] = None,
        *,
        strength: Optional[float] = None,
        radius: Optional[float] = None,
        lifetime: Optional[float] = None,
    ) -> FlowPrimitive:
        """Adds a flow primitive to the grid (``boreas_wind_add_primitive``, after
        Wejchert and Haumann).

        Parameters
        ----------
        type : {"uniform", "source", "sink", "vortex"}
            Uniform: ``strength * direction``; source and sink: outward from and inward to
            `position`; vortex: around the axis `direction` through `position`,
            right-handed.
        position : sequence of 3 float, optional
            m.
        direction : sequence of 3 float, optional
            Flow direction (uniform) or axis (vortex); normalized; not zero.
        strength : float, optional
            m/s, abs <= ``WIND_MAX_SPEED``: the peak speed of its flow.
        radius : float, optional
            m, >= 0: smooth compact support; 0 (uniform only) is everywhere.
        lifetime : float, optional
            s, >= 0: removed automatically after this; 0 is until removed.

        Returns
        -------
        FlowPrimitive
        """
        fields = given(type=type, position=position, direction=direction, strength=strength,
                       radius=radius, lifetime=lifetime)
        return FlowPrimitive(self._world, self._world._core.wind_add_primitive(fields))

    def add_solid_box(self, min: Sequence[float], max: Sequence[float]) -> None:
        """Marks solid every grid cell whose center lies in the box [min, max]
        (``boreas_wind_add_solid_box``).

        Solid cells have zero wind (sine sums included) at once; from the next step on no
        wind flows through their faces.

        Parameters
        ----------
        min, max : sequence of 3 float
            m, the box's corners.
        """
        self._world._core.wind_add_solid_box(min, max)

    def set_solid_mask(self, mask: Optional[Any]) -> None:
        """Replaces the solid cells (``boreas_wind_set_solid_mask``).

        Parameters
        ----------
        mask : array_like of bool, shape (nz, ny, nx), or None
            True where a cell is solid (the layout of :meth:`grid_values`); None clears every
            solid, boxes included. Refused on a grid that follows the focus, except None.
        """
        if mask is not None:
            mask = np.ascontiguousarray(mask, dtype=bool).view(np.uint8)
        self._world._core.wind_set_solid_mask(mask)

    @property
    def grid(self) -> Grid:
        """Grid: the grid as the world uses it (``boreas_wind_get_grid``; its origin is where a
        grid that follows the focus stands now)."""
        return Grid._from_c(self._world._core.wind_grid())

    def grid_values(self) -> np.ndarray:
        """The grid's part of the wind (``boreas_wind_get_grid_values``).

        Returns
        -------
        numpy.ndarray
            Shape (nz, ny, nx, 4), float32: per cell the wind's x, y, z (m/s) and 1.0 if
            the cell is solid, else 0.0. ``[k, j, i]`` is the cell at
            ``origin + cell_size * (i + 0.5, j + 0.5, k + 0.5)``.
        """
        return self._world._core.wind_grid_values()

    def __repr__(self) -> str:
        return f"<boreas.Wind of {self._world!r}>"
