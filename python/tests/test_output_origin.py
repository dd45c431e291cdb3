"""World.set_output_origin: positions handed back relative to a point far from 0, where a
tree 100 km out moves as the same tree at 0 (README, "Far from the origin")."""
import numpy as np
import pytest

import boreas

FAR = (1.0e5, 0.0, -1.0e5)


def test_a_tree_far_out_reads_back_as_the_same_tree_at_zero(world):
    near = world.add_tree("quaking_aspen", position=(0.0, 0.0, 0.0), seed=4)
    far = world.add_tree("quaking_aspen", position=FAR, seed=4)
    rest = near.branches["control_points"].copy()
    for _ in range(30):
        world.step(1.0 / 60.0)
    world.set_output_origin((0.0, 0.0, 0.0))
    a = near.branches["control_points"].copy()
    a_leaves = near.leaves["position"].copy()
    a_mesh = near.mesh()[0]["position"].copy()
    world.set_output_origin(FAR)
    b = far.branches["control_points"]
    assert np.abs(a[:, 3] - rest[:, 3]).max() > 0.01, "the wind should bend the branches"
    # Relative to each tree's base the two are the same, to 1e-4 m (bit for bit in practice).
    np.testing.assert_allclose(b, a, rtol=0, atol=1e-4)
    np.testing.assert_allclose(far.leaves["position"], a_leaves, rtol=0, atol=1e-4)
    np.testing.assert_allclose(far.mesh()[0]["position"], a_mesh, rtol=0, atol=1e-4)


def test_world_coordinates_are_the_default_and_none_restores_them(world):
    tree = world.add_tree("quaking_aspen", position=FAR)
    world.step(1.0 / 60.0)
    world_points = tree.branches["control_points"].astype(np.float64)
    world.set_output_origin(FAR)
    local = tree.branches["control_points"].astype(np.float64)
    # The same points: in float at 100 km (8 mm apart) and relative to the base.
    np.testing.assert_allclose(world_points, local + np.array(FAR), rtol=0, atol=8e-3)
    assert np.abs(local[0, 0]).max() == 0.0, "the trunk stands at the origin given"
    world.set_output_origin(None)
    np.testing.assert_array_equal(tree.branches["control_points"], world_points.astype(np.float32))


def test_a_bad_output_origin_is_refused_by_name(world):
    with pytest.raises(boreas.InvalidArgumentError, match=r"origin\[1\]"):
        world.set_output_origin((0.0, float("nan"), 0.0))
    with pytest.raises(boreas.InvalidArgumentError, match=r"origin\[0\]"):
        world.set_output_origin((2.0e7, 0.0, 0.0))
    with pytest.raises(ValueError, match="3 coordinates"):
        world.set_output_origin((1.0, 2.0))


def test_rays_and_a_collider_far_out_count_from_their_origins(calm_world):
    """Rays count from the output origin (boreas.h, boreas_ray), and a collider's pose
    origin keeps a far position in double: a ray cast at a tree 100 km out from near an
    origin set there measures what the same ray measures at a tree at 0."""
    far = (1.0e5, 0.0, -1.0e5)
    calm_world.add_tree("quaking_aspen", position=(0.0, 0.0, 0.0), seed=4)
    calm_world.add_tree("quaking_aspen", position=far, seed=4)
    calm_world.step(1 / 60)
    origin = np.array([[0.0037, 1.0, 5.0]])
    down_the_trunk = np.array([[0.0, 0.0, -1.0]])
    calm_world.set_output_origin(None)
    a = calm_world.cast_rays(origin, down_the_trunk, 20.0)
    calm_world.set_output_origin(far)
    b = calm_world.cast_rays(origin, down_the_trunk, 20.0)
    assert a["kind"][0] == 1 and b["kind"][0] == 1, "both rays hit a trunk"
    assert a["distance"][0] == pytest.approx(b["distance"][0], abs=1e-4)
    ball = calm_world.add_collider((0.2537, 1.5, 0.0), 0.25, origin=far)
    assert ball.pose["origin"] == pytest.approx(far)
    assert ball.position[0] == pytest.approx(100000.2537, abs=1e-9), "no float rounds it"
