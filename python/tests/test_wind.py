"""world.wind: sampling against the C API bit for bit, the arrays it takes and gives,
waves, gusts, primitives, solids and the grid."""
import numpy as np
import pytest

import boreas

import c_api
from conftest import GUSTY_WAVE, SMALL_GRID, points


def test_sample_is_bit_identical_to_the_c_api(capi):
    pts = points(5000, seed=1)
    c_world = c_api.CWorld(capi, SMALL_GRID, [GUSTY_WAVE])
    try:
        with boreas.World(grid=SMALL_GRID, waves=[GUSTY_WAVE]) as world:
            # A gust makes the grid's part of the wind non-zero: both layers are compared.
            world.wind.add_gust(direction=(0, 0, 1), strength=3.0, rise=0.1, hold=5.0)
            c_world.add_gust(direction=(0, 0, 1), strength=3.0, rise=0.1, hold=5.0)
            for _ in range(5):
                world.step(0.05)
                c_world.step(0.05)
            ours = world.wind.sample(pts)
            theirs = c_world.sample(pts)
            assert ours.tobytes() == theirs.tobytes()
            assert np.abs(ours[:, 2]).max() > 0.1, "the gust reached the grid"
            assert world.state_hash() == c_world.state_hash()
    finally:
        c_world.close()


def test_sample_returns_float32_n_by_3(world):
    out = world.wind.sample(points(7))
    assert out.dtype == np.float32
    assert out.shape == (7, 3)
    assert out.flags.c_contiguous
    # The steady wave alone: 6 m/s along +x everywhere.
    np.testing.assert_allclose(out, np.tile([6.0, 0.0, 0.0], (7, 1)), atol=1e-5)


def test_sample_converts_other_dtypes_and_layouts_once(world):
    pts = points(100, seed=2)
    expected = world.wind.sample(pts)
    as_float64 = pts.astype(np.float64)
    fortran = np.asfortranarray(pts)
    strided = np.zeros((100, 6), np.float32)
    strided[:, ::2] = pts
    for variant in (as_float64, fortran, strided[:, ::2], pts.tolist()):
        assert world.wind.sample(variant).tobytes() == expected.tobytes()


def test_sample_with_a_gusty_wave_varies_in_space(world):
    world.wind.set_waves([GUSTY_WAVE])
    out = world.wind.sample(points(200, seed=3))
    assert np.ptp(np.linalg.norm(out, axis=1)) > 0.5


def test_sample_writes_into_out_without_a_copy(world):
    pts = points(64, seed=4)
    out = np.full((64, 3), np.nan, np.float32)
    result = world.wind.sample(pts, out=out)
    assert result is out
    assert np.shares_memory(result, out)
    assert not np.isnan(out).any()
    assert out.tobytes() == world.wind.sample(pts).tobytes()


def test_sample_into_the_points_own_array(world):
    pts = points(32, seed=5)
    expected = world.wind.sample(pts)
    result = world.wind.sample(pts, out=pts)
    assert result is pts
    assert pts.tobytes() == expected.tobytes()


def test_sample_of_no_points(world):
    out = world.wind.sample(np.zeros((0, 3), np.float32))
    assert out.shape == (0, 3) and out.dtype == np.float32


@pytest.mark.parametrize("bad", [np.zeros(3), np.zeros((4, 2)), np.zeros((2, 3, 1)), [[1, 2]]])
def test_sample_refuses_wrong_shapes(world, bad):
    with pytest.raises(ValueError, match=r"shape \(N, 3\)"):
        world.wind.sample(bad)


def test_sample_refuses_non_numbers(world):
    with pytest.raises(TypeError):
        world.wind.sample([["a", "b", "c"]])
    with pytest.raises(TypeError):
        world.wind.sample(None)


def _readonly(a):
    a.flags.writeable = False
    return a


@pytest.mark.parametrize("make_out", [
    lambda: np.zeros((4, 3), np.float64),              # wrong dtype
    lambda: np.zeros((5, 3), np.float32),              # wrong length
    lambda: np.zeros((4, 4), np.float32),              # wrong width
    lambda: np.asfortranarray(np.zeros((4, 3), np.float32)),  # not C-contiguous
    lambda: np.zeros((4, 6), np.float32)[:, ::2],      # strided
    lambda: _readonly(np.zeros((4, 3), np.float32)),  # read-only
])
def test_sample_refuses_a_wrong_out(world, make_out):
    with pytest.raises(ValueError, match="out must"):
        world.wind.sample(points(4), out=make_out())


