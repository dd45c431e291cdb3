"""What the add-on keeps in the .blend file: a tree's and a meadow's definition on their
objects, the wind and the bake settings on the scene. The bake rebuilds its boreas world
from these, so a saved file bakes again the same."""
import bpy
from bpy.props import (BoolProperty, CollectionProperty, EnumProperty, FloatProperty,
                       FloatVectorProperty, IntProperty, PointerProperty, StringProperty)

TREE_SPECIES = [("quaking_aspen", "Quaking aspen", ""), ("black_tupelo", "Black tupelo", ""),
                ("ca_black_oak", "California black oak", ""),
                ("weeping_willow", "Weeping willow", ""),
                ("FILE", "File", "A boreas species .json or an Arbaro .xml")]
MEADOW_SPECIES = [("meadow_grass", "Grass", "", 1), ("clover", "Clover", "", 2),
                  ("daisy", "Daisy", "", 4), ("fern", "Fern", "", 8)]


def tree_properties():
    """A tree's settings, written once for the object's settings and the Grow Tree
    operator (fresh definitions for each class)."""
    return dict(
        species=EnumProperty(name="Species", items=TREE_SPECIES, default="quaking_aspen"),
        species_file=StringProperty(name="Species file", subtype="FILE_PATH",
                                    description="A boreas species .json or an Arbaro .xml"),
        seed=IntProperty(name="Seed", default=1, min=0,
                         description="The same seed grows the same tree"),
        scale=FloatProperty(name="Scale", default=1.0, min=0.001, max=1000.0,
                            description="Multiplies every length of the species"),
        mode=EnumProperty(name="Mode", default="exact", items=[
            ("lagged", "Lagged", "One launch per step, each level a step behind its parent"),
            ("exact", "Exact", "Level by level, children on their parents' current curves")]),
        response=EnumProperty(name="Response", default="damped", items=[
            ("quasi_static", "Quasi-static", "The bend follows the wind at once"),
            ("damped", "Damped", "A damped oscillator at each branch's natural frequency")]),
        bone_level=IntProperty(name="Bone level", default=1, min=0, max=3,
                               description="Branches down to this level get bones; finer "
                                           "ones and leaves follow their ancestor's"),
        joints_per_branch=IntProperty(name="Joints per branch", default=4, min=1, max=16,
                                      description="Bones along each boned branch's curve"))


def meadow_properties():
    """A meadow's settings, written once for the object's settings and the Plant Meadow
    operator."""
    return dict(
        species=EnumProperty(name="Species", items=MEADOW_SPECIES, options={"ENUM_FLAG"},
                             default={"meadow_grass", "clover", "daisy"}),
        density=FloatProperty(name="Density", default=200.0, min=0.0, max=100000.0,
                              description="Components per square meter"),
        seed=IntProperty(name="Seed", default=1, min=0),
        resolution=IntProperty(name="Height samples", default=64, min=2, max=1024,
                               description="Height-map samples along the longer side"))


def copy_settings(source, target, fields):
    """Sets each of `fields` on target to source's value: an operator's properties into the
    scene's settings that outlive it, those onto the object it grew or planted, or the
    panel's settings onto its operator button. Returns target."""
    for field in fields:
        setattr(target, field, getattr(source, field))
    return target


class BoreasTreeSettings(bpy.types.PropertyGroup):
    """A tree's definition (boreas_tree_def), on its armature object."""
    __annotations__ = dict(is_tree=BoolProperty(default=False), **tree_properties())

    def species_value(self):
        """The species as boreas takes it: a built-in name or a file path."""
        if self.species == "FILE":
            return bpy.path.abspath(self.species_file)
        return self.species


class BoreasMeadowSettings(bpy.types.PropertyGroup):
    """A meadow's definition (boreas_meadow_def), on its mesh object; the ground it grows on
    is the mesh it was planted on."""
    __annotations__ = dict(is_meadow=BoolProperty(default=False),
                           ground=PointerProperty(name="Ground", type=bpy.types.Object),
                           **meadow_properties())


class BoreasWave(bpy.types.PropertyGroup):
    """A sine-sum wave (boreas_wave_def)."""
    heading: FloatProperty(name="Heading", subtype="ANGLE", default=0.0,
                           description="Where the wind blows to, from +X towards +Y")
    amplitude: FloatProperty(name="Amplitude", default=6.0, min=0.0, max=100.0, unit="VELOCITY")
    wavelength: FloatProperty(name="Wavelength", default=30.0, min=0.01, unit="LENGTH")
    speed: FloatProperty(name="Speed", default=5.0, min=0.0, unit="VELOCITY")
    sharpness: FloatProperty(name="Sharpness", default=1.0, min=0.0)


