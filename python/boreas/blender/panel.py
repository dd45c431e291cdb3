"""The add-on's panel in the 3D view's sidebar (tab "boreas"): grow, plant, wind, bake."""
import bpy

from .properties import meadow_properties, tree_properties


class BOREAS_PT_panel(bpy.types.Panel):
    bl_label = "boreas"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "boreas"

    def draw(self, context):
        layout, scene = self.layout, context.scene
        grow = scene.boreas_grow
        box = layout.box()
        box.label(text="Tree", icon="OUTLINER_OB_ARMATURE")
        box.prop(grow, "species")
        if grow.species == "FILE":
            box.prop(grow, "species_file")
        for field in ("seed", "scale", "mode", "response", "bone_level", "joints_per_branch"):
            box.prop(grow, field)
        op = box.operator("boreas.grow_tree")
        for field in tree_properties():
            setattr(op, field, getattr(grow, field))

        plant = scene.boreas_plant
        box = layout.box()
        box.label(text="Meadow on the active mesh", icon="STRANDS")
        box.prop(plant, "species")
        for field in ("density", "seed", "resolution"):
            box.prop(plant, field)
        op = box.operator("boreas.plant_meadow")
        for field in meadow_properties():
            setattr(op, field, getattr(plant, field))

        wind = scene.boreas
        box = layout.box()
        box.label(text="Wind", icon="FORCE_WIND")
        for kind, fields in (("waves", ("heading", "amplitude", "wavelength", "speed")),
                             ("gusts", ("heading", "strength", "delay", "rise", "hold",
                                        "fall", "center", "radius")),
                             ("vortices", ("location", "strength", "radius", "lifetime"))):
            for i, item in enumerate(getattr(wind, kind)):
                sub = box.box()
                row = sub.row()
                row.label(text=f"{kind[:-1] if kind != 'vortices' else 'vortex'} {i + 1}")
                op = row.operator("boreas.wind_remove", text="", icon="X")
                op.kind, op.index = kind, i
                for field in fields:
                    sub.prop(item, field)
        row = box.row()
        for kind, label in (("waves", "Wave"), ("gusts", "Gust"), ("vortices", "Vortex")):
            row.operator("boreas.wind_add", text=label, icon="ADD").kind = kind

        box = layout.box()
        box.label(text="Bake", icon="REC")
        box.prop(wind, "meadow_motion")
        if wind.meadow_motion == "MESH_CACHE":
            box.prop(wind, "cache_dir")
        box.prop(wind, "device")
        box.label(text=f"Frames {scene.frame_start}-{scene.frame_end} at "
                       f"{scene.render.fps / scene.render.fps_base:g} fps")
        from .bake import running
        bake = running()
        if bake is None:
            box.operator("boreas.bake")
        else:
            box.label(text=f"Baking frame {bake.done} of {bake.frames} (Esc cancels)")


def register():
    bpy.utils.register_class(BOREAS_PT_panel)


def unregister():
    bpy.utils.unregister_class(BOREAS_PT_panel)
