"""A tree's skin as the add-on uses it: the joints of boreas's own skeleton (Tree.skin and
Tree.joints, boreas_tree_get_joints: the one the glTF export uses too) as 4x4 frames in
Blender's axes, and the binding of the branch mesh and the leaves. No bpy here."""
import numpy as np

from .axes import frames_to_blender


def joint_frames(joints):
    """(J, 4, 4) frames in boreas's world from boreas_joint records: columns x, y (the
    curve's tangent), z and the origin."""
    q = joints["rotation"].astype(np.float64)
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    x, y, z, w = q[:, 0], q[:, 1], q[:, 2], q[:, 3]
    frames = np.zeros((len(q), 4, 4))
    frames[:, 0, 0] = 1 - 2 * (y * y + z * z)
    frames[:, 0, 1] = 2 * (x * y - z * w)
    frames[:, 0, 2] = 2 * (x * z + y * w)
    frames[:, 1, 0] = 2 * (x * y + z * w)
    frames[:, 1, 1] = 1 - 2 * (x * x + z * z)
    frames[:, 1, 2] = 2 * (y * z - x * w)
    frames[:, 2, 0] = 2 * (x * z - y * w)
    frames[:, 2, 1] = 2 * (y * z + x * w)
    frames[:, 2, 2] = 1 - 2 * (x * x + y * y)
    frames[:, :3, 3] = joints["position"]
    frames[:, 3, 3] = 1.0
    return frames


def blender_frames(tree, skin_def):
    """The tree's joints as of the last step: (J, 4, 4) world frames in Blender's axes."""
    return frames_to_blender(joint_frames(tree.joints(**skin_def)))


class Skin:
    """A tree's skeleton and binding, read once at rest.

    parents (J,) int, -1 for the root; branch (J,) int; frames (J, 4, 4) Blender world;
    vertex_joints / vertex_weights (V, 4) for the branch mesh's vertices; leaf_joints /
    leaf_weights (L, 4) for the leaves.
    """

    def __init__(self, tree, skin_def):
        joints, vertex, leaf = tree.skin(**skin_def)
        self.parents = joints["parent"].astype(np.int64)
        self.branch = joints["branch"].astype(np.int64)
        self.frames = frames_to_blender(joint_frames(joints))
        self.vertex_joints = vertex["joints"].astype(np.int64)
        self.vertex_weights = vertex["weights"].astype(np.float64)
        self.leaf_joints = leaf["joints"].astype(np.int64)
        self.leaf_weights = leaf["weights"].astype(np.float64)
