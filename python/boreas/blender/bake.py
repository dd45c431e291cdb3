"""Bake: boreas simulates the scene's frame range at its frame rate and writes the motion
into Blender: every tree's bones keyed every frame, every meadow as instanced clumps
(meadow_instances.py), or its strips as a point cache or shape keys.

Three stages: the plan is read from Blender (its thread), the world is built and stepped on
a worker thread that touches no Blender data (boreas releases Python's lock while it
works, so the interface stays live, even while kernels compile), and what was recorded is
checked and written into Blender (its thread again), all or nothing. Invoked from the
interface it is a modal operator polling the worker on a timer (progress in the status bar,
Esc cancels and leaves the scene as it was); executed from a script it runs to the end."""
import threading

import bpy
import numpy as np
from bpy.props import IntProperty

import boreas

from . import meadow_instances, meadow_motion
from .axes import points_to_blender
from .grow import skin_def
from .clump_plan import ClumpPlan
from .meadow import strips
from .scene_world import Plan, meadow_objects, tree_objects
from .skin import blender_frames
from .tree_rig import bone_names, key_tree

POLL_SECONDS = 0.1  # how often the interface looks at the worker

_running = []  # the bake in progress in the interface (one at a time)


def running():
    """The modal bake in progress, or None."""
    return _running[0] if _running else None


class MeadowLayout:
    """What the instanced clumps need of a meadow at rest: its components, the kept strip
    vertices (keep, in rows of stride) and their triangles."""

    def __init__(self, meadow):
        self.stride = meadow.vertices()[0].shape[1]
        _, self.keep, self.triangles = strips(meadow)
        self.components = meadow.components