def unaligned(n):
    """A C-contiguous float32 (n, 3) view at an odd byte offset: not aligned."""
    raw = np.zeros(n * 12 + 1, np.uint8)
    a = raw[1:].view(np.float32).reshape(n, 3)
    assert a.flags.c_contiguous and not a.flags.aligned
    return a


def test_unaligned_points_are_copied_once_and_an_unaligned_out_is_refused(world):
    points = unaligned(64)
    points[:] = np.random.default_rng(3).uniform(-4, 4, size=(64, 3))
    expected = world.wind.sample(np.ascontiguousarray(points))
    assert world.wind.sample(points).tobytes() == expected.tobytes()
    with pytest.raises(ValueError, match="out must be aligned"):
        world.wind.sample(expected, out=unaligned(64))


def test_sample_refuses_an_out_that_is_not_an_array(world):
    with pytest.raises(TypeError, match="out must be a numpy.ndarray"):
        world.wind.sample(points(2), out=[[0, 0, 0], [0, 0, 0]])


def test_sample_refuses_nan_points_with_the_library_message(world):
    pts = points(3)
    pts[1, 2] = np.nan
    with pytest.raises(boreas.InvalidArgumentError, match="point 1") as info:
        world.wind.sample(pts)
    assert info.value.status == 1
    assert info.value.status_name == "BOREAS_ERROR_INVALID_ARGUMENT"
    assert isinstance(info.value, ValueError)


def test_set_waves_replaces_and_blends(world):
    p = np.array([[0.0, 1.0, 0.0]], np.float32)
    world.wind.set_waves([boreas.Wave(direction=(0, 1), amplitude=2.0, sharpness=0.0)], blend=1.0)
    world.step(0.5)
    halfway = world.wind.sample(p)[0]
    world.step(0.6)
    after = world.wind.sample(p)[0]
    np.testing.assert_allclose(after, [0.0, 0.0, 2.0], atol=1e-5)
    assert 0.0 < halfway[0] < 6.0 and 0.0 < halfway[2] < 2.0, "both sets sound mid-blend"
    world.wind.set_waves([])
    np.testing.assert_allclose(world.wind.sample(p), 0.0, atol=1e-6)


def test_set_waves_refuses_one_wave_not_in_a_list(world):
    with pytest.raises(TypeError, match="sequence of waves"):
        world.wind.set_waves(boreas.Wave())


def test_wave_fields_are_checked_by_name(world):
    with pytest.raises(TypeError, match="no field 'amplitud'"):
        world.wind.set_waves([{"amplitud": 1.0}])
    with pytest.raises(boreas.InvalidArgumentError):
        world.wind.set_waves([{"wavelength": -1.0}])


def test_the_limits_are_the_librarys(world):
    """boreas.WIND_MAX_WAVES, WIND_MAX_SPEED and STEP_MAX_SECONDS: at the limit accepted,
    past it refused."""
    world.wind.set_waves([boreas.Wave()] * boreas.WIND_MAX_WAVES)
    with pytest.raises(boreas.InvalidArgumentError, match=str(boreas.WIND_MAX_WAVES)):
        world.wind.set_waves([boreas.Wave()] * (boreas.WIND_MAX_WAVES + 1))
    world.wind.set_waves([boreas.Wave(amplitude=boreas.WIND_MAX_SPEED)])
    with pytest.raises(boreas.InvalidArgumentError, match="amplitude"):
        world.wind.set_waves([boreas.Wave(amplitude=boreas.WIND_MAX_SPEED * 1.001)])
    with pytest.raises(boreas.InvalidArgumentError, match="dt"):
        world.step(boreas.STEP_MAX_SECONDS * 1.001)
    assert isinstance(boreas.WIND_SAMPLE_MAX_POINTS, int)
    assert boreas.GRID_MAX_CELLS >= boreas.GRID_MAX_RESOLUTION


def test_grid_round_trips_the_definition(world):
    grid = world.wind.grid
    assert isinstance(grid, boreas.Grid)
    assert grid.origin == SMALL_GRID["origin"]
    assert grid.cell_size == SMALL_GRID["cell_size"]
    assert grid.resolution == SMALL_GRID["resolution"]
    assert grid.edge_fade == boreas.Grid().edge_fade
    assert grid.follow_focus is False


def test_wind_sampling_defaults_to_exact(world):
    assert boreas.Grid().wind_sampling == "exact"
    assert boreas.defaults()["grid"]["wind_sampling"] == "exact"
    assert world.wind.grid.wind_sampling == "exact"


