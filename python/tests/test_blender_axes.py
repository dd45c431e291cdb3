"""The Blender add-on's bpy-free math (boreas.blender.axes and .skin): the axes' change is
a proper rotation that maps boreas's up to Blender's, and a joint's quaternion becomes the
rotation matrix it stands for (against rotations built from axis and angle in double)."""
import math

import numpy as np

from boreas.blender.axes import (TO_BLENDER, frames_to_blender, points_to_blender,
                                 points_to_boreas)
from boreas.blender.skin import joint_frames

JOINT = np.dtype([("position", "<f4", 3), ("rotation", "<f4", 4)])


def rotation(axis, angle):
    """Rodrigues' formula, double."""
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    cross = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(angle) * cross + (1 - math.cos(angle)) * cross @ cross


def test_axes_are_a_proper_rotation_with_y_up_to_z_up():
    assert np.allclose(TO_BLENDER @ TO_BLENDER.T, np.eye(3))
    assert np.isclose(np.linalg.det(TO_BLENDER), 1.0)
    assert np.allclose(points_to_blender([0, 1, 0]), [0, 0, 1])   # up
    assert np.allclose(points_to_blender([0, 0, 1]), [0, -1, 0])  # boreas +z is Blender -y
    p = np.random.default_rng(1).normal(size=(10, 3))
    assert np.allclose(points_to_boreas(points_to_blender(p)), p)


def test_a_turn_about_boreas_up_is_the_same_turn_about_blender_up():
    a = 0.7
    turned = points_to_blender(rotation([0, 1, 0], a) @ [1.0, 0.0, 0.0])
    assert np.allclose(turned, rotation([0, 0, 1], a) @ [1.0, 0.0, 0.0])


def test_joint_quaternions_become_their_rotations():
    rng = np.random.default_rng(7)
    joints = np.zeros(20, JOINT)
    expected = []
    for j in range(len(joints)):
        axis, angle = rng.normal(size=3), rng.uniform(-math.pi, math.pi)
        axis /= np.linalg.norm(axis)
        joints["rotation"][j] = [*(math.sin(angle / 2) * axis), math.cos(angle / 2)]  # x y z w
        joints["position"][j] = rng.normal(size=3)
        expected.append(rotation(axis, angle))
    frames = joint_frames(joints)
    assert np.allclose(frames[:, :3, :3], np.array(expected), atol=1e-6)
    assert np.allclose(frames[:, :3, 3], joints["position"])
    assert np.allclose(frames[:, 3], [0, 0, 0, 1])
    moved = frames_to_blender(frames)
    assert np.allclose(moved[:, :3, 3], points_to_blender(joints["position"]), atol=1e-6)
    assert np.allclose(moved[:, :3, :3], TO_BLENDER @ frames[:, :3, :3])


def test_rotations_become_their_quaternions_and_stay_on_one_side():
    from boreas.blender.rotations import continuous, quaternions
    rng = np.random.default_rng(3)
    axes = rng.normal(size=(200, 3))
    axes /= np.linalg.norm(axes, axis=1, keepdims=True)
    angles = rng.uniform(-math.pi, math.pi, 200)
    angles[:4] = [0.0, math.pi, -math.pi + 1e-9, 1e-9]   # the cases a trace formula fails
    matrices = np.array([rotation(a, t) for a, t in zip(axes, angles)])
    q = quaternions(matrices)
    expected = np.column_stack([np.cos(angles / 2), np.sin(angles / 2)[:, None] * axes])
    same = np.minimum(np.abs(q - expected).max(1), np.abs(q + expected).max(1))
    assert same.max() < 1e-9
    # a slow turn through 3 pi keyed per step: consecutive keys never jump to the far side
    turn = np.linspace(0, 3 * math.pi, 60)
    keys = continuous(quaternions(np.array([rotation([0, 0, 1], t) for t in turn]))[:, None])
    assert (np.einsum("ni,ni->n", keys[1:, 0], keys[:-1, 0]) > 0).all()
