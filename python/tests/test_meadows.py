"""Meadows of underbrush, colliders and emitters: arrays, motion in the wind, handles."""
import numpy as np
import pytest

import boreas

SMALL_MEADOW = {"size": (1.5, 1.5), "density": 120.0}


def test_components_and_vertices_arrays(world):
    meadow = world.add_meadow(**SMALL_MEADOW)
    c = meadow.components
    assert c.dtype == boreas.COMPONENT_DTYPE
    for name in ("base", "center_of_mass", "velocity", "rest_center_of_mass"):
        assert c.dtype.fields[name][0].shape == (3,)
        assert c.dtype.fields[name][0].base == np.float32
    for name in ("broken", "species", "part", "parent"):
        assert c.dtype.fields[name][0] == np.int32
    assert len(c) > 20
    # At rest when planted; parents come before their children.
    assert (c["center_of_mass"] == c["rest_center_of_mass"]).all()
    assert not c["velocity"].any()
    assert (c["parent"] < np.arange(len(c))).all()

    vertices, strips = meadow.vertices()
    assert vertices.dtype == boreas.MEADOW_VERTEX_DTYPE
    assert vertices.shape == (len(c), boreas.MEADOW_VERTEX_STRIDE)
    assert strips.dtype == np.int32 and strips.shape == (len(c),)
    assert (strips >= 4).all() and (strips <= boreas.MEADOW_VERTEX_STRIDE).all()
    assert (strips % 2 == 0).all()
    # Far away, the LOD culls every strip.
    _, far = meadow.vertices(camera=(1e4, 0.0, 0.0))
    assert not far.any()


def test_species_given_three_ways(world):
    as_pairs = world.add_meadow(species=[("clover", 1.0), ("fern", 3.0)], **SMALL_MEADOW)
    as_dict = world.add_meadow(species={"clover": 1.0, "fern": 3.0}, **SMALL_MEADOW)
    assert as_pairs.components.tobytes() == as_dict.components.tobytes()
    names = world.add_meadow(species=["daisy"], **SMALL_MEADOW).components
    assert set(names["species"].tolist()) == {0}
    with pytest.raises(boreas.FileError, match="'nope'"):
        world.add_meadow(species=["nope"], **SMALL_MEADOW)
    with pytest.raises(TypeError, match="meadow has no field 'terrain_image'"):
        world._core.add_meadow({"terrain_image": "x.png"})


def test_a_meadow_leans_downwind(world):
    meadow = world.add_meadow(species=["meadow_grass"], **SMALL_MEADOW)
    for _ in range(15):
        world.step(1 / 30)
    c = meadow.components
    lean = c["center_of_mass"] - c["rest_center_of_mass"]
    assert lean[:, 0].mean() > 1e-3, "the wind blows along +x"
    assert lean[:, 0].mean() > 5 * abs(lean[:, 2].mean())


def test_parts_give_each_components_look(world):
    meadow = world.add_meadow(species=["daisy", "clover"], **SMALL_MEADOW)
    parts = meadow.parts
    assert parts.dtype == boreas.MEADOW_PART_DTYPE
    names = [(int(p["species"]), p["name"].decode()) for p in parts]
    assert (0, "petal") in names and (1, "leaflet") in names
    petal = parts[[n == (0, "petal") for n in names]][0]
    assert petal["color"].min() > 0.8, "daisy petals are white"
    keys = {(int(p["species"]), int(p["part"])) for p in parts}
    c = meadow.components
    assert {(int(s), int(p)) for s, p in zip(c["species"], c["part"])} <= keys


def test_add_meadows_in_one_call(world):
    a, b = world.add_meadows([dict(SMALL_MEADOW, center=(-2, 0, 0)),
                              dict(SMALL_MEADOW, center=(2, 0, 0))])
    assert a.components["base"][:, 0].mean() < 0 < b.components["base"][:, 0].mean()


def test_a_removed_meadow_raises_not_found(world):
    meadow = world.add_meadow(**SMALL_MEADOW)
    meadow.remove()
    with pytest.raises(boreas.NotFoundError, match="meadow"):
        meadow.components
    with pytest.raises(boreas.NotFoundError):
        meadow.vertices()


