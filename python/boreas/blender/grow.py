"""Grow a tree: a boreas tree (built-in species, boreas JSON or Arbaro XML) as an armature
and its skinned mesh at the 3D cursor, its definition kept on the armature for the bake."""
import os

import bpy

import boreas

from .properties import copy_settings, tree_properties
from .tree_rig import make_tree, place_tree


def skin_def(settings):
    """Tree.joints' arguments from a tree's settings."""
    return dict(max_level=settings.bone_level, segments=settings.joints_per_branch)


TEMPLATE_FIELDS = ("species", "species_file", "seed", "scale", "bone_level",
                   "joints_per_branch")  # what shapes a tree and its rig (not mode, response)


def template_of(settings):
    """A tree grown before with the same shape and bones, or None."""
    key = [getattr(settings, f) for f in TEMPLATE_FIELDS]
    for obj in bpy.data.objects:
        if (obj.type == "ARMATURE" and obj.boreas_tree.is_tree and obj.children
                and [getattr(obj.boreas_tree, f) for f in TEMPLATE_FIELDS] == key):
            return obj
    return None


def grow_into(context, settings, name, location):
    """The tree `settings` describes at `location`; returns its armature. A tree of the
    same template shares the earlier one's armature and mesh; otherwise it is grown at the
    origin in a world of its own. Raises boreas.Error or OSError."""
    template = template_of(settings)
    if template is not None:
        return place_tree(context, name, template.data, template.children[0].data, location)[0]
    species = settings.species_value()
    with boreas.World(device=context.scene.boreas.device or None) as world:
        tree = world.add_tree(species, position=(0.0, 0.0, 0.0), seed=settings.seed,
                              scale=settings.scale, mode=settings.mode,
                              response=settings.response)
        return make_tree(context, name, tree, skin_def(settings), location)


class BOREAS_OT_grow_tree(bpy.types.Operator):
    """Grow a boreas tree at the 3D cursor"""
    bl_idname = "boreas.grow_tree"
    bl_label = "Grow Tree"
    bl_options = {"REGISTER", "UNDO"}

    __annotations__ = tree_properties()

    def execute(self, context):
        fields = tuple(tree_properties())
        holder = copy_settings(self, context.scene.boreas_grow, fields)
        holder.is_tree = True
        name = (os.path.splitext(os.path.basename(self.species_file))[0]
                if self.species == "FILE" else self.species)
        try:
            rig = grow_into(context, holder, name, context.scene.cursor.location.copy())
        except (boreas.Error, OSError, ValueError) as error:
            self.report({"ERROR"}, f"boreas: cannot grow the tree: {error}")
            return {"CANCELLED"}
        copy_settings(holder, rig.boreas_tree, fields + ("is_tree",))
        for obj in context.selected_objects:
            obj.select_set(False)
        rig.select_set(True)
        context.view_layer.objects.active = rig
        self.report({"INFO"}, f"boreas: grew {name} ({len(rig.data.bones)} bones)")
        return {"FINISHED"}


def register():
    from .properties import BoreasTreeSettings
    bpy.types.Scene.boreas_grow = bpy.props.PointerProperty(type=BoreasTreeSettings)
    bpy.utils.register_class(BOREAS_OT_grow_tree)


def unregister():
    bpy.utils.unregister_class(BOREAS_OT_grow_tree)
    del bpy.types.Scene.boreas_grow
