"""Blender test: bad input gives a Blender error report (the operator reports ERROR and
returns CANCELLED; bpy.ops raises it as a RuntimeError with that message), not a traceback,
and leaves the scene as it was."""
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from addon_env import arguments, check, enable_addon, fresh_scene  # noqa: E402

package, out = arguments()
enable_addon(package, out)


def error_report(call, **kwargs):
    """The error report of an operator call that must fail, and the objects afterwards."""
    before = set(bpy.data.objects.keys())
    try:
        call(**kwargs)
    except RuntimeError as error:
        message = str(error)
    else:
        raise AssertionError(f"{call.idname()} did not fail")
    check("Traceback" not in message, f"{call.idname()} reported without a traceback")
    check(set(bpy.data.objects.keys()) == before, f"{call.idname()} left the scene as it was")
    return message


scene = fresh_scene()
message = error_report(bpy.ops.boreas.bake)
check("nothing to bake" in message, f"an empty scene is refused: {message.strip()}")
missing = os.path.join(out, "no_such_species.json")
message = error_report(bpy.ops.boreas.grow_tree, species="FILE", species_file=missing)
check(message.startswith("Error: boreas: cannot grow the tree") and missing in message,
      f"a missing species file is named: {message.strip()}")

bad = os.path.join(out, "bad_species.json")
with open(bad, "w") as f:
    f.write("{ not json")
message = error_report(bpy.ops.boreas.grow_tree, species="FILE", species_file=bad)
check("bad_species.json" in message, f"a malformed species file is named: {message.strip()}")

check(bpy.ops.boreas.grow_tree(species="black_tupelo", seed=1, bone_level=0,
                               joints_per_branch=2) == {"FINISHED"}, "a tree grows")
message = error_report(bpy.ops.boreas.bake, frame_start=5, frame_end=4)
check("zero frames" in message, f"zero frames are refused: {message.strip()}")

rig = bpy.context.active_object
rig.scale = (2.0, 2.0, 2.0)
message = error_report(bpy.ops.boreas.bake)
check("is scaled" in message, f"a scaled tree is refused: {message.strip()}")
rig.scale = (1.0, 1.0, 1.0)
rig.boreas_tree.species, rig.boreas_tree.species_file = "FILE", missing
message = error_report(bpy.ops.boreas.bake)
check(missing in message, f"a tree whose species file is gone is named: {message.strip()}")
check(rig.animation_data is None or rig.animation_data.action is None,
      "the failed bake keyed nothing")
