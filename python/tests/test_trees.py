"""Trees: the arrays they give, their motion in the wind, batches, and stale handles."""
import numpy as np
import pytest

import boreas

from conftest import SMALL_GRID, STEADY_WAVE

# A 50 m/s storm: every built-in species loses branches (README, "Storms").
STEADY_WAVE_50 = dict(STEADY_WAVE, amplitude=50.0)


def test_branch_leaf_and_mesh_arrays(world):
    tree = world.add_tree("quaking_aspen", position=(1.0, 0.0, 2.0))
    branches = tree.branches
    assert branches.dtype == boreas.BRANCH_DTYPE
    assert branches.dtype.fields["control_points"][0].shape == (4, 3)
    assert branches.dtype.fields["control_points"][0].base == np.float32
    assert branches.dtype.fields["orientation"][0].shape == (3,)
    for name in ("level", "parent"):
        assert branches.dtype.fields[name][0] == np.int32
    for name in ("parent_v", "radius", "length"):
        assert branches.dtype.fields[name][0] == np.float32
    assert branches.ndim == 1 and len(branches) > 10
    # Invariants of the layout: the trunk first, at the tree's position; parents before
    # children, one level up; radii and lengths positive.
    assert branches["level"][0] == 0 and branches["parent"][0] == -1
    np.testing.assert_allclose(branches["control_points"][0, 0], (1.0, 0.0, 2.0), atol=1e-6)
    children = branches[1:]
    assert (children["parent"] < np.arange(1, len(branches))).all()
    assert (branches["level"][children["parent"]] == children["level"] - 1).all()
    assert (branches["radius"] > 0).all() and (branches["length"] > 0).all()

    leaves = tree.leaves
    assert leaves.dtype == boreas.LEAF_DTYPE and len(leaves) > 0
    assert leaves["branch"].min() >= 0 and leaves["branch"].max() < len(branches)
    np.testing.assert_allclose(np.linalg.norm(leaves["axis"], axis=1), 1.0, atol=1e-4)

    occlusion = tree.leaf_occlusion()
    assert occlusion.dtype == np.float32 and occlusion.shape == (len(leaves), 3)
    assert (occlusion > 0).all() and (occlusion <= 1 + 1e-6).all()
    # Green passes the leaves best: the light inside the crown is greener.
    assert (occlusion[:, 1] >= occlusion[:, 0]).all() and (occlusion[:, 0] >= occlusion[:, 2]).all()
    # Opaque leaves let less through than translucent ones.
    assert (tree.leaf_occlusion((0.0, 0.0, 0.0)) <= tree.leaf_occlusion((0.5, 0.5, 0.5)) + 1e-6).all()
    with pytest.raises(boreas.InvalidArgumentError, match=r"transmittance\[0\]"):
        tree.leaf_occlusion((2.0, 0.1, 0.1))

    vertices, triangles = tree.mesh()
    assert vertices.dtype == boreas.VERTEX_DTYPE
    assert vertices.dtype.fields["uv"][0].shape == (2,)
    assert triangles.dtype == np.uint32 and triangles.ndim == 2 and triangles.shape[1] == 3
    assert triangles.max() < len(vertices)
    np.testing.assert_allclose(np.linalg.norm(vertices["normal"], axis=1), 1.0, atol=1e-3)


def test_a_tree_bends_downwind_in_a_steady_wind(world):
    tree = world.add_tree("quaking_aspen", mode="exact")
    rest = tree.branches["control_points"][:, 3].copy()   # (B, 3) tips
    for _ in range(10):
        world.step(1 / 30)
    bent = tree.branches["control_points"][:, 3]
    moved = bent - rest
    assert np.abs(moved).max() > 0.01
    # The wind blows along +x: tips move that way on the whole, not across it.
    assert moved[:, 0].mean() > 0.0
    assert moved[:, 0].mean() > 5 * abs(moved[:, 2].mean())


def test_a_tree_does_not_move_in_calm_air(calm_world):
    tree = calm_world.add_tree("quaking_aspen")
    rest = tree.branches["control_points"].copy()
    for _ in range(3):
        calm_world.step(0.1)
    # Re-attached on the device: the same rest shape up to float rounding (~1e-6 m).
    np.testing.assert_allclose(tree.branches["control_points"], rest, rtol=0, atol=2e-5)


