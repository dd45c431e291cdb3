"""boreas's axes (Y up) and Blender's (Z up): a boreas point (x, y, z) is Blender's
(x, -z, y), a proper rotation, so frames, rotations about the up axis and handedness carry
over unchanged. No bpy here: the conversions work on NumPy arrays."""
import numpy as np

#: Blender from boreas: v_blender = TO_BLENDER @ v_boreas.
TO_BLENDER = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])


def points_to_blender(points):
    """(..., 3) boreas -> (..., 3) Blender, float64."""
    return np.asarray(points, dtype=np.float64) @ TO_BLENDER.T


def points_to_boreas(points):
    """(..., 3) Blender -> (..., 3) boreas, float64."""
    return np.asarray(points, dtype=np.float64) @ TO_BLENDER


def frames_to_blender(frames):
    """(..., 4, 4) rigid frames in boreas's world -> the same frames in Blender's world
    (columns: the frame's axes and origin)."""
    frames = np.asarray(frames, dtype=np.float64)
    out = np.array(frames)
    out[..., :3, :] = np.einsum("ij,...jk->...ik", TO_BLENDER, frames[..., :3, :])
    return out
