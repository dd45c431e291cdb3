"""A meadow's baked motion in Blender: its strips' vertices per frame as a point cache (a
PC2 file read by a Mesh Cache modifier) or as shape keys (one per frame, each keyed on at
its frame alone). The third form, instanced clumps, is meadow_instances.py."""
import os
import struct

import bpy
import numpy as np

from . import point_cache

MODIFIER = "boreas motion"


def clear(obj):
    """Removes an earlier bake's modifier and shape keys."""
    old = obj.modifiers.get(MODIFIER)
    if old is not None:
        obj.modifiers.remove(old)
    if obj.data.shape_keys is not None:
        obj.shape_key_clear()


def write_pc2(path, positions, frame_start, fps):
    """positions (n, N, 3) float -> a PC2 file (Blender's Mesh Cache reads it): the header
    (signature, version 1, points, start frame, sample rate, samples), then float32 x y z
    per point per sample."""
    positions = np.ascontiguousarray(positions, dtype="<f4")
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    with open(path, "wb") as f:
        f.write(struct.pack("<12siiffi", b"POINTCACHE2\0", 1, positions.shape[1],
                            float(frame_start), 1.0, positions.shape[0]))
        f.write(positions.tobytes())


def apply_point_cache(obj, positions, frame_start, fps, folder):
    """The motion as a PC2 file in `folder` (a // path is relative to the .blend) read by a
    Mesh Cache modifier from frame_start on. Returns the file's path."""
    clear(obj)
    path = os.path.join(bpy.path.abspath(folder), f"{bpy.path.clean_name(obj.name)}.pc2")
    write_pc2(path, positions, frame_start, fps)
    point_cache.note_written(path)  # set aside if an undo takes the modifier away
    modifier = obj.modifiers.new(MODIFIER, "MESH_CACHE")
    modifier.cache_format = "PC2"
    modifier.filepath = path
    modifier.frame_start = frame_start
    modifier.frame_scale = 1.0
    modifier.forward_axis = "POS_Y"
    modifier.up_axis = "POS_Z"
    return path


def apply_shape_keys(obj, positions, frame_start):
    """The motion as shape keys: the basis, then key k is the shape at frame_start + k,
    keyed 1 there and 0 on the frames beside it."""
    clear(obj)
    obj.shape_key_add(name="rest", from_mix=False)
    for k, frame_points in enumerate(positions):
        key = obj.shape_key_add(name=f"frame {frame_start + k}", from_mix=False)
        key.data.foreach_set("co", np.ascontiguousarray(frame_points, np.float32).ravel())
        frame = frame_start + k
        for at, value in ((frame - 1, 0.0), (frame, 1.0), (frame + 1, 0.0)):
            key.value = value
            key.keyframe_insert("value", frame=at)
    curves = obj.data.shape_keys.animation_data.action.fcurves
    for curve in curves:
        for point in curve.keyframe_points:
            point.interpolation = "LINEAR"
