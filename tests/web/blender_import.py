"""Blender's own glTF importer reads a boreas animation: run as
    blender -b --factory-startup --python-exit-code 1 --python blender_import.py -- \
        FILE.glb JOINTS KEYS SECONDS
it imports FILE.glb and checks that the armatures hold JOINTS bones in all, that every
morphed mesh (meadows, imported trees) has its shape keys keyed KEYS times, and that the
animation spans SECONDS (KEYS keys) at the scene's frame rate. Any failure raises, so
Blender exits with 1."""
import os
import sys

import bpy

# Debian's Blender 3.4 importer still spells NumPy's bool `np.bool`, which NumPy 1.24
# removed: blender_numpy_bool.py restores it, saying so (its own test shows it is needed).
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_numpy_bool  # noqa: E402

blender_numpy_bool.restore()

path, joints, keys, seconds = sys.argv[sys.argv.index("--") + 1:]
joints, keys, seconds = int(joints), int(keys), float(seconds)

before = set(bpy.data.objects)  # the factory scene's cube, camera and light
result = bpy.ops.import_scene.gltf(filepath=path)
assert result == {"FINISHED"}, f"import failed: {result}"
armatures = [o for o in bpy.data.objects if o.type == "ARMATURE"]
bones = sum(len(a.data.bones) for a in armatures)
print(f"boreas: {len(armatures)} armatures, {bones} bones, {len(bpy.data.actions)} actions")
assert bones == joints, f"{bones} bones imported, {joints} joints written"
# Blender may gather several skins into one armature; every tree's mesh must be bound.
# Meadows and imported trees are morphed instead: shape keys (Basis and a key per morph
# target), their values keyed a key per frame.
meshes = [o for o in bpy.data.objects if o.type == "MESH" and o not in before]
# (One that stood still within the export's tolerance has none: it is written at rest.)
still = [o for o in meshes if o.name.startswith(("meadow", "mesh_tree"))]
morphed = [o for o in still if o.data.shape_keys is not None]
assert meshes and all(any(m.type == "ARMATURE" and m.object for m in o.modifiers)
                      for o in meshes if o not in still), "a tree mesh without an armature"
for o in morphed:
    blocks = o.data.shape_keys.key_blocks
    action = o.data.shape_keys.animation_data and o.data.shape_keys.animation_data.action
    assert len(blocks) >= 2 and action, f"{o.name}: {len(blocks)} shape keys, action {action}"
    values = [c for c in action.fcurves if c.data_path.endswith(".value")]
    assert len(values) == len(blocks) - 1 and all(len(c.keyframe_points) == keys for c in values), \
        f"{o.name}: {len(values)} shape key curves for {len(blocks) - 1} targets, not {keys} keys each"
print(f"boreas: {len(morphed)} of {len(still)} meadow and imported tree meshes with shape keys")

fps = bpy.context.scene.render.fps / bpy.context.scene.render.fps_base
spans = []
for action in bpy.data.actions:
    start, end = action.frame_range
    spans.append((end - start) / fps)
    # Every rotation curve holds a key per frame written.
    for curve in action.fcurves:
        if "rotation_quaternion" in curve.data_path:
            assert len(curve.keyframe_points) == keys, (
                f"{action.name} {curve.data_path}: {len(curve.keyframe_points)} keys, {keys} written")
print(f"boreas: actions span {min(spans):.4f}..{max(spans):.4f} s at {fps} frames/s")
assert spans and all(abs(s - seconds) <= 1.0 / fps for s in spans), \
    f"animation spans {spans[:3]} s, {seconds} s written"
print("boreas: Blender imported the animation")
