"""Plant a meadow on the active mesh: boreas underbrush over the mesh's area, its ground
heights from the mesh, shown as one mesh of the components' strips at rest; the bake moves
it."""
import bpy

import boreas

from .axes import points_to_blender
from .mesh_data import new_mesh, strip_layout
from .properties import copy_settings, meadow_properties
from .scene_world import meadow_def

GRASS_COLOR = (0.30, 0.50, 0.15, 1.0)


def strips(meadow):
    """The meadow's drawn strip vertices as of the last step, (N, 3) in Blender's axes,
    with the layout (keep, triangles) they were cut by."""
    vertices, counts = meadow.vertices()
    keep, triangles = strip_layout(counts, vertices.shape[1])
    points = vertices["position"].reshape(-1, 3)[keep]
    return points_to_blender(points), keep, triangles


def plant_into(context, settings, name):
    """Plants the meadow `settings` describes in a world of its own and makes its mesh
    object (at the world origin: its vertices are in world space). Raises boreas.Error or
    ValueError."""
    with boreas.World(device=context.scene.boreas.device or None) as world:
        meadow = world.add_meadow(**meadow_def(settings, f"the meadow on '{settings.ground.name}'"))
        points, _, triangles = strips(meadow)
    if len(points) == 0:
        raise ValueError(f"nothing grows on '{settings.ground.name}' at density "
                         f"{settings.density:g} per m^2")
    mesh = new_mesh(name, points, triangles)
    material = bpy.data.materials.get("boreas grass") or bpy.data.materials.new("boreas grass")
    material.diffuse_color = GRASS_COLOR
    mesh.materials.append(material)
    obj = bpy.data.objects.new(name, mesh)
    # its vertices are in world space, where boreas plants it over its ground
    obj.lock_location = obj.lock_rotation = obj.lock_scale = (True, True, True)
    context.collection.objects.link(obj)
    return obj


class BOREAS_OT_plant_meadow(bpy.types.Operator):
    """Plant a boreas meadow over the active mesh, its ground heights from the mesh"""
    bl_idname = "boreas.plant_meadow"
    bl_label = "Plant Meadow"
    bl_options = {"REGISTER", "UNDO"}

    __annotations__ = meadow_properties()

    def execute(self, context):
        ground = context.active_object
        if ground is None or ground.type != "MESH":
            self.report({"ERROR"}, "boreas: select the mesh to plant the meadow on")
            return {"CANCELLED"}
        holder = copy_settings(self, context.scene.boreas_plant, meadow_properties())
        holder.ground = ground
        try:
            obj = plant_into(context, holder, f"{ground.name} meadow")
        except (boreas.Error, ValueError, OSError) as error:
            self.report({"ERROR"}, f"boreas: cannot plant the meadow: {error}")
            return {"CANCELLED"}
        s = copy_settings(holder, obj.boreas_meadow, meadow_properties())
        s.is_meadow = True
        s.ground = ground
        self.report({"INFO"}, f"boreas: planted {obj.name}")
        return {"FINISHED"}

    @classmethod
    def poll(cls, context):
        return context.active_object is not None and context.active_object.type == "MESH"


def register():
    from .properties import BoreasMeadowSettings
    bpy.types.Scene.boreas_plant = bpy.props.PointerProperty(type=BoreasMeadowSettings)
    bpy.utils.register_class(BOREAS_OT_plant_meadow)


def unregister():
    bpy.utils.unregister_class(BOREAS_OT_plant_meadow)
    del bpy.types.Scene.boreas_plant
