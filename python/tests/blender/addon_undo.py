"""Blender test: undoing a meadow bake leaves no point cache behind (boreas.blender.
point_cache). A small meadow is baked as a point cache; Ctrl-Z (ed.undo) takes the Mesh
Cache modifier away and the PC2 file is set aside (FILE.undone), Ctrl-Shift-Z (ed.redo)
brings both back, the modifier reading the same frames; loading another file deletes what
was set aside. A file in the cache folder that the add-on did not write stays."""
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from addon_env import arguments, check, enable_addon, fresh_scene  # noqa: E402

package, out = arguments()
enable_addon(package, out)
from boreas.blender.point_cache import ASIDE  # noqa: E402

scene = fresh_scene(frames=4)
cache = os.path.join(out, "cache")
scene.boreas.cache_dir = cache
scene.boreas.meadow_motion = "MESH_CACHE"
bpy.ops.boreas.wind_add(kind="waves")
bpy.ops.mesh.primitive_plane_add(size=1.0)
check(bpy.ops.boreas.plant_meadow(density=40.0, seed=2, resolution=8) == {"FINISHED"},
      "plant_meadow finished")
meadow = next(o for o in scene.objects if o.boreas_meadow.is_meadow)
name = meadow.name  # undo and redo rebuild the data: the object is looked up by name after
os.makedirs(cache, exist_ok=True)
stranger = os.path.join(cache, "not_the_addons.pc2")
with open(stranger, "wb") as f:
    f.write(b"someone else's")

bpy.ops.ed.undo_push(message="before the bake")
check(bpy.ops.boreas.bake() == {"FINISHED"}, "bake finished")
bpy.ops.ed.undo_push(message="bake")
modifier = next(m for m in meadow.modifiers if m.type == "MESH_CACHE")
path = bpy.path.abspath(modifier.filepath)
size = os.path.getsize(path)
check(size > 32, f"the bake wrote {path} ({size} bytes)")

bpy.ops.ed.undo()
meadow = bpy.data.objects[name]
check(not any(m.type == "MESH_CACHE" for m in meadow.modifiers), "undo took the modifier away")
check(not os.path.exists(path) and os.path.getsize(path + ASIDE) == size,
      "undo set the point cache aside")
check(os.path.exists(stranger), "a file the add-on did not write stays")

bpy.ops.ed.redo()
meadow = bpy.data.objects[name]
check(any(m.type == "MESH_CACHE" for m in meadow.modifiers), "redo brought the modifier back")
check(os.path.getsize(path) == size and not os.path.exists(path + ASIDE),
      "redo put the point cache back")

bpy.ops.ed.undo()
check(os.path.exists(path + ASIDE), "undone again: set aside again")
bpy.ops.wm.read_homefile(use_factory_startup=True)
check(not os.path.exists(path) and not os.path.exists(path + ASIDE),
      "loading another file deleted the set-aside point cache")
check(os.path.exists(stranger), "the file the add-on did not write is still there")
