"""The GIL is released while the library works: another Python thread runs during a long
sample and a long step. And threads sharing one world take turns safely.

How the GIL test cannot pass by chance: a helper thread records the time of each of its
loop iterations. While the main thread is inside the call, the helper can run only if the
call released the GIL. Before the call starts and after it returns the main thread holds
the GIL but may hand it over at a switch interval (set to 0.1 ms here), so the helper may
run at the very edges of the call window; the test therefore looks only at the middle half
of the window, which lasts tens of milliseconds. A held GIL leaves it empty; a released one
fills it (the helper runs on the other core, or in the OS's time slices). Up to three calls
are tried, so that one call starved of CPU by a loaded machine does not fail the test. The
negative control calls the same C function through ctypes.PyDLL, which holds the GIL, and
checks that the test sees that.
"""
import ctypes
import sys
import threading
import time

import numpy as np

import boreas

import c_api
from conftest import SMALL_GRID, STEADY_WAVE


def helper_ran_inside(call, tries=3):
    """Whether a Python thread ran in the middle half of call()'s run, in any of `tries`."""
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
            assert end - start > 0.02, "the call is too short for the test to tell"
            quarter = (end - start) / 4
            stamps = np.asarray(stamps)
            if ((stamps > start + quarter) & (stamps < end - quarter)).any():
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
        assert not helper_ran_inside(held)
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
