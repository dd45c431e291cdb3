"""Set the wind: add and remove the scene's sine-sum waves, gusts and vortices (what the
bake gives boreas's wind; edited in the panel)."""
import bpy
from bpy.props import EnumProperty, IntProperty

KINDS = [("waves", "Wave", "A sine-sum wave over the whole scene"),
         ("gusts", "Gust", "A push that rises, holds and falls"),
         ("vortices", "Vortex", "A whirl about an upright axis")]


class BOREAS_OT_wind_add(bpy.types.Operator):
    """Add a wave, a gust or a vortex to the scene's wind"""
    bl_idname = "boreas.wind_add"
    bl_label = "Add Wind"
    bl_options = {"REGISTER", "UNDO"}
    kind: EnumProperty(name="Kind", items=KINDS)

    def execute(self, context):
        item = getattr(context.scene.boreas, self.kind).add()
        if self.kind != "waves":
            where = context.scene.cursor.location
            if self.kind == "gusts":
                item.center = where
            else:
                item.location = where
        return {"FINISHED"}


class BOREAS_OT_wind_remove(bpy.types.Operator):
    """Remove a wave, a gust or a vortex from the scene's wind"""
    bl_idname = "boreas.wind_remove"
    bl_label = "Remove Wind"
    bl_options = {"REGISTER", "UNDO"}
    kind: EnumProperty(name="Kind", items=KINDS)
    index: IntProperty(name="Index", min=0)

    def execute(self, context):
        items = getattr(context.scene.boreas, self.kind)
        if self.index >= len(items):
            self.report({"ERROR"}, f"boreas: no {self.kind} entry {self.index} "
                                   f"(there are {len(items)})")
            return {"CANCELLED"}
        items.remove(self.index)
        return {"FINISHED"}


_classes = (BOREAS_OT_wind_add, BOREAS_OT_wind_remove)


def register():
    for cls in _classes:
        bpy.utils.register_class(cls)


def unregister():
    for cls in reversed(_classes):
        bpy.utils.unregister_class(cls)
