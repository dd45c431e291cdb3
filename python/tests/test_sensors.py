"""Rays and sensors from Python: the point layout a ROS PointCloud2 reads, presets, LiDARs
and depth images over the C API, refusals that change nothing (bad lidars and cameras, rays
of the wrong shape or with a zero direction, a non-finite origin, a negative max distance),
and hits, LiDAR points and depth of a flat ground against their analytic values."""
import math

import numpy as np
import pytest

import boreas


def flat_ground(world, height=0.0):
    """A meadow with no plants: its ground is the plane y = height, 20 m x 20 m."""
    return world.add_meadow(center=(0.0, height, 0.0), size=(20.0, 20.0), density=0.0)


DOWN = {"orientation": (-math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5))}  # -Z turned to -Y


def test_points_start_with_the_fields_of_a_ros_pointcloud2():
    dt = boreas.LIDAR_POINT_DTYPE
    expected = [("x", 0, "<f4"), ("y", 4, "<f4"), ("z", 8, "<f4"), ("intensity", 12, "<f4"),
                ("ring", 16, "<u2"), ("time", 20, "<f4")]
    assert list(dt.names[:6]) == [name for name, _, _ in expected]
    for name, offset, fmt in expected:
        assert dt.fields[name][1] == offset
        assert dt.fields[name][0] == np.dtype(fmt)
    assert list(dt.names[6:]) == ["kind", "object", "part"]
    assert dt.itemsize == 44


def test_presets_have_their_published_angles():
    assert boreas.lidar_presets() == ["VLP-16", "HDL-32E", "HDL-64E", "OS1-128"]
    vlp = boreas.lidar_preset("VLP-16")
    np.testing.assert_allclose(np.degrees(vlp["vertical_angles"]), np.arange(-15, 16, 2),
                               atol=1e-5)
    hdl = boreas.lidar_preset("HDL-32E")
    np.testing.assert_allclose(np.degrees(hdl["vertical_angles"]),
                               -92 / 3 + 4 / 3 * np.arange(32), atol=0.005)
    with pytest.raises(boreas.InvalidArgumentError, match="VLP-16"):
        boreas.lidar_preset("VLP-17")


def test_a_lidar_before_its_first_step(calm_world):
    lidar = calm_world.add_lidar("OS1-128", pose={"position": (0.0, 2.0, 0.0)})
    for which in ("sweep", "step"):
        points = lidar.points(which)
        assert points.dtype == boreas.LIDAR_POINT_DTYPE and points.shape == (0,)
    info = lidar.info()
    assert info["sweeps"] == 0 and info["firings"] == 0
    with pytest.raises(ValueError, match="'sweep' or 'step'"):
        lidar.points("all")
    lidar.remove()
    with pytest.raises(boreas.NotFoundError):
        lidar.info()


def test_bad_lidars_and_cameras_are_refused_and_change_nothing(calm_world):
    before = calm_world.state_hash()
    with pytest.raises(boreas.InvalidArgumentError, match="dropout"):
        calm_world.add_lidar(dropout=2.0)
    with pytest.raises(boreas.InvalidArgumentError, match="vertical_angles\\[1\\]"):
        calm_world.add_lidar(vertical_angles=[0.0, 3.0])
    with pytest.raises(boreas.InvalidArgumentError, match="pose.orientation"):
        calm_world.add_lidar(pose={"orientation": (0.0, 0.0, 0.0, 0.5)})
    with pytest.raises(ValueError, match="channels"):
        calm_world.add_lidar(channels=3, vertical_angles=[0.0, 0.1])
    with pytest.raises(TypeError, match="has no field 'colour'"):
        calm_world.capture_depth(8, 8, pose={"position": (0, 1, 0), "colour": 1})
    with pytest.raises(boreas.InvalidArgumentError, match="fx"):
        calm_world.capture_depth(8, 8, fx=-1.0)
    lidar = calm_world.add_lidar()
    with pytest.raises(boreas.InvalidArgumentError, match="pose.position"):
        lidar.pose = {"position": (0.0, math.inf, 0.0)}
    assert lidar.pose is None
    lidar.remove()
    assert calm_world.state_hash() == before


def test_a_preset_spreads_other_channel_counts_over_its_span(calm_world):
    lidar = calm_world.add_lidar("HDL-32E", channels=8)
    assert lidar.info()["firings"] == 0  # added: 8 channels over -30.67 .. +10.67 degrees


