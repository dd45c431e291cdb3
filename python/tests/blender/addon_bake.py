"""Blender test: the add-on grows a tree and plants a small meadow, bakes 24 frames at 24
fps, and what Blender plays back is what boreas simulated: the tip bone of every boned
branch at frames 1 and 24 sits on boreas's branch tip of the same world (within 1 mm), the
meadow's strips equal boreas's and move downwind; one small Workbench frame is rendered."""
import os
import sys

import bpy
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from addon_env import arguments, check, enable_addon, fresh_scene  # noqa: E402

TIP_TOLERANCE = 1e-3  # m
FRAMES = 24

package, out = arguments()
enable_addon(package, out)
from boreas.blender.axes import points_to_blender, points_to_boreas  # noqa: E402
from boreas.blender.scene_world import build_world  # noqa: E402
from boreas.blender.skin import joint_frames  # noqa: E402

scene = fresh_scene(frames=FRAMES)
scene.boreas.cache_dir = os.path.join(out, "cache")
bpy.ops.boreas.wind_add(kind="waves")
wave = scene.boreas.waves[0]
wave.heading, wave.amplitude, wave.wavelength, wave.speed = 0.0, 9.0, 40.0, 6.0  # along +X
bpy.ops.boreas.wind_add(kind="gusts")
gust = scene.boreas.gusts[0]
gust.heading, gust.strength, gust.delay, gust.rise, gust.hold = 0.0, 5.0, 0.0, 0.3, 2.0
bpy.ops.boreas.wind_add(kind="vortices")
vortex = scene.boreas.vortices[0]
vortex.location, vortex.strength, vortex.radius = (4.0, -4.0, 0.0), 6.0, 4.0  # off the plants

scene.cursor.location = (1.5, 2.0, 0.0)
check(bpy.ops.boreas.grow_tree(species="quaking_aspen", seed=3, mode="exact",
                               response="damped", bone_level=1,
                               joints_per_branch=4) == {"FINISHED"}, "grow_tree finished")
rig = bpy.context.active_object
check(rig.type == "ARMATURE" and rig.boreas_tree.is_tree, "the tree is an armature")
rig.rotation_euler.z = 0.6  # turned after growing: the bake grows it turned (boreas's rotation)
scene.cursor.location = (-3.0, 7.0, 0.0)
check(bpy.ops.boreas.grow_tree(species="quaking_aspen", seed=3, mode="lagged",
                               response="quasi_static", bone_level=1,
                               joints_per_branch=4) == {"FINISHED"}, "a second tree grows")
twin = bpy.context.active_object
check(twin.data == rig.data and twin.children[0].data == rig.children[0].data,
      "a tree of the same template shares the first one's armature and mesh")
twin.rotation_euler.z = -1.1

bpy.ops.mesh.primitive_plane_add(size=3.0, location=(-4.0, 0.0, 0.4))
ground = bpy.context.active_object
ground.rotation_euler = (0.2, 0.0, 0.0)  # a slope: heights come from the mesh
ground.data.materials.append(bpy.data.materials.new("soil"))
ground.data.materials[0].diffuse_color = (0.25, 0.18, 0.12, 1.0)
check(bpy.ops.boreas.plant_meadow(density=60.0, seed=2, resolution=16) == {"FINISHED"},
      "plant_meadow finished")
meadow_obj = next(o for o in scene.objects if o.boreas_meadow.is_meadow)
rest = np.array([v.co[:] for v in meadow_obj.data.vertices])
check(len(rest) > 100, f"the meadow has {len(rest)} strip vertices")
# the strips stand on the slope: their lowest points follow the plane's heights
lows = rest[:, 2].min(), rest[:, 2].max()
check(lows[0] > 0.4 - 0.35 and lows[0] < 0.4, f"the meadow stands on the tilted ground {lows}")

