"""Blender's own glTF importer reads a boreas animation: run as
    blender -b --factory-startup --python-exit-code 1 --python blender_import.py -- \
        FILE.glb JOINTS KEYS SECONDS
it imports FILE.glb and checks that the armatures hold JOINTS bones in all, and that the
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
meshes = [o for o in bpy.data.objects if o.type == "MESH" and o not in before]
assert meshes and all(any(m.type == "ARMATURE" and m.object for m in o.modifiers) for o in meshes), \
    "a tree mesh without an armature"

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
