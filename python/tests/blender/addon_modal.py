"""Blender test, with its interface (under Xvfb, events simulated): Bake Wind invoked from
the interface runs as a modal operator on a timer, simulating on a worker thread while the
interface stays live, shows its progress in the status bar and finishes with the trees keyed; a second, long bake cancelled with Esc changes nothing; the
panel draws (as a popup, screenshot in <out>/panel.png).

    xvfb-run -a blender --factory-startup --enable-event-simulate --python <this> -- \
        <build>/python <out>

A failure exits with status 1 (exceptions in timers do not end Blender by themselves)."""
import os
import sys
import traceback

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from addon_env import arguments, check, enable_addon, fresh_scene  # noqa: E402

package, out = arguments()
enable_addon(package, out)
from boreas.blender.bake import running  # noqa: E402


def fail_on_error(function):
    def run():
        try:
            return function()
        except BaseException:
            traceback.print_exc()
            sys.stdout.flush()
            os._exit(1)
    return run


def view3d():
    window = bpy.context.window_manager.windows[0]
    area = next(a for a in window.screen.areas if a.type == "VIEW_3D")
    return window, area


state = {}


@fail_on_error
def start():
    fresh_scene(frames=12)
    bpy.ops.boreas.wind_add(kind="waves")
    check(bpy.ops.boreas.grow_tree(species="black_tupelo", seed=2, bone_level=1,
                                   joints_per_branch=2) == {"FINISHED"}, "a tree grows")
    state["rig"] = bpy.context.active_object
    window, area = view3d()
    with bpy.context.temp_override(window=window, area=area):
        result = bpy.ops.boreas.bake("INVOKE_DEFAULT")
    check(result == {"RUNNING_MODAL"}, f"the bake runs modal ({result})")
    bpy.app.timers.register(wait_for_first, first_interval=0.2)


@fail_on_error
def wait_for_first():
    rig = state["rig"]
    if rig.animation_data is None or rig.animation_data.action is None:
        state["polls"] = state.get("polls", 0) + 1
        assert state["polls"] < 600, "the modal bake did not end within 2 minutes"
        return 0.2
    action = rig.animation_data.action
    check(action.frame_range[:] == (1.0, 12.0), "the modal bake keyed frames 1-12")
    state["action"] = action.name
    scene = bpy.context.scene
    scene.frame_end = 100000  # long enough to be cancelled halfway
    for obj in scene.objects:  # the software renderer's redraws would crowd the timers out
        obj.hide_set(True)
    # The interface's turns (a timer every 0.05 s) for 2 s idle, then for 2 s of baking.
    state["phase"], state["ticks"] = "idle", {"idle": 0, "bake": 0}
    bpy.app.timers.register(tick, first_interval=0.05)
    bpy.app.timers.register(start_long_bake, first_interval=2.0)
    return None


def tick():
    if state["phase"] == "done":
        return None
    state["ticks"][state["phase"]] += 1
    return 0.05


@fail_on_error
def start_long_bake():
    window, area = view3d()
    state["phase"] = "bake"
    with bpy.context.temp_override(window=window, area=area):
        result = bpy.ops.boreas.bake("INVOKE_DEFAULT")
    check(result == {"RUNNING_MODAL"}, "the long bake runs modal")
    bpy.app.timers.register(cancel, first_interval=2.0)


@fail_on_error
def cancel():
    state["phase"] = "done"
    bake = running()
    check(bake is not None and 0 < bake.done < bake.frames,
          f"the long bake is under way ({bake.done if bake else None} frames)")
    # The simulation runs on a worker thread: the interface gets its turns as often as
    # when idle (Xvfb's software renderer on a loaded machine gives few either way; a bake
    # on Blender's own thread would give none while it steps).
    idle, baking = state["ticks"]["idle"], state["ticks"]["bake"]
    check(idle > 0 and baking >= idle / 2,
          f"the interface stayed live while baking ({baking} timer turns in 2 s, "
          f"{idle} idle)")
    window, _ = view3d()
    window.event_simulate(type="ESC", value="PRESS")
    window.event_simulate(type="ESC", value="RELEASE")
    bpy.app.timers.register(after_cancel, first_interval=1.0)


@fail_on_error
def after_cancel():
    rig = state["rig"]
    check(running() is None, "Esc ended the long bake")
    check(rig.animation_data.action.name == state["action"],
          "Esc cancelled the long bake and left the first bake's keys")
    # The panel draws without an error (shown as a popup; a screenshot to look at).
    from boreas.blender.panel import BOREAS_PT_panel
    draw = BOREAS_PT_panel.draw

    def checked_draw(self, context):
        try:
            draw(self, context)
            state["drawn"] = True
        except BaseException:
            traceback.print_exc()
            os._exit(1)
    BOREAS_PT_panel.draw = checked_draw
    bpy.ops.boreas.wind_add(kind="gusts")
    bpy.ops.boreas.wind_add(kind="vortices")
    window, area = view3d()
    with bpy.context.temp_override(window=window, area=area):
        bpy.ops.wm.call_panel(name="BOREAS_PT_panel", keep_open=True)
    bpy.app.timers.register(screenshot, first_interval=1.0)


@fail_on_error
def screenshot():
    check(state.get("drawn"), "the panel drew")
    window, area = view3d()
    path = os.path.join(out, "panel.png")
    with bpy.context.temp_override(window=window, area=area):
        bpy.ops.screen.screenshot(filepath=path)
    check(os.path.getsize(path) > 1000, f"screenshot {path}")
    print("addon_modal: all checks passed")
    sys.stdout.flush()
    os._exit(0)


bpy.app.timers.register(start, first_interval=0.5)
