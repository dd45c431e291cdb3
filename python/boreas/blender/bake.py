"""Bake: boreas simulates the scene's frame range at its frame rate and writes the motion
into Blender: every tree's bones keyed every frame, every meadow's strips as a point cache
or shape keys. Invoked from the interface it runs as a modal operator on a timer (progress
in the status bar, Esc cancels and leaves the scene as it was); executed from a script it
runs to the end at once."""
import time

import bpy
import numpy as np
from bpy.props import IntProperty

import boreas

from . import meadow_motion
from .axes import points_to_blender
from .grow import skin_def
from .meadow import strips
from .scene_world import build_world, meadow_objects, tree_objects
from .skin import blender_frames
from .tree_rig import bone_names, key_tree

FRAME_BUDGET = 0.1  # s of simulation per timer tick before the interface gets a turn

_running = []  # the bake in progress in the interface (one at a time)


def running():
    """The modal bake in progress, or None."""
    return _running[0] if _running else None


class Bake:
    """One bake: the world, the frames still to step and what was recorded so far."""

    def __init__(self, scene, frame_start, frame_end):
        if frame_end < frame_start:
            raise ValueError(f"zero frames to bake: frame_end ({frame_end}) is before "
                             f"frame_start ({frame_start})")
        fps = scene.render.fps / scene.render.fps_base
        if not fps > 0:
            raise ValueError(f"the scene's frame rate is {fps:g}")
        if not tree_objects(scene) and not meadow_objects(scene):
            raise ValueError("nothing to bake: grow a tree or plant a meadow first")
        self.scene, self.dt = scene, 1.0 / fps
        self.frame_start, self.frames = frame_start, frame_end - frame_start + 1
        self.world, trees, meadows = build_world(scene)
        try:
            self._bind(trees, meadows)
        except BaseException:
            self.world.close()
            raise
        self.done = 0

    def _bind(self, trees, meadows):
        """Matches the world's trees and meadows with their objects as grown and planted."""
        self.trees = []
        for obj, tree in trees:
            scale = obj.matrix_world.to_scale()
            if max(abs(c - 1.0) for c in scale) > 1e-4:
                raise ValueError(f"tree '{obj.name}' is scaled by {tuple(scale)}: boreas "
                                 f"grows a tree's size (its Scale); keep the object's 1")
            sdef = skin_def(obj.boreas_tree)
            names = bone_names(tree.joints(**sdef)["branch"])
            missing = [n for n in names if n not in obj.data.bones]
            if missing:
                raise ValueError(f"tree '{obj.name}' has no bone '{missing[0]}': grow it again "
                                 f"after changing its species, seed or bones")
            self.trees.append((obj, tree, sdef, names, []))
        self.meadows = []
        for obj, meadow in meadows:
            points, keep, _ = strips(meadow)
            if len(points) != len(obj.data.vertices):
                raise ValueError(f"meadow '{obj.name}' has {len(obj.data.vertices)} vertices, "
                                 f"boreas plants {len(points)}: plant it again")
            self.meadows.append((obj, meadow, keep, []))

    def step(self):
        """Steps one frame and records it; True when every frame is stepped."""
        self.world.step(self.dt)
        for _, tree, sdef, _, frames in self.trees:
            frames.append(blender_frames(tree, sdef))
        for _, meadow, keep, frames in self.meadows:
            vertices, _ = meadow.vertices()
            frames.append(vertices["position"].reshape(-1, 3)[keep])
        self.done += 1
        return self.done == self.frames

    def finish(self):
        """Writes what was recorded into the scene and closes the world."""
        settings = self.scene.boreas
        try:
            for obj, _, _, names, frames in self.trees:
                key_tree(obj, names, np.array(frames), self.frame_start)
            for obj, _, _, frames in self.meadows:
                positions = points_to_blender(np.array(frames))
                if settings.meadow_motion == "MESH_CACHE":
                    meadow_motion.apply_point_cache(obj, positions, self.frame_start,
                                                    1.0 / self.dt, settings.cache_dir)
                else:
                    meadow_motion.apply_shape_keys(obj, positions, self.frame_start)
        finally:
            self.close()

    def close(self):
        self.world.close()


def _frame_range(op, scene):
    start = scene.frame_start if op.frame_start < 0 else op.frame_start
    end = scene.frame_end if op.frame_end < 0 else op.frame_end
    return start, end


class BOREAS_OT_bake(bpy.types.Operator):
    """Simulate the scene's frame range with boreas and key its trees and meadows"""
    bl_idname = "boreas.bake"
    bl_label = "Bake Wind"
    bl_options = {"REGISTER", "UNDO"}

    frame_start: IntProperty(name="Start", default=-1, description="-1: the scene's")
    frame_end: IntProperty(name="End", default=-1, description="-1: the scene's")

    _bake = None
    _timer = None

    def _begin(self, context):
        try:
            self._bake = Bake(context.scene, *_frame_range(self, context.scene))
        except (boreas.Error, ValueError, OSError) as error:
            self.report({"ERROR"}, f"boreas: cannot bake: {error}")
            return False
        return True

    def _end(self, context):
        try:
            self._bake.finish()
        except (boreas.Error, ValueError, OSError) as error:
            self.report({"ERROR"}, f"boreas: the bake could not be written: {error}")
            return {"CANCELLED"}
        context.scene.frame_set(context.scene.frame_current)
        self.report({"INFO"}, f"boreas: baked {self._bake.frames} frames")
        return {"FINISHED"}

    def execute(self, context):
        if not self._begin(context):
            return {"CANCELLED"}
        try:
            while not self._bake.step():
                pass
        except boreas.Error as error:
            self._bake.close()
            self.report({"ERROR"}, f"boreas: the bake stopped: {error}")
            return {"CANCELLED"}
        return self._end(context)

    def invoke(self, context, event):
        if running() is not None:
            self.report({"ERROR"}, "boreas: a bake is running already (Esc cancels it)")
            return {"CANCELLED"}
        if not self._begin(context):
            return {"CANCELLED"}
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.01, window=context.window)
        wm.progress_begin(0, self._bake.frames)
        wm.modal_handler_add(self)
        _running.append(self._bake)
        return {"RUNNING_MODAL"}

    def _stop(self, context):
        wm = context.window_manager
        wm.event_timer_remove(self._timer)
        wm.progress_end()
        context.workspace.status_text_set(None)
        _running.clear()

    def modal(self, context, event):
        if event.type == "ESC":
            self._stop(context)
            self._bake.close()
            self.report({"WARNING"}, "boreas: bake cancelled; nothing was changed")
            return {"CANCELLED"}
        if event.type != "TIMER":
            return {"PASS_THROUGH"}
        bake, until = self._bake, time.perf_counter() + FRAME_BUDGET
        try:
            finished = bake.step()
            while not finished and time.perf_counter() < until:
                finished = bake.step()
        except boreas.Error as error:
            self._stop(context)
            bake.close()
            self.report({"ERROR"}, f"boreas: the bake stopped: {error}")
            return {"CANCELLED"}
        context.window_manager.progress_update(bake.done)
        context.workspace.status_text_set(
            f"boreas: baking frame {bake.done} of {bake.frames} (Esc cancels)")
        if not finished:
            return {"RUNNING_MODAL"}
        self._stop(context)
        return self._end(context)


def register():
    bpy.utils.register_class(BOREAS_OT_bake)


def unregister():
    bpy.utils.unregister_class(BOREAS_OT_bake)
