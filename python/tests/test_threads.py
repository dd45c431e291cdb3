"""The GIL is released while the library works: another Python thread runs during a long
sample and a long step. And threads sharing one world take turns safely.

How the GIL test cannot pass by chance: a helper thread records the time of each of its
loop iterations while the main thread makes the call. The helper can run inside the call
only if the call released the GIL, so the test looks at the largest gap between the
helper's stamps within the call's window (its edges count as stamps). A held GIL leaves
one gap about as long as the call (the helper may only run at the window's very edges,
where the main thread is in Python); a released one leaves only short gaps (the helper
runs on the other core, or in the OS's time slices). The verdict "released" needs the
largest gap below half the call, and stamps in the middle half of the window; a machine
so loaded that the helper is starved for half a call makes a false "held", never a false
"released", so the positive tests try up to three calls and the negative control, which
calls the same C function through ctypes.PyDLL (it holds the GIL), tries one. A call too
short to judge (a fast GPU) skips the test rather than guess.
"""
import ctypes
import sys
import threading
import time

import numpy as np
import pytest

import boreas

import c_api
from conftest import SMALL_GRID, STEADY_WAVE


def helper_ran_inside(call, tries=3):
    """Whether a Python thread ran all through call()'s run, in any of `tries` calls."""
    old_interval = sys.getswitchinterval()
    sys.setswitchinterval(1e-4)
    try:
        for _ in range(tries):
            stamps = []
            stop = threading.Event()

            def tick():
                while not stop.is_set():
                    stamps.append(time.perf_counter())

            helper = threading.Thread(target=tick)
            helper.start()
            while not stamps:  # the helper is running
                time.sleep(0.001)
            start = time.perf_counter()
            call()
            end = time.perf_counter()
            stop.set()
            helper.join()
            duration = end - start
            if duration < 0.02:
                pytest.skip(f"the call takes {duration * 1e3:.1f} ms on this device: too "
                            "short to tell a released GIL from a held one")
            inside = np.asarray([t for t in stamps if start < t < end])
            edges = np.concatenate(([start], inside, [end]))
            largest_gap = np.diff(edges).max()
            quarter = duration / 4
            middle = ((inside > start + quarter) & (inside < end - quarter)).any()
            if middle and largest_gap < 0.5 * duration:
                return True
        return False
    finally:
        sys.setswitchinterval(old_interval)


def test_sample_releases_the_gil(world):
    pts = np.random.default_rng(0).uniform(-5, 5, size=(4_000_000, 3)).astype(np.float32)
    out = np.empty_like(pts)
    world.wind.sample(pts[:10])  # kernels built
    assert helper_ran_inside(lambda: world.wind.sample(pts, out=out))


def test_step_releases_the_gil(world):
    world.add_trees(species="weeping_willow", position=[(x, 0.0, 0.0) for x in range(24)],
                    mode="exact")
    world.step(0.01)
    assert helper_ran_inside(lambda: world.step(1 / 30))


def test_the_check_fails_for_a_call_that_holds_the_gil(capi):
    # The negative control: the same C function called through ctypes.PyDLL, which keeps
    # the GIL during the call, on a world made the same way.
    c_world = c_api.CWorld(capi, SMALL_GRID, [STEADY_WAVE])
    try:
        sample = ctypes.PyDLL(capi.path).boreas_wind_sample
        sample.restype = ctypes.c_int
        sample.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_int, ctypes.c_void_p]
        pts = np.random.default_rng(0).uniform(-5, 5, size=(4_000_000, 3)).astype(np.float32)
        out = np.empty_like(pts)

        def held():
            assert sample(c_world.handle, pts.ctypes.data, len(pts), out.ctypes.data) == 0

        held()
        assert not helper_ran_inside(held, tries=1)
    finally:
        c_world.close()


def test_threads_sharing_a_world_take_turns():
    with boreas.World(grid=SMALL_GRID, waves=[STEADY_WAVE]) as world:
        pts = np.random.default_rng(1).uniform(-4, 4, size=(20000, 3)).astype(np.float32)
        expected = world.wind.sample(pts)
        errors = []

        def worker():
            try:
                for _ in range(20):
                    assert world.wind.sample(pts).tobytes() == expected.tobytes()
            except Exception as e:  # reported below
                errors.append(e)

        threads = [threading.Thread(target=worker) for _ in range(4)]
        for t in threads:
            t.start()
        for _ in range(10):
            world.add_tree("quaking_aspen")
        for t in threads:
            t.join()
        assert not errors
