"""Rotation matrices as keyframe quaternions: Blender keys a bone's rotation as a
quaternion (w, x, y, z) per frame. No bpy here."""
import numpy as np


def quaternions(rotations):
    """(..., 3, 3) rotation matrices -> (..., 4) unit quaternions (w, x, y, z), Shepperd's
    method: from the largest of the four squared components, so none divides by a small
    one."""
    r = np.asarray(rotations, dtype=np.float64)
    trace = r[..., 0, 0] + r[..., 1, 1] + r[..., 2, 2]
    squares = np.stack([1 + trace, 1 + 2 * r[..., 0, 0] - trace, 1 + 2 * r[..., 1, 1] - trace,
                        1 + 2 * r[..., 2, 2] - trace], axis=-1) / 4   # w^2, x^2, y^2, z^2
    pick = np.argmax(squares, axis=-1)
    big = np.sqrt(np.take_along_axis(squares, pick[..., None], axis=-1))[..., 0]
    # products of pairs, each from the off-diagonal: 4wx, 4wy, 4wz, 4xy, 4xz, 4yz
    wx, wy = r[..., 2, 1] - r[..., 1, 2], r[..., 0, 2] - r[..., 2, 0]
    wz, xy = r[..., 1, 0] - r[..., 0, 1], r[..., 1, 0] + r[..., 0, 1]
    xz, yz = r[..., 0, 2] + r[..., 2, 0], r[..., 2, 1] + r[..., 1, 2]
    rows = [np.stack([4 * big * big, wx, wy, wz], -1), np.stack([wx, 4 * big * big, xy, xz], -1),
            np.stack([wy, xy, 4 * big * big, yz], -1), np.stack([wz, xz, yz, 4 * big * big], -1)]
    q = np.choose(pick[..., None], rows) / (4 * big[..., None])
    return q / np.linalg.norm(q, axis=-1, keepdims=True)


def continuous(quats):
    """(n, J, 4) quaternions with each one's sign chosen nearest the frame before, so that
    the keys interpolate the short way."""
    out = np.array(quats)
    for k in range(1, len(out)):
        flip = np.einsum("ji,ji->j", out[k], out[k - 1]) < 0
        out[k, flip] *= -1
    return out