def swirl(world, center, radius=2.0, height=1.5):
    """m/s, the mean counter-clockwise tangential wind on a ring about Blender's up axis."""
    angles = np.linspace(0, 2 * np.pi, 16, endpoint=False)
    ring = np.column_stack([np.cos(angles), np.sin(angles), np.zeros(16)])
    points = ring * radius + (center[0], center[1], height)
    wind = points_to_blender(world.wind.sample(points_to_boreas(points).astype(np.float32)))
    tangent = np.column_stack([-np.sin(angles), np.cos(angles), np.zeros(16)])
    return float(np.einsum("ij,ij->i", wind, tangent).mean())


def reference(scene):
    """The same world, stepped here: per tree (in the scene's order) its skin at rest, its
    branches at frames 1 and 24, its joints and mesh at 24; the meadow's strips at 1 and 24."""
    from boreas.blender.mesh_data import strip_layout
    world, trees, meadows = build_world(scene)
    meadow = meadows[0][1]
    out = []
    for obj, tree in trees:
        sdef = dict(max_level=obj.boreas_tree.bone_level,
                    segments=obj.boreas_tree.joints_per_branch)
        rest_joints, vertex_weights, _ = tree.skin(**sdef)
        out.append(dict(rig=obj, tree=tree, sdef=sdef, rest_joints=rest_joints,
                        vertex_weights=vertex_weights, branches={},
                        rest_mesh=tree.mesh()[0]["position"].astype(np.float64)))
    strips = {}
    for step in range(1, FRAMES + 1):
        world.step(1.0 / 24)
        if step in (1, FRAMES):
            for t in out:
                t["branches"][step] = t["tree"].branches.copy()
                t["joints"] = t["tree"].joints(**t["sdef"])
                t["mesh"] = t["tree"].mesh()[0]["position"].astype(np.float64)
            v, counts = meadow.vertices()
            keep, _ = strip_layout(counts, v.shape[1])
            strips[step] = points_to_blender(v["position"].reshape(-1, 3)[keep])
    # The vortex turns counter-clockwise seen from above (right-handed about up) where it
    # was set: the mean tangential wind on a ring around it (uniform wind cancels) is
    # positive there and nothing on a ring as large 10 m away.
    check(swirl(world, (4.0, -4.0)) > 0.2 and abs(swirl(world, (4.0, 6.0))) < 0.02,
          f"the vortex turns about up where it was set (mean tangential wind "
          f"{swirl(world, (4.0, -4.0)):.2f} m/s there, {swirl(world, (4.0, 6.0)):.3f} m/s "
          f"10 m away)")
    world.close()
    return out, strips


def check_tips(motion, t, frame):
    """The tip bone of every boned branch sits on boreas's branch tip; returns the tips."""
    rig, branches = t["rig"], t["branches"][frame]
    boned = np.nonzero(branches["level"] <= rig.boreas_tree.bone_level)[0]
    k = rig.boreas_tree.joints_per_branch
    heads = np.array([(rig.matrix_world @ rig.pose.bones[f"b{b}.{k}"].head)[:] for b in boned])
    tips = branches["control_points"][boned, 3].astype(np.float64)
    error = np.linalg.norm(points_to_boreas(heads) - tips, axis=1)
    check(error.max() < TIP_TOLERANCE,
          f"{motion} frame {frame} {rig.name}: {len(boned)} tip bones on boreas's branch "
          f"tips (largest miss {error.max() * 1e3:.3f} mm)")
    return tips


