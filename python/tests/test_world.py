"""boreas.World: its life (context manager, close), stepping, what it reports, and the
module-level calls, against the C API where it has an answer."""
import numpy as np
import pytest

import boreas

import c_api
from conftest import GUSTY_WAVE, SMALL_GRID, STEADY_WAVE


def test_version_is_the_loaded_librarys(capi):
    assert boreas.__version__ == capi.version().decode()
    assert boreas.__version__.count(".") == 2


def test_builtin_species_match_the_c_api(capi):
    assert boreas.builtin_species() == capi.names(capi.builtin_species)
    assert boreas.builtin_underbrush_species() == capi.names(capi.builtin_underbrush_species)
    assert "weeping_willow" in boreas.builtin_species()
    assert "meadow_grass" in boreas.builtin_underbrush_species()


def test_defaults_are_the_c_librarys(capi):
    grid = capi.default_grid_def()
    assert boreas.Grid().cell_size == grid.cell_size
    assert boreas.Grid().resolution == tuple(grid.resolution)
    assert np.float32(boreas.Grid().decay_rate) == np.float32(grid.decay_rate)
    wave = capi.default_wave()
    assert boreas.Wave().wavelength == wave.wavelength
    assert boreas.defaults()["tree"]["species"] == capi.default_tree_def().species.decode()
    # A copy: changing it changes nothing.
    boreas.defaults()["grid"]["cell_size"] = -1
    assert boreas.defaults()["grid"]["cell_size"] == grid.cell_size


def test_devices_and_the_worlds_device():
    devices = boreas.devices()
    assert devices and all(isinstance(d, boreas.DeviceInfo) for d in devices)
    with boreas.World(device=devices[0], grid=SMALL_GRID) as world:
        assert world.device == devices[0]
        assert world.device.request == "%d:%d" % (devices[0].platform_index,
                                                  devices[0].device_index)


def test_unknown_device_is_no_device_error():
    with pytest.raises(boreas.NoDeviceError) as info:
        boreas.World(device="no such device anywhere", grid=SMALL_GRID)
    assert info.value.status == 2


def test_context_manager_closes_and_calls_then_raise(world):
    with boreas.World(grid=SMALL_GRID) as w:
        tree = w.add_tree("quaking_aspen")
        assert not w.closed
    assert w.closed
    for call in (lambda: w.step(0.1), lambda: w.time, lambda: w.wind.sample([[0, 0, 0]]),
                 lambda: tree.branches, lambda: w.add_tree(), lambda: w.state_hash()):
        with pytest.raises(boreas.Error, match="closed") as info:
            call()
        assert info.value.status is None
        assert type(info.value) is boreas.Error
    w.close()  # twice is fine
    assert "closed" in repr(w)


def test_step_advances_time_and_refuses_bad_dt(world):
    assert world.time == 0.0
    world.step(0.25)
    world.step(0.25)
    assert world.time == pytest.approx(0.5)
    for dt in (0.0, -1.0, float("nan"), 3601.0):
        with pytest.raises(boreas.InvalidArgumentError, match="dt") as info:
            world.step(dt)
        assert info.value.status == 1
    assert world.time == pytest.approx(0.5), "a refused step leaves the world as it was"


def test_step_stats_and_memory(world):
    assert world.step_stats.total == 0.0
    world.add_tree("quaking_aspen")
    world.step(0.1)
    stats = world.step_stats
    assert isinstance(stats, boreas.StepStats)
    assert stats.total > 0.0
    assert stats.trees_by_lod == (1, 0, 0, 0)
    assert stats.branches_stepped == len(world.add_tree("quaking_aspen").branches)
    memory = world.memory
    assert isinstance(memory, boreas.MemoryInfo)
    assert 0 < memory.device_bytes <= memory.device_limit


def test_state_hash_matches_a_world_built_through_the_c_api(capi):
    c_world = c_api.CWorld(capi, SMALL_GRID, [GUSTY_WAVE])
    try:
        with boreas.World(grid=SMALL_GRID, waves=[GUSTY_WAVE]) as world:
            tree = world.add_tree("quaking_aspen", (1.0, 0.0, -1.0), mode="exact")
            c_tree = c_world.add_tree("quaking_aspen", (1.0, 0.0, -1.0), mode=1)
            for _ in range(4):
                world.step(1 / 30)
                c_world.step(1 / 30)
            assert world.state_hash() == c_world.state_hash()
            ours = tree.branches
            theirs = c_world.branches(c_tree, boreas.BRANCH_DTYPE)
            assert ours.tobytes() == theirs.tobytes()
    finally:
        c_world.close()


def test_same_inputs_same_hash_different_inputs_different_hash():
    def run(amplitude):
        wave = dict(GUSTY_WAVE, amplitude=amplitude)
        with boreas.World(grid=SMALL_GRID, waves=[wave]) as world:
            world.add_tree("quaking_aspen", seed=3)
            for _ in range(3):
                world.step(0.05)
            return world.state_hash()

    assert run(4.0) == run(4.0)
    assert run(4.0) != run(5.0)


def test_grid_given_as_grid_or_dict_and_checked():
    with boreas.World(grid=boreas.Grid(**SMALL_GRID)) as world:
        assert world.wind.grid.resolution == SMALL_GRID["resolution"]
    with pytest.raises(TypeError, match="grid has no field 'size'"):
        boreas.World(grid={"size": 3})
    with pytest.raises(TypeError, match="grid must be"):
        boreas.World(grid=42)
    with pytest.raises(ValueError, match=r"grid.resolution must be 3 integers"):
        boreas.World(grid={"resolution": (8, 8)})
    with pytest.raises(TypeError, match=r"grid.resolution\[0\] must be an integer"):
        boreas.World(grid={"resolution": (8.5, 8, 8)})
    with pytest.raises(boreas.InvalidArgumentError, match="cell_size"):
        boreas.World(grid=dict(SMALL_GRID, cell_size=-1.0))


def test_set_focus_moves_a_following_grid():
    grid = dict(SMALL_GRID, follow_focus=True)
    with boreas.World(grid=grid, waves=[STEADY_WAVE]) as world:
        world.set_focus((20.0, 1.0, 0.0))
        world.step(0.1)
        assert world.wind.grid.origin[0] > 10.0
        world.set_focus(None)
        world.set_focus([[0, 0, 0], [1, 1, 1]])
        with pytest.raises(boreas.InvalidArgumentError):
            world.set_focus([[np.inf, 0, 0]])


def test_error_classes_mirror_the_statuses(capi):
    classes = {1: boreas.InvalidArgumentError, 2: boreas.NoDeviceError,
               3: boreas.KernelBuildError, 4: boreas.OpenCLError, 5: boreas.NotFoundError,
               6: boreas.OutOfMemoryError, 7: boreas.FileError, 8: boreas.InternalError}
    for status, cls in classes.items():
        assert issubclass(cls, boreas.Error)
        assert cls.status == status
        assert cls.status_name == capi.status_name(status).decode()
        assert cls.__module__ == "boreas" and cls.__doc__
    assert issubclass(boreas.InvalidArgumentError, ValueError)
    assert issubclass(boreas.NotFoundError, LookupError)
    assert issubclass(boreas.OutOfMemoryError, MemoryError)
    assert issubclass(boreas.FileError, OSError)
    assert boreas.Error.status is None
