"""The add-on's panel in the 3D view's sidebar (tab "boreas"): grow, plant, wind, bake."""
import bpy

from .properties import copy_settings, meadow_properties, tree_properties


def _settings_box(layout, title, icon, settings, shown, operator, fields):
    """A box of the settings `shown` and the operator's button, which takes all of `fields`
    from them."""
    box = layout.box()
    box.label(text=title, icon=icon)
    for field in shown:
        box.prop(settings, field)
    copy_settings(settings, box.operator(operator), fields)


class BOREAS_PT_panel(bpy.types.Panel):
    bl_label = "boreas"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "boreas"

    def draw(self, context):
        layout, scene = self.layout, context.scene
        grow = scene.boreas_grow
        file = ("species_file",) if grow.species == "FILE" else ()
        _settings_box(layout, "Tree", "OUTLINER_OB_ARMATURE", grow,
                      ("species",) + file + ("seed", "scale", "mode", "response", "bone_level",
                                             "joints_per_branch"),
                      "boreas.grow_tree", tree_properties())
        _settings_box(layout, "Meadow on the active mesh", "STRANDS", scene.boreas_plant,
                      ("species", "density", "seed", "resolution"), "boreas.plant_meadow",
                      meadow_properties())

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
        if wind.meadow_motion == "INSTANCES":
            for name in ("meadow_clumps", "clump_size", "clump_phases"):
                box.prop(wind, name)
        if wind.meadow_motion in ("MESH_CACHE", "INSTANCES"):
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
