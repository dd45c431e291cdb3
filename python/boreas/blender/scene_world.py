"""The boreas world a Blender scene describes: its trees (armatures the grow operator made),
its meadows (on the mesh they were planted on) and its wind, in boreas's axes. The bake and
the tests build their worlds here, so both simulate the same thing."""
import math

import bpy
import numpy as np
from mathutils import Vector
from mathutils.bvhtree import BVHTree

import boreas

from .axes import points_to_boreas

GRID_CELL = 2.0        # m, the wind grid's cell when the scene is small enough
GRID_MAX_SIDE = 128    # cells along x and z at most; larger scenes get larger cells
GRID_HEIGHT = 40.0     # m of air above the lowest plant the grid covers
GRID_MARGIN = 10.0     # m around the plants


def tree_objects(scene):
    return [o for o in scene.objects if o.type == "ARMATURE" and o.boreas_tree.is_tree]


def meadow_objects(scene):
    return [o for o in scene.objects if o.type == "MESH" and o.boreas_meadow.is_meadow]


def tree_def(obj):
    """boreas_tree_def of a tree's armature: where the object stands and how it turns about
    Z (its other rotations and its scale are not the tree's: use the tree's scale)."""
    s = obj.boreas_tree
    base = points_to_boreas(np.array(obj.matrix_world.translation))
    return dict(species=s.species_value(), position=tuple(base), seed=s.seed,
                rotation=obj.matrix_world.to_euler().z, scale=s.scale, mode=s.mode,
                response=s.response)


