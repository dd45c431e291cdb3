"""How fast Blender plays back a baked boreas meadow: instanced clumps (the add-on's default:
4 clumps x 4 phases on cells of 1 m, meadow_instances.py), the whole meadow as a point cache
(Mesh Cache modifier on a PC2 file) and as shape keys (one per frame). Run by Blender:

    blender -b --factory-startup --python python/bench/blender_playback.py -- \
        build/python OUT [SIDE_M DENSITY FRAMES]

Plants a SIDE x SIDE m meadow at DENSITY per m^2 on a plane, bakes FRAMES frames each way,
then times scene.frame_set over every frame three times (the depsgraph evaluates the
modifier or the shape keys); prints ms per frame (process CPU time and wall time) and the
bake's time and the .blend size it adds."""
import os
import sys
import time

import bpy

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests",
                                "blender"))
from addon_env import arguments, enable_addon, fresh_scene  # noqa: E402

package, out = arguments()
rest = sys.argv[sys.argv.index("--") + 3:]
side, density, frames = ((float(rest[0]), float(rest[1]), int(rest[2])) if rest
                         else (10.0, 200.0, 120))
enable_addon(package, out)
scene = fresh_scene(frames=frames)
scene.boreas.cache_dir = os.path.join(out, "cache")
bpy.ops.boreas.wind_add(kind="waves")
scene.boreas.waves[0].amplitude = 8.0
bpy.ops.mesh.primitive_plane_add(size=side)
bpy.ops.boreas.plant_meadow(density=density, seed=1, resolution=16)
meadow = next(o for o in scene.objects if o.boreas_meadow.is_meadow)
print(f"meadow: {len(meadow.data.vertices)} vertices, {len(meadow.data.polygons)} triangles, "
      f"{frames} frames")
for motion in ("INSTANCES", "MESH_CACHE", "SHAPE_KEYS"):
    scene.boreas.meadow_motion = motion
    t = time.perf_counter()
    bpy.ops.boreas.bake()
    baked = time.perf_counter() - t
    if motion == "INSTANCES":
        cells = [o for o in scene.objects if o.instance_type == "COLLECTION"]
        print(f"INSTANCES: {len(cells)} cells instancing "
              f"{len(bpy.data.collections[meadow.name + ' clump sources'].children)} clump objects")
    path = os.path.join(out, f"playback_{motion}.blend")
    bpy.ops.wm.save_as_mainfile(filepath=path, copy=True)
    runs = []
    for _ in range(3):
        cpu, wall = time.process_time(), time.perf_counter()
        for frame in range(1, frames + 1):
            scene.frame_set(frame)
        runs.append(((time.process_time() - cpu) / frames * 1e3,
                     (time.perf_counter() - wall) / frames * 1e3))
    print(f"{motion}: bake {baked:.1f} s, .blend {os.path.getsize(path) / 2**20:.1f} MiB; "
          "playback ms/frame (cpu, wall): "
          + ", ".join(f"({c:.2f}, {w:.2f})" for c, w in runs))
