"""A tree in Blender: an armature with a bone per joint of the tree's skin and, parented
to it, the branch mesh and the leaves weighted to those bones (vertex groups named as the
bones); the bake keys every bone every frame from boreas's joints."""
import bpy
import numpy as np
from mathutils import Matrix

from .axes import points_to_blender
from .mesh_data import leaf_geometry, new_mesh
from .rotations import continuous, quaternions
from .skin import Skin

BARK_COLOR = (0.33, 0.25, 0.18, 1.0)
LEAF_COLOR = (0.22, 0.42, 0.12, 1.0)


def bone_names(branches):
    """One name per joint, from its branch index (joints of a branch base to tip): the
    branch's index and the joint's place along it."""
    names, along = [], {}
    for branch in branches:
        k = along.get(int(branch), 0)
        along[int(branch)] = k + 1
        names.append(f"b{int(branch)}.{k}")
    return names


def _material(name, color):
    material = bpy.data.materials.get(name) or bpy.data.materials.new(name)
    material.diffuse_color = color
    return material


def _build_bones(armature, skin, names):
    """Edit bones at the joints' rest frames (the armature's space is the tree's, its base
    at the origin), each as long as the way to the next joint on its branch."""
    bones = armature.edit_bones
    origins = skin.frames[:, :3, 3]
    for j, name in enumerate(names):
        bone = bones.new(name)
        bone.head = (0.0, 0.0, 0.0)
        bone.tail = (0.0, 1.0, 0.0)
        nxt = j + 1
        if nxt < len(names) and skin.branch[nxt] == skin.branch[j]:
            length = float(np.linalg.norm(origins[nxt] - origins[j]))
        else:
            prev = j - 1 if j > 0 and skin.branch[j - 1] == skin.branch[j] else j
            length = float(np.linalg.norm(origins[j] - origins[prev])) / 2
        bone.matrix = Matrix(skin.frames[j].tolist())
        bone.length = max(length, 1e-3)
    for j, parent in enumerate(skin.parents):
        if parent >= 0:
            bones[names[j]].parent = bones[names[parent]]


def _weight(obj, names, joints, weights, first):
    """Vertex groups from up to four (joint, weight) pairs per vertex, vertices numbered
    from `first`. Vertices of a ring, and the leaves a joint carries, share their weights:
    one call per distinct (joint, weight) instead of one per vertex."""
    groups = [obj.vertex_groups.get(n) or obj.vertex_groups.new(name=n) for n in names]
    vertex = np.repeat(np.arange(first, first + len(joints)), joints.shape[1])
    joint, weight = joints.ravel(), weights.astype(np.float32).ravel()
    used = weight > 0
    vertex, joint, weight = vertex[used], joint[used], weight[used]
    order = np.lexsort((weight, joint))
    vertex, joint, weight = vertex[order], joint[order], weight[order]
    starts = np.flatnonzero(np.r_[True, (np.diff(joint) != 0) | (np.diff(weight) != 0)])
    for begin, end in zip(starts, np.r_[starts[1:], len(vertex)]):
        groups[joint[begin]].add(vertex[begin:end].tolist(), float(weight[begin]), "REPLACE")


def place_tree(context, name, armature, mesh, location):
    """A tree's objects: an armature object at `location` (Blender) and, parented to it
    with an Armature modifier, the mesh. Trees of one template share `armature` and `mesh`
    (each has its own pose and keys). Returns (rig, body)."""
    rig = bpy.data.objects.new(name, armature)
    rig.location = location
    rig.lock_scale = (True, True, True)  # the tree's size is boreas's (its Scale setting)
    context.collection.objects.link(rig)
    body = bpy.data.objects.new(f"{name} mesh", mesh)
    context.collection.objects.link(body)
    body.parent = rig
    modifier = body.modifiers.new("boreas skin", "ARMATURE")
    modifier.object = rig
    return rig, body