def ground_map(ground, resolution):
    """A meadow's ground from a mesh object: (center, size, terrain, nutrients) for
    World.add_meadow. Heights come from rays cast down onto the mesh over its bounding
    rectangle; where a ray misses, nothing grows (nutrients 0)."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = ground.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        world = ground.matrix_world
        verts = [world @ v.co for v in mesh.vertices]
        polys = [tuple(p.vertices) for p in mesh.polygons]
    finally:
        evaluated.to_mesh_clear()
    if not polys:
        raise ValueError(f"ground '{ground.name}' has no faces to plant on")
    tree = BVHTree.FromPolygons(verts, polys)
    lo = np.min(np.array(verts), axis=0)
    hi = np.max(np.array(verts), axis=0)
    extent = np.maximum(hi[:2] - lo[:2], 0.01)
    step = float(max(extent)) / (resolution - 1)
    columns = max(2, int(math.ceil(extent[0] / step)) + 1)   # along Blender x = boreas x
    rows = max(2, int(math.ceil(extent[1] / step)) + 1)      # along Blender -y = boreas z
    terrain = np.full((rows, columns), lo[2], np.float32)
    nutrients = np.zeros((rows, columns, 3), np.float32)
    top = hi[2] + 1.0
    for r in range(rows):
        y = hi[1] - extent[1] * r / (rows - 1)        # row 0 on boreas's -z side: Blender +y
        for c in range(columns):
            x = lo[0] + extent[0] * c / (columns - 1)
            hit = tree.ray_cast(Vector((x, y, top)), Vector((0.0, 0.0, -1.0)))
            if hit[0] is not None:
                terrain[r, c] = hit[0].z
                nutrients[r, c] = 1.0
    center = ((lo[0] + hi[0]) / 2, 0.0, -(lo[1] + hi[1]) / 2)
    return center, (float(extent[0]), float(extent[1])), terrain, nutrients


def meadow_def(s, what):
    """World.add_meadow's arguments from meadow settings; `what` names the meadow in
    errors."""
    if s.ground is None:
        raise ValueError(f"{what} has no ground mesh")
    if not s.species:
        raise ValueError(f"{what} has no species")
    center, size, terrain, nutrients = ground_map(s.ground, s.resolution)
    return dict(species=sorted(s.species), center=center, size=size, density=s.density,
                seed=s.seed, terrain=terrain, terrain_relief=1.0, nutrients=nutrients)


def _heading(angle):
    """A heading in Blender's ground plane (from +X towards +Y) as boreas's (x, z)."""
    return (math.cos(angle), -math.sin(angle))


def waves(settings):
    return [boreas.Wave(direction=_heading(w.heading), amplitude=w.amplitude,
                        wavelength=w.wavelength, speed=w.speed, sharpness=w.sharpness)
            for w in settings.waves]


def grid_around(points):
    """A wind grid covering boreas points (N, 3) with a margin, cells of GRID_CELL where
    GRID_MAX_SIDE cells allow it."""
    points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    if len(points) == 0:
        points = np.zeros((1, 3))
    lo = points.min(axis=0) - GRID_MARGIN
    hi = points.max(axis=0) + GRID_MARGIN
    side = float(max(hi[0] - lo[0], hi[2] - lo[2]))
    cell = max(GRID_CELL, side / GRID_MAX_SIDE)
    nx = max(2, int(math.ceil((hi[0] - lo[0]) / cell)))
    nz = max(2, int(math.ceil((hi[2] - lo[2]) / cell)))
    ny = max(2, int(math.ceil(GRID_HEIGHT / cell)))
    return boreas.Grid(origin=(lo[0], points[:, 1].min() - cell, lo[2]), cell_size=cell,
                       resolution=(nx, ny, nz))


def grid_wind(settings):
    """The scene's gusts and vortices as World.wind's arguments: (gusts, primitives)."""
    gusts = [dict(direction=(_heading(g.heading)[0], 0.0, _heading(g.heading)[1]),
                  strength=g.strength, delay=g.delay, rise=g.rise, hold=g.hold, fall=g.fall,
                  center=tuple(points_to_boreas(np.array(g.center))), radius=g.radius)
             for g in settings.gusts]
    vortices = [dict(type="vortex", position=tuple(points_to_boreas(np.array(v.location))),
                     direction=(0.0, 1.0, 0.0), strength=v.strength, radius=v.radius,
                     lifetime=v.lifetime)
                for v in settings.vortices]
    return gusts, vortices


class Plan:
    """What the scene asks boreas to simulate, read from Blender (on Blender's thread) so
    that the world can be built and stepped on another: the tree and meadow objects and
    their definitions, the grid, the waves, gusts and vortices, the device."""

    def __init__(self, scene):
        settings = scene.boreas
        self.trees = tree_objects(scene)
        self.meadows = meadow_objects(scene)
        self.tree_defs = [tree_def(o) for o in self.trees]
        self.meadow_defs = [meadow_def(o.boreas_meadow, f"meadow '{o.name}'")
                            for o in self.meadows]
        anchors = [d["position"] for d in self.tree_defs]
        for d in self.meadow_defs:
            c, (sx, sz) = d["center"], d["size"]
            anchors += [(c[0] - sx / 2, float(d["terrain"].min()), c[2] - sz / 2),
                        (c[0] + sx / 2, float(d["terrain"].max()), c[2] + sz / 2)]
        self.grid = grid_around(anchors)
        self.waves = waves(settings)
        self.gusts, self.primitives = grid_wind(settings)
        self.device = settings.device or None

    def build(self):
        """A new boreas.World of the plan, at rest; touches no Blender data. Returns (world,
        trees, meadows), the handles in the order of self.trees and self.meadows. Raises
        boreas.Error naming what is wrong; the caller closes the world."""
        world = boreas.World(device=self.device, grid=self.grid, waves=self.waves)
        try:
            for gust in self.gusts:
                world.wind.add_gust(**gust)
            for primitive in self.primitives:
                world.wind.add_primitive(**primitive)
            trees = world.add_trees(self.tree_defs) if self.tree_defs else []
            meadows = [world.add_meadow(**d) for d in self.meadow_defs]
        except BaseException:
            world.close()
            raise
        return world, trees, meadows


def build_world(scene):
    """A new boreas.World with the scene's wind, trees and meadows, at rest.

    Returns (world, [(object, boreas.Tree)], [(object, boreas.Meadow)]). Raises boreas.Error,
    ValueError or OSError with a message naming what is wrong; the caller closes the world.
    """
    plan = Plan(scene)
    world, trees, meadows = plan.build()
    return world, list(zip(plan.trees, trees)), list(zip(plan.meadows, meadows))
