"""Colliders from Python: spheres, capsules and boxes with a pose and velocities, moved by
the world; the Collider handle's pose, velocity and contact; bad input refused naming the
field, the world unchanged."""
import math

import numpy as np
import pytest

import boreas
from test_mesh_trees import write_tube_tree


def test_the_sphere_call_still_works(calm_world):
    ball = calm_world.add_collider((0.5, 0.2, -0.5), 0.3)
    assert ball.position == pytest.approx((0.5, 0.2, -0.5))
    assert ball.pose["orientation"] == pytest.approx((0.0, 0.0, 0.0, 1.0))
    calm_world.step(1 / 30)
    assert ball.position == pytest.approx((0.5, 0.2, -0.5)), "no velocity: it stays"


def test_a_box_given_a_velocity_moves_and_turns(calm_world):
    box = calm_world.add_collider(center=(0.0, 0.9, 0.0), shape="box",
                                  half_extents=(2.25, 0.75, 0.9), velocity=(5.0, 0.0, 0.0))
    for _ in range(30):
        calm_world.step(1 / 30)
    assert box.position == pytest.approx((5.0, 0.9, 0.0), abs=1e-4), "5 m/s for 1 s"
    # A quarter turn about +Y over a second.
    box.set_velocity(velocity=(0.0, 0.0, 0.0), angular_velocity=(0.0, math.pi / 2, 0.0))
    for _ in range(30):
        calm_world.step(1 / 30)
    q = box.pose["orientation"]
    assert q == pytest.approx((0.0, math.sin(math.pi / 4), 0.0, math.cos(math.pi / 4)),
                              abs=1e-4)
    assert box.position == pytest.approx((5.0, 0.9, 0.0), abs=1e-4), "turning, not moving"
    box.set_velocity(angular_velocity=(0.0, 0.0, 0.0))  # None keeps the velocity (zero)
    box.set_pose((1.0, 2.0, 3.0))  # keeps the orientation
    assert box.pose["position"] == pytest.approx((1.0, 2.0, 3.0))
    assert box.pose["orientation"] == pytest.approx(q)
    box.set_pose((1.0, 2.0, 3.0), orientation=(0.0, 0.0, 0.0, 1.0))
    assert box.pose["orientation"] == pytest.approx((0.0, 0.0, 0.0, 1.0))


@pytest.mark.parametrize("fields, named", [
    ({"shape": "cone"}, "collider.shape"),
    ({"orientation": (0.0, 0.0, 0.0, 2.0)}, "orientation"),
    ({"orientation": (np.nan, 0.0, 0.0, 1.0)}, "orientation"),
    ({"velocity": (np.nan, 0.0, 0.0)}, r"velocity\[0\]"),
    ({"angular_velocity": (0.0, 1e9, 0.0)}, r"angular_velocity\[1\]"),
    ({"shape": "box", "half_extents": (1.0, -0.5, 1.0)}, r"half_extents\[1\]"),
    ({"shape": "capsule", "radius": 0.0}, "radius"),
    ({"shape": "capsule", "half_height": -1.0}, "half_height"),
    ({"velocity": (1.0, 2.0)}, "velocity"),
])
def test_bad_input_is_refused_naming_the_field(calm_world, fields, named):
    with pytest.raises((ValueError, TypeError), match=named):
        calm_world.add_collider(**fields)
    # The world is unchanged: a step runs, and a good collider comes out as the first.
    calm_world.step(1 / 30)
    good = calm_world.add_collider((0.0, 0.5, 0.0), 0.2)
    assert good.contact == boreas.ColliderContact((0.0, 0.0, 0.0), (0.0, 0.0, 0.0), 0)


def test_bad_moves_are_refused_and_keep_the_collider(calm_world):
    c = calm_world.add_collider((0.0, 0.5, 0.0), 0.2, velocity=(1.0, 0.0, 0.0))
    with pytest.raises(boreas.InvalidArgumentError, match="velocity"):
        c.set_velocity(velocity=(np.inf, 0.0, 0.0))
    with pytest.raises(boreas.InvalidArgumentError, match="orientation"):
        c.set_pose((0.0, 0.0, 0.0), orientation=(0.0, 0.0, 0.0, 0.0))
    calm_world.step(0.5)
    assert c.position == pytest.approx((0.5, 0.5, 0.0)), "the old velocity, from the old pose"


def test_contact_is_readable_and_pushes_back(calm_world, tmp_path):
    model = tmp_path / "tubes.obj"
    write_tube_tree(model)
    tree = calm_world.add_mesh_tree(model, cache=False)
    rest = tree.vertices("trunk")["position"].copy()
    # A capsule walking along -x into the stem at 1.5 m (0.25 -> 0.1 m thick over 6 m).
    walker = calm_world.add_collider(center=(0.6, 1.5, 0.0), radius=0.3, shape="capsule",
                                     half_height=0.6, velocity=(-1.0, 0.0, 0.0))
    assert walker.contact.contacts == 0, "before the first step"
    forces = []
    for _ in range(6):
        calm_world.step(1 / 30)
        contact = walker.contact
        assert isinstance(contact, boreas.ColliderContact)
        forces.append(contact.force[0])
    assert contact.contacts >= 1
    assert forces[-1] > 0.0, "the stem pushes the walker back (+x)"
    assert forces[-1] > forces[0], "harder as it goes deeper"
    moved = tree.vertices("trunk")["position"] - rest
    assert moved[:, 0].min() < -1e-3, "the stem bends away (-x)"
    assert len(contact.torque) == 3
    walker.remove()
    with pytest.raises(boreas.NotFoundError):
        walker.contact