class Bake:
    """One bake: the plan, the worker's progress and what it recorded."""

    def __init__(self, scene, frame_start, frame_end):
        if frame_end < frame_start:
            raise ValueError(f"zero frames to bake: frame_end ({frame_end}) is before "
                             f"frame_start ({frame_start})")
        fps = scene.render.fps / scene.render.fps_base
        if not fps > 0:
            raise ValueError(f"the scene's frame rate is {fps:g}")
        if not tree_objects(scene) and not meadow_objects(scene):
            raise ValueError("nothing to bake: grow a tree or plant a meadow first")
        for obj in tree_objects(scene):
            scale = obj.matrix_world.to_scale()
            if max(abs(c - 1.0) for c in scale) > 1e-4:
                raise ValueError(f"tree '{obj.name}' is scaled by {tuple(scale)}: boreas "
                                 f"grows a tree's size (its Scale); keep the object's 1")
        self.scene, self.dt = scene, 1.0 / fps
        self.frame_start, self.frames = frame_start, frame_end - frame_start + 1
        self.plan = Plan(scene)
        # Instanced clumps (their settings read here, on Blender's thread) seek their loops
        # in frames past the last (clump_plan.py).
        b = scene.boreas
        self.clumps = ((b.meadow_clumps, b.clump_size, b.clump_phases)
                       if b.meadow_motion == "INSTANCES" else None)
        self.loop_frames = 2 * (self.frames - 1) if self.plan.meadows and self.clumps else 0
        self.skin_defs = [skin_def(o.boreas_tree) for o in self.plan.trees]
        self.done = 0
        self.error = None
        self.cancel = threading.Event()
        self.bones = []         # per tree, the bone of each joint
        self.tree_frames = []   # per tree, per frame (J, 4, 4) joint frames, Blender world
        self.meadow_frames = []  # per meadow, per frame (N, 3) strip vertices, boreas
        self.layouts = []        # per meadow, its MeadowLayout
        self.clump_plans = []    # per meadow, its ClumpPlan where instanced

    def simulate(self):
        """Builds the world and steps it over the frames, recording each (any thread; no
        Blender data). A boreas error is kept in self.error; self.cancel stops it."""
        try:
            world, trees, meadows = self.plan.build()
        except (boreas.Error, ValueError, OSError) as error:
            self.error = error
            return
        try:
            self.bones = [bone_names(t.joints(**d)["branch"])
                          for t, d in zip(trees, self.skin_defs)]
            self.layouts = [MeadowLayout(m) for m in meadows]
            if self.clumps:  # only the clumps' vertices are recorded
                self.clump_plans = [ClumpPlan(l.components, l.keep, l.stride, *self.clumps)
                                    for l in self.layouts]
            recorded = [l.keep[p.vertices] if p else l.keep for l, p in
                        zip(self.layouts, self.clump_plans or [None] * len(meadows))]
            self.tree_frames = [[] for _ in trees]
            self.meadow_frames = [[] for _ in meadows]
            for step in range(self.frames + self.loop_frames):
                if self.cancel.is_set():
                    return
                world.step(self.dt)
                for tree, sdef, frames in zip(trees, self.skin_defs, self.tree_frames):
                    if step < self.frames:
                        frames.append(blender_frames(tree, sdef))
                for meadow, kept, frames in zip(meadows, recorded, self.meadow_frames):
                    frames.append(meadow.vertices()[0]["position"].reshape(-1, 3)[kept])
                self.done += 1
        except (boreas.Error, ValueError, OSError) as error:
            self.error = error
        finally:
            world.close()

    def _check(self):
        """Raises ValueError when an object no longer matches what boreas grew for it."""
        for obj, names in zip(self.plan.trees, self.bones):
            missing = [n for n in names if n not in obj.data.bones]
            if missing:
                raise ValueError(f"tree '{obj.name}' has no bone '{missing[0]}': grow it again "
                                 f"after changing its species, seed or bones")
        for obj, layout in zip(self.plan.meadows, self.layouts):
            if len(layout.keep) != len(obj.data.vertices):
                raise ValueError(f"meadow '{obj.name}' has {len(obj.data.vertices)} vertices, "
                                 f"boreas plants {len(layout.keep)}: plant it again")

    def write(self):
        """Writes what was recorded into the scene (Blender's thread), after checking every
        object, so that a refused bake writes nothing."""
        self._check()
        settings = self.scene.boreas
        for obj, names, frames in zip(self.plan.trees, self.bones, self.tree_frames):
            key_tree(obj, names, np.array(frames), self.frame_start)
        for i, (obj, frames, layout) in enumerate(zip(self.plan.meadows, self.meadow_frames,
                                                      self.layouts)):
            if self.clumps:
                meadow_instances.apply_instances(bpy.context, obj, np.array(frames), self.frames,
                                                 self.clump_plans[i], layout, self.frame_start,
                                                 settings.cache_dir)
                continue
            meadow_instances.clear(obj)
            positions = points_to_blender(np.array(frames[:self.frames]))
            if settings.meadow_motion == "MESH_CACHE":
                meadow_motion.apply_point_cache(obj, positions, self.frame_start,
                                                1.0 / self.dt, settings.cache_dir)
            else:
                meadow_motion.apply_shape_keys(obj, positions, self.frame_start)


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
    _worker = None

    def _begin(self, context):
        try:
            self._bake = Bake(context.scene, *_frame_range(self, context.scene))
        except (boreas.Error, ValueError, OSError) as error:
            self.report({"ERROR"}, f"boreas: cannot bake: {error}")
            return False
        return True

    def _end(self, context):
        bake = self._bake
        if bake.error is not None:
            self.report({"ERROR"}, f"boreas: cannot bake: {bake.error}")
            return {"CANCELLED"}
        try:
            bake.write()
        except (ValueError, OSError) as error:
            self.report({"ERROR"}, f"boreas: cannot bake: {error}")
            return {"CANCELLED"}
        context.scene.frame_set(context.scene.frame_current)
        self.report({"INFO"}, f"boreas: baked {bake.frames} frames")
        return {"FINISHED"}

    def execute(self, context):
        if not self._begin(context):
            return {"CANCELLED"}
        self._bake.simulate()
        return self._end(context)

    def invoke(self, context, event):
        if running() is not None:
            self.report({"ERROR"}, "boreas: a bake is running already (Esc cancels it)")
            return {"CANCELLED"}
        if not self._begin(context):
            return {"CANCELLED"}
        self._worker = threading.Thread(target=self._bake.simulate, name="boreas bake",
                                        daemon=True)
        self._worker.start()
        wm = context.window_manager
        self._timer = wm.event_timer_add(POLL_SECONDS, window=context.window)
        wm.progress_begin(0, self._bake.frames + self._bake.loop_frames)
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
        bake = self._bake
        if event.type == "ESC":
            bake.cancel.set()  # the worker stops at its next frame and closes the world;
            self._stop(context)  # not waited for: it may be compiling kernels
            self.report({"WARNING"}, "boreas: bake cancelled; nothing was changed")
            return {"CANCELLED"}
        if event.type != "TIMER":
            return {"PASS_THROUGH"}
        if self._worker.is_alive():
            context.window_manager.progress_update(bake.done)
            context.workspace.status_text_set(
                f"boreas: baking frame {bake.done} of {bake.frames + bake.loop_frames} "
                f"(Esc cancels)")
            return {"PASS_THROUGH"}
        self._stop(context)
        return self._end(context)


def register():
    bpy.utils.register_class(BOREAS_OT_bake)


def unregister():
    bpy.utils.unregister_class(BOREAS_OT_bake)
