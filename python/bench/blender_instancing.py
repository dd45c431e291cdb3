"""How fast Blender plays back a meadow merged into one mesh against the same meadow as
instanced clumps, both moved by point caches (PC2 files read by Mesh Cache modifiers, as the
add-on bakes meadows). Run by Blender:

    blender -b --factory-startup --python python/bench/blender_instancing.py -- \
        OUT [CELLS CLUMP_VERTICES CLUMPS PHASES FRAMES]

merged: CELLS cells of CLUMP_VERTICES strip vertices each as one mesh, one cache of all of
its vertices (what the add-on builds today). instanced: CLUMPS clumps baked at PHASES
phases each (CLUMPS x PHASES objects, each its clump's mesh and a cache of its own, started
a phase in), hidden in a collection each, and CELLS empties instancing them (the glTF's
clumps, its phases cut to PHASES). The same vertices are on screen; the motion is a sway per
vertex (the cost of playing a cache does not depend on what it holds). Times
scene.frame_set over every frame three times (the depsgraph evaluates the modifiers; the
instances are not re-evaluated) and prints ms per frame (process CPU, wall)."""
import os
import struct
import sys
import time

import bpy
import numpy as np

args = sys.argv[sys.argv.index("--") + 1:]
out = args[0]
cells, clump_vertices, clumps, phases, frames = (
    (int(args[1]), int(args[2]), int(args[3]), int(args[4]), int(args[5])) if len(args) > 5
    else (900, 2000, 4, 4, 120))
os.makedirs(out, exist_ok=True)


def strips(n):
    """n vertices as strips of 8 (a blade each) across a 1 m cell; their faces."""
    rng = np.random.default_rng(n)
    blades = n // 8
    base = rng.uniform(-0.5, 0.5, (blades, 1, 3)) * [1, 0, 1]
    up = np.arange(8)[None, :, None] * [0, 0.06, 0] + (np.arange(8) % 2)[None, :, None] * [0.01, 0, 0]
    co = (base + up).reshape(-1, 3)
    faces = [(8 * b + j, 8 * b + j + 1, 8 * b + j + 2) for b in range(blades) for j in range(6)]
    return co.astype(np.float32), faces


def write_pc2(path, rest, phase):
    """frames samples of rest swayed in x by height, phase frames in."""
    t = (np.arange(frames) + phase)[:, None] * (2 * np.pi / frames)
    sway = 0.05 * rest[None, :, 1] * np.sin(t + rest[None, :, 0])
    pos = np.repeat(rest[None], frames, axis=0)
    pos[:, :, 0] += sway
    with open(path, "wb") as f:
        f.write(struct.pack("<12siiffi", b"POINTCACHE2\0", 1, rest.shape[0], 1.0, 1.0, frames))
        f.write(np.ascontiguousarray(pos, "<f4").tobytes())


def cached_object(name, co, faces, phase, collection):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(co.tolist(), [], faces)
    obj = bpy.data.objects.new(name, mesh)
    collection.objects.link(obj)
    path = os.path.join(out, name + ".pc2")
    write_pc2(path, co, phase)
    m = obj.modifiers.new("boreas motion", "MESH_CACHE")
    m.cache_format = "PC2"
    m.filepath = path
    m.frame_start = 1
    m.forward_axis = "POS_Y"
    m.up_axis = "POS_Z"
    return obj


def timed(label):
    scene = bpy.context.scene
    runs = []
    for _ in range(3):
        cpu, wall = time.process_time(), time.perf_counter()
        for frame in range(1, frames + 1):
            scene.frame_set(frame)
        runs.append(((time.process_time() - cpu) / frames * 1e3,
                     (time.perf_counter() - wall) / frames * 1e3))
    print(f"{label}: playback ms/frame (cpu, wall): "
          + ", ".join(f"({c:.2f}, {w:.2f})" for c, w in runs), flush=True)


def fresh():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = 1, frames
    return scene


side = int(np.ceil(np.sqrt(cells)))
co, faces = strips(clump_vertices)

scene = fresh()
grid = [((c % side) - side / 2, (c // side) - side / 2) for c in range(cells)]
all_co = np.concatenate([co + [x, 0, z] for x, z in grid])
all_faces = [(a + clump_vertices * c, b + clump_vertices * c, d + clump_vertices * c)
             for c in range(cells) for a, b, d in faces]
t = time.perf_counter()
cached_object("merged", all_co, all_faces, 0, scene.collection)
print(f"merged: {len(all_co)} vertices, built in {time.perf_counter() - t:.1f} s", flush=True)
timed("merged")

scene = fresh()
t = time.perf_counter()
sources = []
for k in range(clumps):
    for p in range(phases):
        holder = bpy.data.collections.new(f"clump{k}_phase{p}")
        holder.hide_render = True
        ck, fk = strips(clump_vertices + 8 * k)  # clumps of their own shapes
        cached_object(f"clump{k}_phase{p}", ck, fk, p * frames // phases, holder)
        sources.append(holder)
        scene.collection.children.link(holder)
        bpy.context.view_layer.layer_collection.children[holder.name].exclude = False
        holder.hide_viewport = False
for c, (x, z) in enumerate(grid):
    empty = bpy.data.objects.new(f"cell{c}", None)
    empty.instance_type = "COLLECTION"
    empty.instance_collection = sources[c % len(sources)]
    empty.location = (x, z, 0)
    scene.collection.objects.link(empty)
print(f"instanced: {clumps * phases} clump objects of ~{clump_vertices} vertices, {cells} "
      f"instances ({cells * clump_vertices} vertices on screen), built in "
      f"{time.perf_counter() - t:.1f} s", flush=True)
timed("instanced")
