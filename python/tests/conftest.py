"""Shared fixtures: small worlds (an 8 x 4 x 8 grid of 1 m cells around the origin, so
steps are cheap) in a steady wind, and the C API through ctypes for round trips."""
import numpy as np
import pytest

import boreas

import c_api

# A grid around the origin, small enough for fast steps.
SMALL_GRID = {"origin": (-4.0, 0.0, -4.0), "cell_size": 1.0, "resolution": (8, 4, 8)}
# A steady wind of 6 m/s along +x: sharpness 0 makes the sine sum a constant.
STEADY_WAVE = {"direction": (1.0, 0.0), "amplitude": 6.0, "sharpness": 0.0}
# A gusty wave: its strength changes over space and time.
GUSTY_WAVE = {"direction": (0.8, 0.6), "amplitude": 4.0, "wavelength": 12.0, "speed": 5.0,
              "sharpness": 2.0}


@pytest.fixture
def world():
    """A small world in a steady 6 m/s wind along +x, closed after the test."""
    with boreas.World(grid=SMALL_GRID, waves=[STEADY_WAVE]) as w:
        yield w


@pytest.fixture
def calm_world():
    """A small world with no wind at all."""
    with boreas.World(grid=SMALL_GRID) as w:
        yield w


@pytest.fixture(scope="session")
def capi():
    """The C API of the library under test (BOREAS_LIBRARY)."""
    return c_api.load()


def points(n, seed=0, extent=6.0):
    """n random points, float32 (n, 3), m, over and beyond the small grid."""
    rng = np.random.default_rng(seed)
    p = rng.uniform(-extent, extent, size=(n, 3)).astype(np.float32)
    p[:, 1] = np.abs(p[:, 1])
    return p
