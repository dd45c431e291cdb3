"""boreas for Blender: an add-on that grows Weber-Penn trees and meadows, sets the wind and
bakes boreas's simulation of the scene's frame range into Blender's animation.

Trees become a mesh (branches and leaves) skinned to an armature, one bone per joint of the
tree's skin (``boreas_tree_get_skin``, the skeleton the glTF export uses too), keyed every
frame; meadows as a few clumps instanced over their cells (each clump's loop a point
cache, clump_plan.py), or a mesh of all the components' strips driven by a point cache (Mesh
Cache modifier) or shape keys. The panel is in the 3D view's sidebar, tab "boreas".

Enable it (the package must be importable by Blender's Python 3.11)::

    build/boreas-python -m boreas.blender install     # or: python3 -m boreas.blender install
    # then Blender: Edit > Preferences > Add-ons, search "boreas", tick it

``install`` writes a small add-on file into Blender's user add-on folder that finds this
package where it lies (the build tree or the installed site). From Blender's own Python
(a script, ``--python``) ``import boreas.blender; boreas.blender.register()`` works too.

Frame f of the scene shows the world after ``f - frame_start + 1`` steps of ``1 / fps``
seconds: the first baked frame is one step after rest.

Axes: boreas is Y up, Blender Z up; a boreas point (x, y, z) is Blender's (x, -z, y), as
glTF's importer maps them.
"""

bl_info = {
    "name": "boreas wind",
    "author": "boreas",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Sidebar > boreas",
    "description": "Weber-Penn trees and meadows moved by boreas's physically based wind",
    "category": "Animation",
}

_modules = None


def _load():
    """The add-on's modules, imported on first registration (bpy exists only in Blender)."""
    global _modules
    if _modules is None:
        from . import bake, grow, meadow, panel, point_cache, properties, wind
        _modules = (properties, grow, meadow, wind, bake, point_cache, panel)
    return _modules


def register():
    for module in _load():
        module.register()


def unregister():
    for module in reversed(_load()):
        module.unregister()