def check_bark(motion, t):
    """The skinned bark at frame 24: Blender's armature deforms it as linear blend skinning
    of boreas's skin does (computed here in double), and that follows boreas's own mesh."""
    body = t["rig"].children[0].evaluated_get(bpy.context.evaluated_depsgraph_get())
    rest_mesh = t["rest_mesh"]
    local = np.array([v.co[:] for v in body.data.vertices])[:len(rest_mesh)]
    to_world = np.array(body.matrix_world)
    bark = points_to_boreas(local @ to_world[:3, :3].T + to_world[:3, 3])
    deform = joint_frames(t["joints"]) @ np.linalg.inv(joint_frames(t["rest_joints"]))
    blended = np.zeros_like(rest_mesh)
    weights = t["vertex_weights"]
    for slot in range(4):
        d = deform[weights["joints"][:, slot]]
        moved = np.einsum("vij,vj->vi", d[:, :3, :3], rest_mesh) + d[:, :3, 3]
        blended += weights["weights"][:, slot, None] * moved
    miss = np.linalg.norm(bark - blended, axis=1).max()
    check(miss < 1e-4, f"{motion} {t['rig'].name}: Blender's skinned bark is boreas's skin "
                       f"blended (largest miss {miss * 1e3:.3f} mm)")
    off = np.linalg.norm(bark - t["mesh"], axis=1)
    rms = np.sqrt((off ** 2).mean())
    # Bones down to level 1: level-2 and 3 branches ride rigidly on them and miss their own
    # bend (about 9 mm rms, 12 cm at the worst twig tip here); a wrong binding misses by m.
    check(rms < 0.02, f"{motion} {t['rig'].name}: the skinned bark follows boreas's mesh at "
                      f"frame 24 (rms {rms * 1e3:.2f} mm, max {off.max() * 1e3:.1f} mm)")


for motion in ("MESH_CACHE", "SHAPE_KEYS"):
    scene.boreas.meadow_motion = motion
    check(bpy.ops.boreas.bake() == {"FINISHED"}, f"bake finished ({motion})")
    trees, strips = reference(scene)
    check(len(trees) == 2, "both trees are in the world")
    first_tips = {}
    for frame in (1, FRAMES):
        scene.frame_set(frame)
        for t in trees:
            tips = check_tips(motion, t, frame)
            first_tips.setdefault(t["rig"].name, tips)
        evaluated = meadow_obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
        played = np.array([v.co[:] for v in evaluated.data.vertices])
        miss = np.abs(played - strips[frame]).max()
        check(miss < 1e-4, f"{motion} frame {frame}: the meadow plays boreas's strips "
                           f"(largest miss {miss:.2e} m)")
    for t in trees:
        check_bark(motion, t)
    moved = np.linalg.norm(tips - first_tips[trees[-1]["rig"].name], axis=1).max()
    check(moved > 0.01, f"the tree moved between frames 1 and 24 ({moved:.3f} m at most)")
    downwind = (played - rest)[:, 0]  # Blender +X is the wind's heading
    check(downwind.mean() > 1e-3 and (downwind > 0).mean() > 0.6,
          f"{motion}: the meadow leans downwind (mean {downwind.mean() * 1e3:.1f} mm, "
          f"{(downwind > 0).mean():.0%} of vertices downwind)")

# Species from files: a boreas JSON and an Arbaro XML grow too (not baked).
repo = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", ".."))
for path in ("host/species/weeping_willow.json", "tests/data/arbaro/barley.xml"):
    scene.cursor.location = (30.0, 0.0, 0.0)
    check(bpy.ops.boreas.grow_tree(species="FILE", species_file=os.path.join(repo, path),
                                   seed=1) == {"FINISHED"}, f"a tree grows from {path}")
    grown = bpy.context.active_object
    check(grown.boreas_tree.species_file.endswith(path) and len(grown.data.bones) > 0,
          f"{grown.name} has {len(grown.data.bones)} bones")
    bpy.data.objects.remove(grown.children[0])
    bpy.data.objects.remove(grown)

# One small Workbench frame of the baked scene, to look at.
scene.frame_set(12)
camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
scene.collection.objects.link(camera)
camera.location = (-1.0, -24.0, 7.0)
camera.rotation_euler = (1.47, 0.0, 0.0)
scene.camera = camera
scene.render.engine = "BLENDER_WORKBENCH"
scene.display.shading.color_type = "MATERIAL"
scene.render.resolution_x, scene.render.resolution_y = 320, 240
scene.render.resolution_percentage = 100
scene.render.filepath = os.path.join(out, "frame_12.png")
bpy.ops.render.render(write_still=True)
check(os.path.getsize(scene.render.filepath) > 1000, f"rendered {scene.render.filepath}")
