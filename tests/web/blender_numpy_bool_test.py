"""The numpy.bool workaround (blender_numpy_bool.py) is needed and is what makes Blender's
glTF importer read a mesh: run as
    blender -b --factory-startup --python-exit-code 1 --python blender_numpy_bool_test.py -- OUT
Blender writes its default cube as OUT/cube.glb; importing it fails with NumPy's
AttributeError for `bool` (carried by bpy.ops as a RuntimeError) before restore() and succeeds after. Where the importer no longer
needs it (a fixed Blender or an older NumPy), it fails, saying the workaround can go."""
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_numpy_bool  # noqa: E402

out = sys.argv[sys.argv.index("--") + 1]
os.makedirs(out, exist_ok=True)
path = os.path.join(out, "cube.glb")
assert bpy.ops.export_scene.gltf(filepath=path) == {"FINISHED"}
for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj)

assert blender_numpy_bool.importer_needs_it(), (
    "Blender's glTF importer no longer needs numpy.bool: remove tests/web/blender_numpy_bool.py "
    "and its use in blender_import.py")
try:
    bpy.ops.import_scene.gltf(filepath=path)
    raise AssertionError("the importer read a mesh without numpy.bool: the workaround can go")
except RuntimeError as error:  # bpy.ops carries the importer's AttributeError in its text
    assert "has no attribute 'bool'" in str(error), f"the importer failed otherwise: {error}"
    print("boreas: without the workaround the importer fails, as expected: "
          "module 'numpy' has no attribute 'bool'")
for obj in list(bpy.data.objects):  # whatever the failed import left
    bpy.data.objects.remove(obj)

assert blender_numpy_bool.restore(), "restore() did not restore numpy.bool"
assert bpy.ops.import_scene.gltf(filepath=path) == {"FINISHED"}
meshes = [o for o in bpy.data.objects if o.type == "MESH"]
# glTF holds triangles: the cube's six faces come back as twelve.
assert len(meshes) == 1 and len(meshes[0].data.polygons) == 12, "the cube did not come back"
assert not blender_numpy_bool.restore(), "restore() patched twice"
print("boreas: the importer reads the cube with numpy.bool restored")