def test_a_collider_pushes_grass_aside_and_moves(calm_world):
    meadow = calm_world.add_meadow(species=["meadow_grass"], **SMALL_MEADOW)
    rest = meadow.components
    # A ball rolled into the middle of the grass: at the mean of the components' bases.
    middle = rest["base"].mean(axis=0)
    distance = np.linalg.norm((rest["base"] - middle)[:, [0, 2]], axis=1)
    spot = rest["base"][np.argmin(distance)]
    center = (float(spot[0]), float(spot[1]) + 0.1, float(spot[2]))
    ball = calm_world.add_collider(center=center, radius=0.3)
    assert ball.position == pytest.approx(center)
    for _ in range(5):
        calm_world.step(1 / 30)
    c = meadow.components
    moved = np.linalg.norm(c["center_of_mass"] - c["rest_center_of_mass"], axis=1)
    from_ball = np.linalg.norm((c["base"] - spot)[:, [0, 2]], axis=1)
    near, far = from_ball < 0.15, from_ball > 0.6
    assert near.any() and far.any()
    assert moved[near].mean() > 1e-3
    assert moved[near].mean() > 10 * moved[far].mean(), "calm air: only the ball moves grass"
    ball.position = (5.0, 0.1, 5.0)
    assert ball.position == pytest.approx((5.0, 0.1, 5.0))
    with pytest.raises(boreas.InvalidArgumentError):
        ball.position = (np.nan, 0.0, 0.0)
    assert ball.position == pytest.approx((5.0, 0.1, 5.0)), "a refused move keeps the position"
    ball.remove()
    with pytest.raises(boreas.NotFoundError):
        ball.position = (0.0, 0.0, 0.0)


def test_an_emitter_pushes_grass(calm_world):
    meadow = calm_world.add_meadow(species=["meadow_grass"], **SMALL_MEADOW)
    rain = calm_world.add_emitter((0.0, 0.5, 0.0), area_radius=0.7, event_radius=0.2,
                                  impulse=(0.0, -2e-3, 0.0), rate=400.0)
    for _ in range(5):
        calm_world.step(1 / 30)
    assert np.abs(meadow.components["velocity"]).max() > 0.0
    rain.position = (1.0, 0.5, 1.0)
    rain.remove()
    with pytest.raises(boreas.NotFoundError):
        rain.remove()


def test_plants_stand_on_a_terrain_array_and_follow_a_nutrient_array(world):
    # A ramp rising along +x by terrain_relief: every plant's base is on it, within the
    # ramp's slope (0.5) times a plant's spread of a few cm.
    ramp = np.array([[0.0, 1.0], [0.0, 1.0]])  # float64, converted once
    meadow = world.add_meadow(species=["meadow_grass"], size=(4.0, 4.0), density=50.0,
                              terrain=ramp, terrain_relief=2.0)
    c = meadow.components
    roots = c[c["parent"] < 0]
    assert len(roots) > 50
    expected = 2.0 * (roots["base"][:, 0] + 2.0) / 4.0
    assert np.abs(roots["base"][:, 1] - expected).max() < 0.03
    # Nutrients rich on the +x half only (H, W, 3): nothing grows on the -x half.
    rich = np.zeros((32, 32, 3), np.float32)
    rich[:, 16:, :] = 0.9
    grown = world.add_meadow(size=(4.0, 4.0), center=(10.0, 0.0, 0.0), density=200.0,
                             nutrients=rich).components
    roots = grown[grown["parent"] < 0]
    assert (roots["base"][:, 0] > 10.0 - 0.1).all()
    assert len(roots) > 100


def test_bad_terrain_arrays_are_refused_naming_the_field(world):
    before = world.state_hash()
    with pytest.raises(ValueError, match="terrain must have shape"):
        world.add_meadow(size=(1.0, 1.0), terrain=np.zeros(4, np.float32))
    with pytest.raises(TypeError, match="nutrients must hold numbers"):
        world.add_meadow(size=(1.0, 1.0), nutrients=np.array([["a", "b"]]))
    bad = np.zeros((2, 2), np.float32)
    bad[1, 0] = np.nan
    with pytest.raises(boreas.InvalidArgumentError,
                       match=r"meadow_def.terrain: pixel \(0, 1\) channel 0 is not a finite"):
        world.add_meadow(size=(1.0, 1.0), terrain=bad)
    assert world.state_hash() == before, "a refused meadow leaves the world as it was"
