"""The one workaround the Blender tests need, written once: Debian's Blender 3.4 glTF
importer (io_scene_gltf2/blender/imp/gltf2_blender_mesh.py, set_poly_smoothing) spells
NumPy's bool `np.bool`, an alias NumPy 1.24 (Debian's) removed, so importing any mesh
raises AttributeError. restore() puts the alias back (it is the builtin bool, as it was
before NumPy removed it) only where NumPy lacks it and the importer still spells it, and
says so; importer_needs_it() tells whether it is still needed, so the workaround can go
when Debian's importer is fixed (blender_numpy_bool_test.py fails then, saying so)."""
import os

import numpy

IMPORTER_FILE = os.path.join("io_scene_gltf2", "blender", "imp", "gltf2_blender_mesh.py")


def importer_source():
    """The text of the importer's mesh module as the running Blender has it."""
    import io_scene_gltf2  # Blender's bundled add-on
    folder = os.path.dirname(os.path.dirname(io_scene_gltf2.__file__))
    with open(os.path.join(folder, IMPORTER_FILE), encoding="utf-8") as f:
        return f.read()


def importer_needs_it():
    """Whether the importer spells np.bool and this NumPy has no such attribute."""
    return "np.bool)" in importer_source() and "bool" not in vars(numpy)


def restore():
    """Puts numpy.bool back where the importer needs it; returns whether it did."""
    if not importer_needs_it():
        return False
    numpy.bool = bool
    print("boreas tests: numpy.bool restored for Blender's glTF importer "
          "(tests/web/blender_numpy_bool.py)")
    return True