def test_interpolated_wind_sampling_reaches_the_plants_only(capi):
    # The C struct's last field through ctypes: 1 is BOREAS_WIND_SAMPLING_INTERPOLATED.
    c_world = c_api.CWorld(capi, dict(SMALL_GRID, wind_sampling=1), [GUSTY_WAVE])
    try:
        with boreas.World(grid=boreas.Grid(**SMALL_GRID, wind_sampling="interpolated"),
                          waves=[GUSTY_WAVE]) as world, \
                boreas.World(grid=SMALL_GRID, waves=[GUSTY_WAVE]) as exact:
            assert world.wind.grid.wind_sampling == "interpolated"
            tree = world.add_tree("quaking_aspen", (1.0, 0.0, -1.0))
            exact_tree = exact.add_tree("quaking_aspen", (1.0, 0.0, -1.0))
            c_world.add_tree("quaking_aspen", (1.0, 0.0, -1.0))
            for _ in range(4):
                for w in (world, exact, c_world):
                    w.step(1 / 30)
            assert world.state_hash() == c_world.state_hash()
            # The tree read the sums between column centers: a sharp wave bends it otherwise.
            assert tree.branches.tobytes() != exact_tree.branches.tobytes()
            # Sampling is exact in either mode.
            pts = points(500, seed=5)
            assert world.wind.sample(pts).tobytes() == exact.wind.sample(pts).tobytes()
    finally:
        c_world.close()


def test_wind_sampling_is_checked_by_name():
    with pytest.raises(ValueError, match="grid.wind_sampling must be one of 'exact', "
                                         "'interpolated', not 'cubic'"):
        boreas.World(grid=boreas.Grid(**SMALL_GRID, wind_sampling="cubic"))
    with pytest.raises(TypeError, match="grid.wind_sampling must be one of"):
        boreas.World(grid=dict(SMALL_GRID, wind_sampling=1))


def test_grid_values_layout_and_a_calm_grid_is_zero(world):
    cells = world.wind.grid_values()
    nx, ny, nz = SMALL_GRID["resolution"]
    assert cells.shape == (nz, ny, nx, 4)
    assert cells.dtype == np.float32
    world.step(0.1)
    assert not world.wind.grid_values().any(), "no primitive, gust or solid: the grid stays zero"


def test_solid_box_zeroes_the_wind_inside_and_marks_cells(world):
    world.wind.add_solid_box((-1.0, 0.0, -1.0), (1.0, 1.0, 1.0))
    inside = np.array([[0.5, 0.5, 0.5]], np.float32)
    outside = np.array([[3.5, 0.5, 3.5]], np.float32)
    assert not world.wind.sample(inside).any()
    assert world.wind.sample(outside)[0, 0] == pytest.approx(6.0)
    solid = world.wind.grid_values()[..., 3]
    # Cells whose centers lie in the box: x and z cells 3, 4 (centers -0.5, 0.5), y cell 0.
    assert solid.sum() == 4
    assert solid[3:5, 0, 3:5].all()
    world.wind.set_solid_mask(None)
    assert not world.wind.grid_values()[..., 3].any()


def test_solid_mask_in_grid_values_layout(world):
    nx, ny, nz = SMALL_GRID["resolution"]
    mask = np.zeros((nz, ny, nx), bool)
    mask[2, 1, 5] = True
    world.wind.set_solid_mask(mask)
    np.testing.assert_array_equal(world.wind.grid_values()[..., 3] == 1.0, mask)
    with pytest.raises(boreas.InvalidArgumentError):
        world.wind.set_solid_mask(np.zeros(5, bool))


def test_gusts_and_primitives_drive_the_grid_and_are_removed(calm_world):
    gust = calm_world.wind.add_gust(direction=(0, 0, 1), strength=4.0, rise=0.0, hold=10.0)
    vortex = calm_world.wind.add_primitive("vortex", position=(0, 1, 0), direction=(0, 1, 0),
                                           strength=3.0, radius=3.0)
    assert isinstance(gust, boreas.Gust) and isinstance(vortex, boreas.FlowPrimitive)
    for _ in range(5):
        calm_world.step(0.1)
    assert np.abs(calm_world.wind.grid_values()[..., :3]).max() > 0.5
    gust.remove()
    vortex.remove()
    with pytest.raises(boreas.NotFoundError):
        gust.remove()
    with pytest.raises(boreas.NotFoundError):
        vortex.remove()


def test_primitive_type_is_checked(calm_world):
    with pytest.raises(ValueError, match="'uniform', 'source', 'sink', 'vortex'"):
        calm_world.wind.add_primitive("tornado")
