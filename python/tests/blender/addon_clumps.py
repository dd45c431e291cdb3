"""Blender test: a meadow baked as instanced clumps (the default meadow motion) plays back
as boreas simulated it, as the animated glTF's clumps do: every cell with plants is an
instance at its cell's center and ground height; a clump at its own cell (phase 0) plays
boreas's components of that cell over its loop's window (the F of 3 F - 2 stepped frames
whose last is nearest its first) less the loop's drift (frame k: k / (F - 1) of the move
from the window's first frame to its last) within 0.1 mm; instances at other phases sway
out of step; baking again as a point cache takes the instances away. (Whether a window
leans downwind of rest is the wave's phase there, not a property: addon_bake checks that
the merged meadow leans downwind.)"""
import os
import sys

import bpy
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from addon_env import arguments, check, enable_addon, fresh_scene  # noqa: E402

FRAMES = 24

package, out = arguments()
enable_addon(package, out)
from boreas.blender.axes import points_to_blender  # noqa: E402
from boreas.blender.bake import MeadowLayout  # noqa: E402
from boreas.blender.clump_plan import ClumpPlan  # noqa: E402
from boreas.blender.scene_world import build_world  # noqa: E402

scene = fresh_scene(frames=FRAMES)
scene.boreas.cache_dir = os.path.join(out, "cache")
check(scene.boreas.meadow_motion == "INSTANCES", "meadows bake as instanced clumps by default")
bpy.ops.boreas.wind_add(kind="waves")
wave = scene.boreas.waves[0]
wave.heading, wave.amplitude, wave.wavelength, wave.speed = 0.0, 9.0, 40.0, 6.0  # along +X
bpy.ops.mesh.primitive_plane_add(size=3.0, location=(0.0, 0.0, 0.2))
ground = bpy.context.active_object
ground.rotation_euler = (0.15, 0.0, 0.0)
check(bpy.ops.boreas.plant_meadow(density=60.0, seed=2, resolution=16) == {"FINISHED"},
      "plant_meadow finished")
meadow_obj = next(o for o in scene.objects if o.boreas_meadow.is_meadow)
scene.boreas.meadow_clumps, scene.boreas.clump_size, scene.boreas.clump_phases = 2, 1.0, 3
check(bpy.ops.boreas.bake() == {"FINISHED"}, "bake finished (INSTANCES)")
check(meadow_obj.hide_viewport and meadow_obj.hide_render, "the merged meadow is hidden")

# The same world stepped here: the kept strips at every frame, and the plan on its rest.
world, _, meadows = build_world(scene)
meadow = meadows[0][1]
layout = MeadowLayout(meadow)
plan = ClumpPlan(layout.components, layout.keep, layout.stride, 2, 1.0, 3)
frames = []
for _ in range(3 * FRAMES - 2):  # the baked frames and the ones the loops are sought in
    world.step(1.0 / 24)
    frames.append(meadow.vertices()[0]["position"].reshape(-1, 3)[layout.keep].astype(np.float64))
world.close()
frames = np.array(frames)
cells = {cell for *_, cell in plan.instances}
empties = [o for o in scene.objects if o.instance_type == "COLLECTION"
           and o.name.startswith(f"{meadow_obj.name} cell")]
check(len(empties) == len(cells) == len(plan.instances),
      f"an instance on each of the {len(cells)} cells with plants")
placed, bound = 0.0, 0
for k, phase, origin, cell in plan.instances:
    empty = scene.objects[f"{meadow_obj.name} cell{cell}"]
    placed = max(placed, np.abs(np.array(empty.location) - points_to_blender(origin)).max())
    bound += empty.instance_collection.name.endswith(f"clump{k} phase{phase}")
check(placed < 1e-5 and bound == len(plan.instances),
      f"each cell instances its share's clump at its phase, at the cell's center and ground "
      f"(largest offset {placed:.1e} m)")


def instanced(frame):
    """What Blender draws of each instance at frame: {cell: (N, 3) world points}."""
    scene.frame_set(frame)
    depsgraph = bpy.context.evaluated_depsgraph_get()
    drawn = {}
    for inst in depsgraph.object_instances:
        if not inst.is_instance or inst.parent is None:
            continue
        name = inst.parent.original.name
        if not name.startswith(f"{meadow_obj.name} cell"):
            continue
        m = np.array(inst.matrix_world)
        co = np.array([v.co[:] for v in inst.object.data.vertices])
        drawn[int(name.rsplit("cell", 1)[1])] = co @ m[:3, :3].T + m[:3, 3]
    return drawn


# Each clump's loop: the window of FRAMES frames whose last is nearest its first.
windows = []
for vertices, _ in plan.clumps:
    seams = [np.linalg.norm(frames[w + FRAMES - 1, vertices] - frames[w, vertices], axis=1).max()
             for w in range(2 * FRAMES - 1)]
    windows.append(frames[int(np.argmin(seams)):int(np.argmin(seams)) + FRAMES][:, vertices])
    print(f"clump window from frame {int(np.argmin(seams)) + 1}: seam {min(seams) * 1e3:.1f} mm "
          f"(the first {FRAMES} frames: {seams[0] * 1e3:.1f} mm)")
worst, moved, out_of_step = 0.0, 0.0, 0.0
vertices_drawn = 0
for frame in (1, 12, FRAMES):
    drawn = instanced(frame)
    check(set(drawn) == cells, f"frame {frame}: every cell drawn ({len(drawn)})")
    if frame == 1:
        vertices_drawn = sum(len(p) for p in drawn.values())
    k_frame = frame - 1
    for k, (vertices, origin) in enumerate(plan.clumps):
        own = plan.own[k]
        w = windows[k]
        want = w[k_frame] - k_frame / (FRAMES - 1) * (w[-1] - w[0])
        worst = max(worst, np.abs(drawn[own] - points_to_blender(want)).max())
        moved = max(moved, np.abs(w[k_frame] - w[0]).max())
        others = [cell for kk, phase, _, cell in plan.instances if kk == k and phase != 0]
        if frame == 12 and others:
            a, b = drawn[own] - drawn[own].mean(axis=0), drawn[others[0]] - drawn[others[0]].mean(axis=0)
            out_of_step = max(out_of_step, np.abs(a - b).max())
check(worst < 1e-4, f"each clump at its own cell plays boreas's cell in its window less the "
                    f"loop's drift "
                    f"(largest miss {worst:.2e} m; boreas moved it up to {moved:.3f} m)")
check(out_of_step > 1e-3, f"an instance at another phase sways out of step "
                          f"({out_of_step * 1e3:.1f} mm apart at frame 12)")
total = frames.shape[1]
check(abs(vertices_drawn - total) <= 0.35 * total,
      f"the instances draw {vertices_drawn} strip vertices for the meadow's {total}")
scene.boreas.meadow_motion = "MESH_CACHE"
check(bpy.ops.boreas.bake() == {"FINISHED"}, "bake finished (MESH_CACHE)")
check(not meadow_obj.hide_viewport and bpy.data.collections.get(f"{meadow_obj.name} clumps") is None
      and not any(o.name.startswith(f"{meadow_obj.name} cell") for o in bpy.data.objects),
      "baking as a point cache takes the instances away and shows the meadow again")
