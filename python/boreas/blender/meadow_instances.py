"""A meadow's baked motion as instanced clumps (clump_plan.py): each clump at each phase an
object of its own (its cell's strips about the cell's origin, moved by a point cache), kept
in a collection excluded from the view layer; each cell with plants an empty instancing one
of them at the cell's origin. The meadow's own mesh is hidden meanwhile (it keeps the
meadow's settings and a later bake's vertex check)."""
import os

import bpy
import numpy as np

from . import meadow_motion, point_cache
from .axes import points_to_blender
from .clump_plan import loop_window, looped
from .mesh_data import new_mesh


def holder_name(obj):
    return f"{obj.name} clumps"


def clear(obj):
    """Removes an earlier instanced bake of obj (its collections, objects and meshes) and
    shows obj's own mesh again."""
    holder = bpy.data.collections.get(holder_name(obj))
    if holder is not None:
        for collection in [holder, *holder.children_recursive]:
            for child in list(collection.objects):
                data = child.data
                bpy.data.objects.remove(child)
                if data is not None and data.users == 0:
                    bpy.data.meshes.remove(data)
        for collection in list(holder.children_recursive) + [holder]:
            bpy.data.collections.remove(collection)
    obj.hide_viewport = obj.hide_render = False


def _source(obj, k, phase, plan, frames, mesh, frame_start, folder, sources):
    """Clump k's object at `phase`, its cache written, in a collection of its own; frames:
    its loop's window."""
    name = f"{obj.name} clump{k} phase{phase}"
    collection = bpy.data.collections.new(name)
    sources.children.link(collection)
    source = bpy.data.objects.new(name, mesh)
    collection.objects.link(source)
    vertices, origin = plan.clumps[k]
    local = looped(frames - origin, phase, plan.phases)
    path = os.path.join(bpy.path.abspath(folder), f"{bpy.path.clean_name(name)}.pc2")
    meadow_motion.write_pc2(path, points_to_blender(local), frame_start, 1.0)
    point_cache.note_written(path)
    modifier = source.modifiers.new(meadow_motion.MODIFIER, "MESH_CACHE")
    modifier.cache_format = "PC2"
    modifier.filepath = path
    modifier.frame_start = frame_start
    modifier.forward_axis = "POS_Y"
    modifier.up_axis = "POS_Z"
    return collection


def apply_instances(context, obj, frames, count, plan, layout, frame_start, folder):
    """frames (K, plan.vertices, 3): the clumps' strip vertices at each stepped frame,
    boreas's axes, the first `count` the baked frames, the rest for the loops' windows;
    layout: the meadow's bake.MeadowLayout. Builds the clumps' objects and the cells'
    instances."""
    meadow_motion.clear(obj)
    clear(obj)
    holder = bpy.data.collections.new(holder_name(obj))
    (obj.users_collection[0] if obj.users_collection else context.scene.collection).children.link(holder)
    sources = bpy.data.collections.new(f"{obj.name} clump sources")
    holder.children.link(sources)
    material = obj.data.materials[0] if obj.data.materials else None
    made = {}
    first = 0  # clump k's vertices in frames
    for k, (vertices, origin) in enumerate(plan.clumps):
        inside = np.zeros(len(layout.keep), bool)
        inside[vertices] = True
        renumber = np.cumsum(inside) - 1
        mesh_triangles = renumber[layout.triangles[inside[layout.triangles].all(axis=1)]]
        clump = np.asarray(frames[:, first:first + len(vertices)], np.float64)
        first += len(vertices)
        mesh = new_mesh(f"{obj.name} clump{k}", points_to_blender(clump[0] - origin),
                        mesh_triangles)
        if material is not None:
            mesh.materials.append(material)
        start = loop_window(clump, count)
        window = clump[start:start + count]
        for phase in range(plan.phases):
            made[k, phase] = _source(obj, k, phase, plan, window, mesh, frame_start, folder,
                                     sources)
    for k, phase, origin, cell in plan.instances:
        empty = bpy.data.objects.new(f"{obj.name} cell{cell}", None)
        empty.instance_type = "COLLECTION"
        empty.instance_collection = made[k, phase]
        empty.location = points_to_blender(origin)
        empty.empty_display_size = 0.1
        holder.objects.link(empty)
    # sources are drawn through their instances only
    layer = context.view_layer.layer_collection
    for found in _layers(layer, sources.name):
        found.exclude = True
    obj.hide_viewport = obj.hide_render = True


def _layers(layer, name):
    if layer.collection.name == name:
        yield layer
    for child in layer.children:
        yield from _layers(child, name)