def make_tree(context, name, tree, skin_def, location):
    """The armature and mesh of a boreas tree grown at the origin unrotated; the armature
    at `location` (Blender). Returns the armature object."""
    skin = Skin(tree, skin_def)
    names = bone_names(skin.branch)
    vertices, triangles = tree.mesh()
    leaves = tree.leaves
    leaf_points, leaf_triangles = leaf_geometry(leaves)
    points = points_to_blender(np.concatenate([vertices["position"], leaf_points]))
    faces = np.concatenate([triangles.astype(np.int64),
                            leaf_triangles + len(vertices)])
    material = np.concatenate([np.zeros(len(triangles), np.int32),
                               np.ones(len(leaf_triangles), np.int32)])
    mesh = new_mesh(name, points, faces, material)
    mesh.materials.append(_material("boreas bark", BARK_COLOR))
    mesh.materials.append(_material("boreas leaf", LEAF_COLOR))

    armature = bpy.data.armatures.new(name)
    rig, body = place_tree(context, name, armature, mesh, location)

    previous = context.view_layer.objects.active
    context.view_layer.objects.active = rig
    bpy.ops.object.mode_set(mode="EDIT")
    try:
        _build_bones(armature, skin, names)
    finally:
        bpy.ops.object.mode_set(mode="OBJECT")
        context.view_layer.objects.active = previous or rig
    _weight(body, names, skin.vertex_joints, skin.vertex_weights, 0)
    corners = np.repeat(skin.leaf_joints, 4, axis=0), np.repeat(skin.leaf_weights, 4, axis=0)
    _weight(body, names, corners[0], corners[1], len(vertices))
    return rig


def bone_bases(rig, names, frames):
    """Pose-bone basis matrices from the joints' world frames: frames (n, J, 4, 4) in
    Blender's world, joint j the bone names[j] -> (n, J, 4, 4), each bone's transform
    relative to its rest and its parent's pose, so that the posed bone's matrix in the
    armature equals the joint."""
    bones = [rig.data.bones[n] for n in names]
    index = {n: j for j, n in enumerate(names)}
    parents = np.array([index[b.parent.name] if b.parent else -1 for b in bones])
    rest = np.array([np.array(b.matrix_local) for b in bones])                    # (J, 4, 4)
    posed = np.linalg.inv(np.array(rig.matrix_world)) @ frames                        # (n, J, 4, 4)
    has_parent = parents >= 0
    safe = np.where(has_parent, parents, 0)
    rest_rel = np.where(has_parent[:, None, None], np.linalg.inv(rest[safe]) @ rest, rest)
    posed_rel = np.where(has_parent[None, :, None, None],
                         np.linalg.inv(posed[:, safe]) @ posed, posed)
    return np.linalg.inv(rest_rel)[None] @ posed_rel


def key_tree(rig, names, frames, frame_start):
    """Keys every bone at frames frame_start.. from the joints' world frames (n, J, 4, 4),
    joint j the bone names[j], in a new action on the armature (an earlier bake's action
    is replaced)."""
    bases = bone_bases(rig, names, frames)
    n = len(frames)
    action = bpy.data.actions.new(f"{rig.name} boreas")
    rig.animation_data_create()
    old = rig.animation_data.action
    rig.animation_data.action = action
    if old is not None and old.users == 0:
        bpy.data.actions.remove(old)
    times = np.arange(frame_start, frame_start + n, dtype=np.float64)
    quats = continuous(quaternions(bases[..., :3, :3]))                 # (n, J, 4) w x y z
    for j, name in enumerate(names):
        rig.pose.bones[name].rotation_mode = "QUATERNION"
        channels = [("location", bases[:, j, :3, 3]), ("rotation_quaternion", quats[:, j])]
        for path, values in channels:
            for axis in range(values.shape[1]):
                curve = action.fcurves.new(f'pose.bones["{name}"].{path}', index=axis,
                                           action_group=name)
                curve.keyframe_points.add(n)
                curve.keyframe_points.foreach_set(
                    "co", np.column_stack([times, values[:, axis]]).ravel().astype(np.float32))
                curve.update()
    return action