class BoreasGust(bpy.types.PropertyGroup):
    """A gust on the grid (boreas_gust_def)."""
    heading: FloatProperty(name="Heading", subtype="ANGLE", default=0.0)
    strength: FloatProperty(name="Strength", default=8.0, min=-100.0, max=100.0, unit="VELOCITY")
    delay: FloatProperty(name="Delay", default=0.5, min=0.0, unit="TIME_ABSOLUTE")
    rise: FloatProperty(name="Rise", default=0.5, min=0.0, unit="TIME_ABSOLUTE")
    hold: FloatProperty(name="Hold", default=1.0, min=0.0, unit="TIME_ABSOLUTE")
    fall: FloatProperty(name="Fall", default=1.0, min=0.0, unit="TIME_ABSOLUTE")
    center: FloatVectorProperty(name="Center", size=3, subtype="TRANSLATION")
    radius: FloatProperty(name="Radius", default=0.0, min=0.0, unit="LENGTH",
                          description="0: the whole grid")


class BoreasVortex(bpy.types.PropertyGroup):
    """A vortex flow primitive (boreas_flow_primitive_def, type vortex), its axis up."""
    location: FloatVectorProperty(name="Location", size=3, subtype="TRANSLATION")
    strength: FloatProperty(name="Strength", default=6.0, min=-100.0, max=100.0, unit="VELOCITY")
    radius: FloatProperty(name="Radius", default=10.0, min=0.01, unit="LENGTH")
    lifetime: FloatProperty(name="Lifetime", default=0.0, min=0.0, unit="TIME_ABSOLUTE",
                            description="0: the whole bake")


class BoreasSceneSettings(bpy.types.PropertyGroup):
    """The scene's wind and how it is baked."""
    waves: CollectionProperty(type=BoreasWave)
    gusts: CollectionProperty(type=BoreasGust)
    vortices: CollectionProperty(type=BoreasVortex)
    device: StringProperty(name="Device", default="",
                           description="OpenCL device: empty for the best, 'cpu', 'gpu', "
                                       "'P:D' or part of its name")
    meadow_motion: EnumProperty(name="Meadow motion", default="INSTANCES", items=[
        ("INSTANCES", "Instanced clumps", "A few clumps, each baked at a few phases of a "
                                          "loop (point caches), instanced on every cell of "
                                          "the meadow: plays back many times faster than "
                                          "the whole meadow; not every blade as simulated"),
        ("MESH_CACHE", "Point cache", "Every strip as simulated: a PC2 file in the cache "
                                      "folder read by a Mesh Cache modifier, keeps the "
                                      ".blend small"),
        ("SHAPE_KEYS", "Shape keys", "Every strip as simulated: one shape key per frame, "
                                     "every frame kept in the .blend and in memory")])
    meadow_clumps: IntProperty(name="Clumps", default=4, min=1, max=64,
                               description="Instanced clumps: clumps per meadow")
    clump_size: FloatProperty(name="Clump size", default=1.0, min=0.1, max=100.0, unit="LENGTH",
                              description="Instanced clumps: the side of a clump's square cell")
    clump_phases: IntProperty(name="Phases", default=4, min=1, max=64,
                              description="Instanced clumps: starts in its loop each clump is "
                                          "baked at (a cell takes one)")
    cache_dir: StringProperty(name="Cache folder", subtype="DIR_PATH", default="//boreas_cache",
                              description="Where meadow point caches are written")


_classes = (BoreasTreeSettings, BoreasMeadowSettings, BoreasWave, BoreasGust, BoreasVortex,
            BoreasSceneSettings)


def register():
    for cls in _classes:
        bpy.utils.register_class(cls)
    bpy.types.Object.boreas_tree = PointerProperty(type=BoreasTreeSettings)
    bpy.types.Object.boreas_meadow = PointerProperty(type=BoreasMeadowSettings)
    bpy.types.Scene.boreas = PointerProperty(type=BoreasSceneSettings)


def unregister():
    del bpy.types.Scene.boreas
    del bpy.types.Object.boreas_meadow
    del bpy.types.Object.boreas_tree
    for cls in reversed(_classes):
        bpy.utils.unregister_class(cls)