def test_add_tree_arguments_are_checked(world):
    with pytest.raises(boreas.InvalidArgumentError, match="unknown species 'oak'"):
        world.add_tree("oak")
    with pytest.raises(boreas.FileError):
        world.add_tree("/nonexistent/species.json")
    with pytest.raises(ValueError, match="tree.mode must be one of 'lagged', 'exact'"):
        world.add_tree(mode="fast")
    with pytest.raises(ValueError, match="tree.position must be 3 numbers"):
        world.add_tree(position=(1, 2))
    with pytest.raises(boreas.InvalidArgumentError, match="scale"):
        world.add_tree(scale=-1.0)
    with pytest.raises(TypeError, match=r"tree.levels\[0\] has no field 'stifness'"):
        world.add_tree(levels=[{"stifness": 2}])
    with pytest.raises(ValueError, match="more than 4"):
        world.add_tree(levels=[{}] * 5)


def test_levels_change_the_mesh(world):
    coarse = world.add_tree("quaking_aspen", levels=[{"rings": 2, "sides": 3}])
    fine = world.add_tree("quaking_aspen")
    assert len(coarse.mesh()[0]) < len(fine.mesh()[0])


def test_add_trees_rows_and_columns_give_the_same_trees(world):
    positions = [(0.0, 0.0, 0.0), (2.0, 0.0, 0.0), (0.0, 0.0, 2.0)]
    by_columns = world.add_trees(species="quaking_aspen", position=positions, seed=[1, 2, 3])
    by_rows = world.add_trees([{"species": "quaking_aspen", "position": p, "seed": s}
                               for p, s in zip(positions, [1, 2, 3])])
    assert len(by_columns) == len(by_rows) == 3
    for a, b in zip(by_columns, by_rows):
        assert a != b
        assert a.branches.tobytes() == b.branches.tobytes()
    assert by_columns[0].branches.tobytes() != by_columns[1].branches.tobytes()


def test_add_trees_is_all_or_nothing(world):
    before = world.state_hash()
    with pytest.raises(boreas.InvalidArgumentError, match=r"defs\[1\]|\[1\]"):
        world.add_trees([{"position": (0, 0, 0)}, {"scale": -2.0}])
    assert world.state_hash() == before


def test_add_trees_columns_are_checked(world):
    with pytest.raises(ValueError, match="differ in length"):
        world.add_trees(position=[(0, 0, 0), (1, 0, 0)], seed=[1, 2, 3])
    with pytest.raises(ValueError, match="one column with a value per tree"):
        world.add_trees(species="quaking_aspen")
    with pytest.raises(TypeError, match="unexpected keyword argument 'colour'"):
        world.add_trees(position=[(0, 0, 0)], colour="red")


def test_a_removed_tree_raises_not_found(world):
    tree = world.add_tree("quaking_aspen")
    other = world.add_tree("quaking_aspen", position=(3, 0, 0))
    tree.remove()
    for call in (lambda: tree.branches, lambda: tree.leaves, tree.mesh, tree.remove):
        with pytest.raises(boreas.NotFoundError, match="tree") as info:
            call()
        assert info.value.status == 5 and isinstance(info.value, LookupError)
    assert len(other.branches) > 0, "the other tree is untouched"


def test_a_tree_of_another_world_is_not_found(world, calm_world):
    tree = world.add_tree("quaking_aspen")
    stranger = boreas.Tree(calm_world, tree.id)
    with pytest.raises(boreas.NotFoundError):
        stranger.branches


def test_handles_compare_by_world_and_id(world):
    a = world.add_tree("quaking_aspen")
    assert a == boreas.Tree(world, a.id)
    assert hash(a) == hash(boreas.Tree(world, a.id))
    assert a != world.add_tree("quaking_aspen")
    assert a.world is world


def test_a_storm_breaks_branches_and_heal_mends_them():
    storm = dict(STEADY_WAVE_50)
    with boreas.World(grid=SMALL_GRID, waves=[storm]) as w:
        tree = w.add_tree("black_tupelo", mode="exact")
        rest = tree.branches["control_points"].copy()
        assert tree.branches.dtype.fields["broken"][0] == np.int32
        assert (tree.branches["broken"] == 0).all()
        counted = 0
        for _ in range(6):
            w.step(1 / 60)
            counted += w.step_stats.branches_broken
        broken = tree.branches["broken"]
        assert set(np.unique(broken)) <= {0, 1}
        # Every break counted by the step stats once; a 50 m/s storm breaks some.
        assert counted == broken.sum() > 0
        tree.heal()
        healed = tree.branches
        assert (healed["broken"] == 0).all()
        np.testing.assert_array_equal(healed["control_points"], rest)
