"""Imported tree meshes and BlobTrees: a small tube tree written as OBJ, its arrays and
motion; preprocessing to glTF; a BlobTree of a world's tree with a progress callable."""
import math

import numpy as np
import pytest

import boreas


def tube(out, base, direction, length, r0, r1, sides=6, rings=4):
    """A tapered open tube (one connected run of triangles) appended to out."""
    d = np.asarray(direction, float) / np.linalg.norm(direction)
    ref = np.array([0, 1, 0.0]) if abs(d[1]) < 0.9 else np.array([1.0, 0, 0])
    a = np.cross(d, ref)
    a /= np.linalg.norm(a)
    b = np.cross(d, a)
    first = len(out["v"])
    for i in range(rings + 1):
        u = i / rings
        r = r0 + u * (r1 - r0)
        for j in range(sides):
            phi = 2 * math.pi * j / sides
            out["v"].append(np.asarray(base) + u * length * d + r * (math.cos(phi) * a +
                                                                     math.sin(phi) * b))
    for i in range(rings):
        for j in range(sides):
            v00 = first + i * sides + j
            v01 = first + i * sides + (j + 1) % sides
            v10, v11 = v00 + sides, v01 + sides
            out["f"] += [(v00, v10, v11), (v00, v11, v01)]
    return np.asarray(base) + length * d


def write_tube_tree(path):
    """A 6 m stem with three limbs, a leaf quad at each limb's tip."""
    trunk = {"v": [], "f": []}
    leaves = {"v": [], "f": []}
    tube(trunk, (0, 0, 0), (0, 1, 0), 6.0, 0.25, 0.1)
    for k in range(3):
        angle = 2 * math.pi * k / 3
        direction = (math.cos(angle), 0.8, math.sin(angle))
        tip = tube(trunk, (0, 2.0 + k, 0), direction, 2.0, 0.08, 0.03)
        n = len(leaves["v"])
        leaves["v"] += [tip + (-0.1, 0, 0), tip + (0.1, 0, 0), tip + (0.1, 0.2, 0),
                        tip + (-0.1, 0.2, 0)]
        leaves["f"] += [(n, n + 1, n + 2), (n, n + 2, n + 3)]
    with open(path, "w") as f:
        base = 1
        for name, part in (("trunk", trunk), ("leaves", leaves)):
            f.write(f"o {name}\n")
            for v in part["v"]:
                f.write("v %.6f %.6f %.6f\n" % tuple(v))
            for t in part["f"]:
                f.write("f %d %d %d\n" % tuple(i + base for i in t))
            base += len(part["v"])
    return len(trunk["v"]), len(trunk["f"]), len(leaves["v"]), len(leaves["f"])


def test_mesh_tree_arrays_info_and_sway(world, tmp_path):
    model = tmp_path / "tubes.obj"
    tv, tt, lv, lt = write_tube_tree(model)
    tree = world.add_mesh_tree(model, position=(1.0, 0.0, 0.0), cache=False)
    info = tree.info
    assert isinstance(info, boreas.MeshTreeInfo)
    assert (info.trunk_triangles, info.leaf_triangles) == (tt, lt)
    assert info.branches == 4 and info.leaves == 3
    assert not info.from_cache
    for part, triangles in (("trunk", tt), ("leaves", lt)):
        vertices = tree.vertices(part)
        indices = tree.indices(part)
        assert vertices.dtype == boreas.VERTEX_DTYPE
        assert indices.dtype == np.uint32 and indices.shape == (triangles, 3)
        assert indices.max() < len(vertices)
    rest = tree.vertices("trunk")["position"].copy()
    at_origin = world.add_mesh_tree(model, cache=False).vertices("trunk")["position"]
    np.testing.assert_allclose(rest - at_origin, np.tile([1.0, 0.0, 0.0], (len(rest), 1)),
                               atol=1e-5, err_msg="placed at x = 1")
    for _ in range(10):
        world.step(1 / 30)
    moved = tree.vertices("trunk")["position"] - rest
    top = rest[:, 1] > 4.0
    assert moved[top, 0].mean() > 1e-3, "the crown moves downwind (+x)"
    with pytest.raises(ValueError, match="'trunk', 'leaves'"):
        tree.vertices("roots")
    tree.remove()
    with pytest.raises(boreas.NotFoundError):
        tree.info


def test_mesh_tree_file_errors(world, tmp_path):
    with pytest.raises(boreas.FileError, match="no such file") as info:
        world.add_mesh_tree(tmp_path / "missing.obj")
    assert isinstance(info.value, OSError) and info.value.status == 7


def test_preprocess_mesh_tree_writes_a_glb_that_loads(world, tmp_path):
    model = tmp_path / "tubes.obj"
    write_tube_tree(model)
    out = tmp_path / "tubes.glb"
    info = boreas.preprocess_mesh_tree(model, out)
    assert out.stat().st_size > 0
    assert info.branches == 4
    tree = world.add_mesh_tree(out, cache=False)
    assert tree.info.branches == 4


def test_blobtree_with_progress(world):
    tree = world.add_tree("quaking_aspen")
    reports = []
    blob = tree.add_blobtree(resolution=32, max_level=1,
                             progress=lambda f, stage: reports.append((f, stage)))
    info = blob.info
    assert isinstance(info, boreas.BlobTreeInfo)
    vertices, triangles = blob.mesh()
    assert len(vertices) == info.vertices and len(triangles) == info.triangles > 0
    assert vertices.dtype == boreas.VERTEX_DTYPE and triangles.dtype == np.uint32
    lo, hi = np.array(info.bounds_min), np.array(info.bounds_max)
    assert (vertices["position"] >= lo - 1e-3).all() and (vertices["position"] <= hi + 1e-3).all()
    # Watertight: every edge is shared by exactly two triangles.
    edges = np.sort(triangles[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1)
    _, counts = np.unique(edges, axis=0, return_counts=True)
    assert (counts == 2).all()
    assert reports and all(0.0 <= f <= 1.0 for f, _ in reports)
    assert all(isinstance(stage, str) and stage for _, stage in reports)
    blob.remove()
    with pytest.raises(boreas.NotFoundError):
        blob.mesh()


def test_blobtree_progress_exception_propagates(world):
    tree = world.add_tree("quaking_aspen")

    def fail(fraction, stage):
        raise KeyError("stop")

    with pytest.raises(KeyError, match="stop"):
        world.add_blobtree(tree, resolution=32, max_level=0, progress=fail)


def test_blobtree_progress_must_not_call_into_its_world(world):
    tree = world.add_tree("quaking_aspen")
    with pytest.raises(boreas.Error, match="must not call into the world"):
        world.add_blobtree(tree, resolution=32, max_level=0, progress=lambda f, s: world.time)


def test_blobtree_arguments_are_checked(world):
    tree = world.add_tree("quaking_aspen")
    with pytest.raises(boreas.InvalidArgumentError, match="resolution"):
        tree.add_blobtree(resolution=4)
    with pytest.raises(boreas.InvalidArgumentError):
        tree.add_blobtree(resolution=32, cuts=[(100000, 0.5)])
    with pytest.raises(ValueError, match="'pcm', 'blend'"):
        tree.add_blobtree(junctions="weld")
    with pytest.raises(TypeError, match="boreas.Tree"):
        world.add_blobtree("tree")
