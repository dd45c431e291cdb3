"""What the Blender tests share: run by Blender (``blender -b --factory-startup
--python-exit-code 1 --python <test> -- <build>/python <out>``), they install the add-on as
a user would (``python3 -m boreas.blender install``, here into a folder of the test's) and
enable it through Blender's add-on machinery."""
import os
import sys

import addon_utils
import bpy


def arguments():
    """(package folder, output folder) from the arguments after '--'."""
    args = sys.argv[sys.argv.index("--") + 1:]
    package, out = args[0], args[1]
    os.makedirs(out, exist_ok=True)
    return package, out


def enable_addon(package, out):
    """Writes the add-on file into out/addons the way `install` does and enables it."""
    sys.path.insert(0, package)  # only to run install(); the add-on file adds it itself
    from boreas.blender.__main__ import install
    folder = os.path.join(out, "addons")
    install([folder])
    sys.path.remove(package)
    sys.path.insert(0, folder)
    module = addon_utils.enable("boreas_wind", default_set=True, handle_error=_raise)
    assert module is not None, "the boreas add-on did not enable"
    assert hasattr(bpy.types, "BOREAS_PT_panel"), "the panel is not registered"
    return module


def _raise(error):
    raise error


def fresh_scene(fps=24, frames=24):
    """An empty scene of `frames` frames from 1 at `fps`."""
    for obj in list(bpy.data.objects):  # the factory scene's cube, light and camera
        bpy.data.objects.remove(obj)
    scene = bpy.context.scene
    scene.render.fps, scene.render.fps_base = fps, 1.0
    scene.frame_start, scene.frame_end = 1, frames
    return scene


def check(condition, message):
    if not condition:
        raise AssertionError(message)
    print("ok:", message)
