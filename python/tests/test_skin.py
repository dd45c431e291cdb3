"""A tree's skin (Tree.skin): the joints follow the branch tips as the tree bends, and the
weights bind every vertex and leaf to joints of its own branch or an ancestor."""
import numpy as np
import pytest

import boreas


def test_skin_arrays_and_tips(world):
    tree = world.add_tree("quaking_aspen")
    joints, vertex_weights, leaf_weights = tree.skin(max_level=2, segments=3)
    assert joints.dtype == boreas.JOINT_DTYPE and vertex_weights.dtype == boreas.SKIN_WEIGHT_DTYPE
    vertices, _ = tree.mesh()
    assert len(vertex_weights) == len(vertices) and len(leaf_weights) == len(tree.leaves)
    np.testing.assert_allclose(vertex_weights["weights"].sum(axis=1), 1.0, atol=1e-6)
    branches = tree.branches
    assert (branches["level"][joints["branch"]] <= 2).all()
    assert (joints["parent"] < np.arange(len(joints))).all()
    for _ in range(10):
        world.step(1 / 30)
    joints = world._core.tree_joints(tree._id, 2, 3)
    branches = tree.branches
    tips = joints[joints["u"] == 1.0]
    np.testing.assert_allclose(tips["position"], branches["control_points"][tips["branch"], 3],
                               atol=1e-3)


def test_bad_skin_def_names_the_field(world):
    tree = world.add_tree("quaking_aspen")
    with pytest.raises(boreas.InvalidArgumentError, match="segments"):
        tree.skin(segments=boreas.SKIN_MAX_SEGMENTS + 1)


def test_export_animation_shares_a_template_mesh(world, tmp_path):
    import json
    import struct

    trees = [world.add_tree("quaking_aspen"), world.add_tree("quaking_aspen", position=(2.0, 0.0, 1.0))]
    path = tmp_path / "two.glb"
    world.export_animation(trees, path, frames=3, frame_time=0.05, max_level=0, segments=2, leaves=False)
    data = path.read_bytes()
    assert data[:4] == b"glTF"
    doc = json.loads(data[20:20 + struct.unpack("<I", data[12:16])[0]])
    assert len(doc["meshes"]) == 1 and len(doc["skins"]) == 2
    assert [len(s["joints"]) for s in doc["skins"]] == [len(trees[0].skin(0, 2)[0])] * 2
    times = doc["accessors"][doc["animations"][0]["samplers"][0]["input"]]
    assert times["count"] == 3 and times["max"] == [pytest.approx(0.1)]
    assert world.time == pytest.approx(0.1)


def test_export_animation_warms_up_before_the_first_key(world, tmp_path):
    import json
    import struct

    tree = world.add_tree("quaking_aspen")
    rest = tree.joints(0, 2)["position"].copy()
    path = tmp_path / "warm.glb"
    world.export_animation([tree], path, frames=3, frame_time=0.05, max_level=0, segments=2,
                           leaves=False, warmup=0.5)
    assert world.time == pytest.approx(0.5 + 0.1)  # 10 warm-up steps, then 2 keys' steps
    doc = json.loads(path.read_bytes()[20:20 + struct.unpack("<I", path.read_bytes()[12:16])[0]])
    times = doc["accessors"][doc["animations"][0]["samplers"][0]["input"]]
    assert times["count"] == 3 and times["max"] == [pytest.approx(0.1)]
    assert abs(tree.joints(0, 2)["position"] - rest).max() > 1e-4  # the wind moved it
    for bad in (-1.0, float("nan"), boreas.ANIMATION_MAX_WARMUP_SECONDS * 2):
        with pytest.raises(boreas.InvalidArgumentError, match="warmup"):
            world.export_animation([tree], tmp_path / "none.glb", frames=2, warmup=bad)
    assert not (tmp_path / "none.glb").exists()


def test_export_animation_refuses_zero_frames(world, tmp_path):
    tree = world.add_tree("quaking_aspen")
    with pytest.raises(boreas.InvalidArgumentError, match="frames"):
        world.export_animation([tree], tmp_path / "none.glb", frames=0)
    assert world.time == 0.0 and not (tmp_path / "none.glb").exists()


def test_export_animation_writes_a_meadow_as_morph_targets(world, tmp_path):
    import json
    import struct

    meadow = world.add_meadow(center=(0.0, 0.0, 0.0), size=(1.0, 1.0), density=40.0)
    path = tmp_path / "meadow.glb"
    world.export_animation([], path, frames=4, frame_time=0.05, meadows=[meadow])
    data = path.read_bytes()
    doc = json.loads(data[20:20 + struct.unpack("<I", data[12:16])[0]])
    node = next(n for n in doc["nodes"] if n["name"] == "meadow0_piece0")
    targets = doc["meshes"][node["mesh"]]["primitives"][0].get("targets", [])
    assert len(targets) <= 4
    strips, counts = meadow.vertices()
    assert doc["accessors"][doc["meshes"][node["mesh"]]["primitives"][0]["attributes"]["POSITION"]]["count"] \
        == counts.sum()
    with pytest.raises(boreas.InvalidArgumentError, match="morph_tolerance"):
        world.export_animation([], tmp_path / "none.glb", meadows=[meadow], morph_tolerance=0.0)
    with pytest.raises(boreas.InvalidArgumentError, match="MAX_MORPH_FRAMES"):
        world.export_animation([], tmp_path / "none.glb", meadows=[meadow],
                               frames=boreas.ANIMATION_MAX_MORPH_FRAMES + 1)
    assert not (tmp_path / "none.glb").exists()


def test_export_animation_writes_a_meadow_as_clumps(world, tmp_path):
    import json
    import struct

    meadow = world.add_meadow(center=(0.0, 0.0, 0.0), size=(2.0, 2.0), density=40.0)
    path = tmp_path / "clumps.glb"
    world.export_animation([], path, frames=4, frame_time=0.05, meadows=[meadow], meadow_clumps=2,
                           clump_size=1.0)
    data = path.read_bytes()
    doc = json.loads(data[20:20 + struct.unpack("<I", data[12:16])[0]])
    placed = [n for n in doc["nodes"] if n["name"].startswith("meadow0_clump")]
    assert 1 <= len(placed) <= 4  # a 2 x 2 m meadow in cells of 1 m: an instance per planted cell
    assert len({n["mesh"] for n in placed}) <= 2  # two clumps at most, shared by the instances
    for field, value in (("meadow_clumps", boreas.ANIMATION_MAX_CLUMPS + 1), ("clump_size", 0.0)):
        with pytest.raises(boreas.InvalidArgumentError, match=field):
            world.export_animation([], tmp_path / "none.glb", meadows=[meadow], **{field: value})
    assert not (tmp_path / "none.glb").exists()