def test_cast_rays_checks_its_arrays(calm_world):
    with pytest.raises(ValueError, match="rows"):
        calm_world.cast_rays(np.zeros((3, 3)), np.ones((2, 3)))
    with pytest.raises(ValueError, match="max_distance"):
        calm_world.cast_rays(np.zeros((2, 3)), np.ones((2, 3)), [1.0, 2.0, 3.0])
    hits = calm_world.cast_rays(np.zeros((0, 3)), np.zeros((0, 3)))
    assert hits.dtype == boreas.HIT_DTYPE and hits.shape == (0,)


def test_bad_rays_are_refused_naming_the_ray_and_field(calm_world):
    flat_ground(calm_world)
    calm_world.step(1 / 60)
    origins = np.zeros((3, 3), np.float32)
    origins[:, 1] = 2.0
    down = np.tile(np.array([0.0, -1.0, 0.0], np.float32), (3, 1))
    zero = down.copy()
    zero[2] = 0.0
    with pytest.raises(boreas.InvalidArgumentError, match=r"rays\[2\]\.direction must not be zero"):
        calm_world.cast_rays(origins, zero)
    nan_origin = origins.copy()
    nan_origin[1, 0] = np.nan
    with pytest.raises(boreas.InvalidArgumentError, match=r"rays\[1\]\.origin\[0\] must be finite"):
        calm_world.cast_rays(nan_origin, down)
    inf_direction = down.copy()
    inf_direction[0, 2] = np.inf
    with pytest.raises(ValueError, match=r"rays\[0\]\.direction\[2\] must be finite"):
        calm_world.cast_rays(origins, inf_direction)
    with pytest.raises(ValueError, match=r"rays\[1\]\.max_distance must be >= 0 m \(got -1"):
        calm_world.cast_rays(origins, down, [5.0, -1.0, 5.0])
    with pytest.raises(ValueError, match=r"rays\[0\]\.max_distance must be >= 0 m"):
        calm_world.cast_rays(origins, down, -0.5)
    # Wrong shapes, each named.
    with pytest.raises(ValueError, match=r"directions must have shape \(N, 3\), not \(3, 2\)"):
        calm_world.cast_rays(origins, down[:, :2])
    with pytest.raises(ValueError, match=r"origins must have shape \(N, 3\), not \(2, 3, 1\)"):
        calm_world.cast_rays(np.zeros((2, 3, 1)), down[:2])
    with pytest.raises(ValueError, match=r"max_distance must be a number or have shape \(3,\)"):
        calm_world.cast_rays(origins, down, np.ones((3, 1)))
    # The refusals changed nothing: the same rays, made good, still hit the ground 2 m down.
    hits = calm_world.cast_rays(origins, down)
    np.testing.assert_allclose(hits["distance"], 2.0, atol=1e-4)


def test_rays_hit_flat_ground_at_its_height(calm_world):
    flat_ground(calm_world, 0.5)
    calm_world.step(1 / 60)
    directions = np.array([[0.0, -1.0, 0.0], [1.0, -1.0, 0.0], [0.0, 1.0, 0.0]], np.float32)
    hits = calm_world.cast_rays([0.0, 2.5, 0.0], directions)
    np.testing.assert_allclose(hits["distance"][:2], [2.0, 2.0 * math.sqrt(2)], atol=1e-4)
    assert list(hits["kind"]) == [7, 7, 0]
    assert math.isinf(hits["distance"][2])


def test_lidar_points_lie_on_flat_ground(calm_world):
    flat_ground(calm_world)
    calm_world.step(1 / 60)
    lidar = calm_world.add_lidar("VLP-16", pose={"position": (0.0, 1.5, 0.0)}, max_range=9.0,
                                 range_noise=0.0)
    for _ in range(8):
        calm_world.step(1 / 60)
    sweep = lidar.points("sweep")
    assert len(sweep) > 0
    np.testing.assert_allclose(sweep["y"], 0.0, atol=1e-3)
    assert set(sweep["kind"]) == {7}
    assert sweep["time"].max() < 0.1


def test_depth_of_flat_ground_from_above_is_the_height(calm_world):
    flat_ground(calm_world, 0.25)
    calm_world.step(1 / 60)
    depth, labels = calm_world.capture_depth(16, 12, fx=10.0, fy=10.0, cx=7.5, cy=5.5,
                                             pose={"position": (0.0, 2.25, 0.0), **DOWN})
    assert depth.shape == (12, 16) and labels.shape == (12, 16)
    np.testing.assert_allclose(depth, 2.0, atol=1e-3)
    assert (labels["kind"] == 7).all()
