"""boreas.dataset: (scene, seed) items over a Dask LocalCluster of two worker processes on
loopback, against the same items run one by one in this process: the same state hashes;
a worker killed in the middle of an item; bad scene items recorded, not fatal; reruns
that skip what finished; items with a LiDAR and a depth camera, whose point clouds and
depth images two workers write byte for byte as one process does. Scenes are tiny (a 64 x 16 x 64 m grid, one aspen, 16-pixel
slice frames), so each run costs about a second of process start-up."""
import json
import os
import signal
import subprocess
import sys
import threading
import time

import pytest

distributed = pytest.importorskip("distributed")

from boreas.dataset import Item, dataset, items_from, main, parse_seeds, read_items_file  # noqa: E402

RUN_ARGS = ["--animation", "none"]


def scene_text(frames, size=16):
    return json.dumps({
        "world": {"grid": {"origin": [-32, 0, -32], "cell_size": 2, "resolution": [32, 8, 32]}},
        "wind": {"waves": [{"direction": [1, 0], "amplitude": 9, "wavelength": 30, "speed": 12,
                            "sharpness": 2}]},
        "trees": [{"species": "quaking_aspen", "position": [0, 0, 0], "seed": 4}],
        "run": {"frames": frames, "steps_per_frame": 2, "dt": 0.05, "image_size": [size, size],
                "view": "slice"}})


@pytest.fixture(scope="module")
def scenes(tmp_path_factory):
    d = tmp_path_factory.mktemp("scenes")
    (d / "tiny.json").write_text(scene_text(2))
    # Long enough (~4 s) to be caught running: many frames of a bigger slice.
    (d / "slow.json").write_text(scene_text(120, 64))
    (d / "malformed.json").write_text('{"run": {"frames": 2,}}')
    return d


@pytest.fixture(scope="module")
def client():
    """Two worker processes of one thread each on loopback."""
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None, host="127.0.0.1") as cluster, \
            distributed.Client(cluster) as c:
        yield c


def manifest(path):
    with open(os.path.join(path, "manifest.jsonl")) as f:
        return [json.loads(line) for line in f]


def hashes(entries):
    return {e["item"]: e["state_hash"] for e in entries}


def test_two_workers_write_the_state_hashes_one_process_does(scenes, client, tmp_path):
    items = items_from([str(scenes / "tiny.json")], range(3))
    one = dataset(str(tmp_path / "one"), items, workers=0, run_args=RUN_ARGS, progress=False)
    two = dataset(str(tmp_path / "two"), items, client=client, devices=["cpu", "cpu"],
                  run_args=RUN_ARGS, progress=False)
    assert sorted(one.finished) == sorted(two.finished) == ["tiny_s0", "tiny_s1", "tiny_s2"]
    assert hashes(one.entries) == hashes(two.entries)
    assert len(set(hashes(one.entries).values())) == 3  # the seed makes another world
    for e in manifest(tmp_path / "two"):
        assert e["timings"]["device"] == "cpu"
        assert e["timings"]["worker"].startswith("tcp://127.0.0.1:")
        assert e["timings"]["seconds"] == pytest.approx(e["timings"]["end"] - e["timings"]["start"],
                                                        abs=1e-3)
        with open(tmp_path / "two" / e["item"] / "summary.json") as f:
            summary = json.load(f)
        assert summary["state_hash"] == e["state_hash"] and summary["seed"] == e["seed"]
        paths = [f["path"] for f in e["files"]]
        assert paths == sorted(f"{e['item']}/{n}" for n in os.listdir(tmp_path / "two" / e["item"]))
        assert f"{e['item']}/frame_0001.png" in paths
        for f in e["files"]:
            assert os.path.getsize(tmp_path / "two" / f["path"]) == f["size"]
    assert not os.path.exists(tmp_path / "two" / ".partial")


def sensor_scene_text(frames=2):
    """The tiny scene over a meadow with a LiDAR and a depth camera beside the aspen."""
    scene = json.loads(scene_text(frames))
    scene["meadows"] = [{"center": [0, 0, 0], "size": [20, 20], "density": 4, "seed": 2}]
    scene["sensors"] = [
        {"type": "lidar", "name": "roof", "preset": "VLP-16", "points_per_turn": 360,
         "pose": {"position": [-5, 2, 0]}},
        {"type": "depth", "name": "cam", "width": 24, "height": 16, "fov_deg": 60,
         "pose": {"position": [-6, 2, 0], "heading_deg": -90, "pitch_deg": -10}}]
    return json.dumps(scene)


def sensor_files(root, item):
    """{path under the item: sha256} of the item's sensor files."""
    import hashlib
    out = {}
    base = os.path.join(root, item, "sensors")
    for folder, _, names in os.walk(base):
        for name in names:
            path = os.path.join(folder, name)
            with open(path, "rb") as f:
                out[os.path.relpath(path, base)] = hashlib.sha256(f.read()).hexdigest()
    return out


def test_sensor_items_write_the_same_point_clouds_and_depth_on_two_workers(tmp_path, client):
    np = pytest.importorskip("numpy")
    (tmp_path / "sensed.json").write_text(sensor_scene_text())
    items = items_from([str(tmp_path / "sensed.json")], range(2))
    one = dataset(str(tmp_path / "one"), items, workers=0, run_args=RUN_ARGS, progress=False)
    two = dataset(str(tmp_path / "two"), items, client=client, devices=["cpu", "cpu"],
                  run_args=RUN_ARGS, progress=False)
    assert sorted(one.finished) == sorted(two.finished) == ["sensed_s0", "sensed_s1"]
    for item in ("sensed_s0", "sensed_s1"):
        files = sensor_files(tmp_path / "one", item)
        assert sorted(files) == sorted(
            [f"roof/frame_000{f}.{ext}" for f in range(2) for ext in ("ply", "pcd")] +
            [f"cam/frame_000{f}_{kind}.npy" for f in range(2) for kind in ("depth", "labels")])
        # The two-worker run wrote the same bytes (the same world, seed and sweep).
        assert sensor_files(tmp_path / "two", item) == files
        # The manifest lists them with their sizes.
        entry = {e["item"]: e for e in manifest(tmp_path / "two")}[item]
        listed = {f["path"] for f in entry["files"]}
        assert {f"{item}/sensors/{p}" for p in files} <= listed
        # The last frame's sweep (0.2 s: a whole turn at 10 Hz) and its labels.
        ply = (tmp_path / "one" / item / "sensors/roof/frame_0001.ply").read_bytes()
        header, body = ply.split(b"end_header\n", 1)
        count = int(header.split(b"element vertex ")[1].split(b"\n")[0])
        assert count > 100 and len(body) == 31 * count
        kinds = np.frombuffer(body, dtype=np.uint8).reshape(count, 31)[:, 22]
        assert set(kinds) <= {1, 2, 5, 7} and 7 in set(kinds)  # bark, leaf, grass, ground
        depth = np.load(tmp_path / "one" / item / "sensors/cam/frame_0001_depth.npy")
        labels = np.load(tmp_path / "one" / item / "sensors/cam/frame_0001_labels.npy")
        assert depth.shape == (16, 24) and labels.shape == (16, 24, 3)
        seen = labels[..., 0] != 0
        assert seen.any() and np.isfinite(depth[seen]).all() and np.isinf(depth[~seen]).all()
    # Two seeds, two meadows: the point clouds differ.
    assert sensor_files(tmp_path / "one", "sensed_s0") != sensor_files(tmp_path / "one",
                                                                         "sensed_s1")


def test_bad_scene_items_are_recorded_and_the_rest_go_on(scenes, client, tmp_path):
    items = [Item("missing", str(scenes / "missing.json"), 1),
             Item("malformed", str(scenes / "malformed.json"), 1),
             Item("good", str(scenes / "tiny.json"), 1)]
    report = dataset(str(tmp_path / "ds"), items, client=client, run_args=RUN_ARGS,
                     progress=False)
    assert report.finished == ["good"]
    assert sorted(report.failed) == ["malformed", "missing"]
    entries = {e["item"]: e for e in manifest(tmp_path / "ds")}
    assert entries["missing"]["error"] == {
        "exit_code": 1,
        "message": f"boreas: error: {scenes / 'missing.json'}: cannot open: No such file or "
                   f"directory"}
    bad = entries["malformed"]["error"]
    assert bad["exit_code"] == 1
    assert bad["message"].startswith(f"boreas: error: {scenes / 'malformed.json'}: line 1, column")
    for name in ("missing", "malformed"):
        assert entries[name]["status"] == "failed" and entries[name]["files"] == []
        assert not os.path.exists(tmp_path / "ds" / name)
    assert entries["good"]["status"] == "finished" and entries["good"]["error"] is None


def test_a_rerun_skips_finished_items_and_redoes_the_rest(scenes, tmp_path):
    out = str(tmp_path / "ds")
    items = items_from([str(scenes / "tiny.json")], range(2)) + [
        Item("missing", str(scenes / "missing.json"))]
    first = dataset(out, items, workers=0, run_args=RUN_ARGS, progress=False)
    assert sorted(first.finished) == ["tiny_s0", "tiny_s1"] and first.failed == ["missing"]

    again = dataset(out, items, workers=0, run_args=RUN_ARGS, progress=False)
    assert sorted(again.skipped) == ["tiny_s0", "tiny_s1"]
    assert [e["item"] for e in again.entries] == ["missing"]  # a failed item is retried

    os.remove(os.path.join(out, "tiny_s1", "frame_0000.png"))  # an item no longer whole
    third = dataset(out, items, workers=0, run_args=RUN_ARGS, progress=False)
    assert third.skipped == ["tiny_s0"]
    redone = {e["item"]: e for e in third.entries}["tiny_s1"]
    assert redone["status"] == "finished"
    assert redone["state_hash"] == {e["item"]: e for e in first.entries}["tiny_s1"]["state_hash"]
    assert os.path.isfile(os.path.join(out, "tiny_s1", "frame_0000.png"))

    # Other run arguments make other items: nothing is skipped.
    fourth = dataset(out, items[:1], workers=0, run_args=RUN_ARGS + ["--frames", "1"],
                     progress=False)
    assert fourth.skipped == [] and fourth.finished == ["tiny_s0"]
    assert len(manifest(out)) == 3 + 1 + 2 + 1


def boreas_children(item_name, parents):
    """{pid: parent pid} of the boreas runs writing the item (found by --out in /proc)
    whose parent is one of parents (this test's workers, not another test's)."""
    found = {}
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            with open(f"/proc/{pid}/cmdline", "rb") as f:
                args = f.read().split(b"\0")
            with open(f"/proc/{pid}/stat") as f:
                parent = int(f.read().rsplit(")", 1)[1].split()[1])
        except OSError:
            continue
        if parent in parents and any(f"/.partial/{item_name}.".encode() in a for a in args):
            found[int(pid)] = parent
    return found


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="finds the run through /proc")
def test_a_worker_killed_mid_item_leaves_a_complete_dataset(scenes, client, tmp_path):
    out = str(tmp_path / "ds")
    items = [Item("slow", str(scenes / "slow.json"), 3)] + items_from(
        [str(scenes / "tiny.json")], range(2))
    result = {}
    runner = threading.Thread(target=lambda: result.update(report=dataset(
        out, items, client=client, run_args=RUN_ARGS, progress=False)))
    workers = set(client.run(os.getpid).values())
    runner.start()
    deadline = time.monotonic() + 60
    while not boreas_children("slow", workers) and time.monotonic() < deadline:
        time.sleep(0.02)
    children = boreas_children("slow", workers)
    assert children, "the slow item never started"
    (run_pid, worker_pid), = children.items()
    os.kill(worker_pid, signal.SIGKILL)  # the worker process, in the middle of the run
    assert not os.path.exists(os.path.join(out, "slow"))  # nothing looks finished
    # The run dies with its worker (at once: it had seconds of frames left to write).
    gone = time.monotonic() + 1.0
    while not _is_gone(run_pid) and time.monotonic() < gone:
        time.sleep(0.01)
    assert _is_gone(run_pid)
    runner.join(120)
    assert not runner.is_alive()

    report = result["report"]
    assert sorted(report.finished) == ["slow", "tiny_s0", "tiny_s1"] and not report.failed
    slow = {e["item"]: e for e in manifest(out)}["slow"]
    assert slow["timings"]["pid"] != worker_pid  # rerun by another worker process
    frames = [f for f in slow["files"] if f["path"].startswith("slow/frame_")]
    assert len(frames) == 120
    with open(os.path.join(out, "slow", "summary.json")) as f:
        summary = json.load(f)
    assert summary["state_hash"] == slow["state_hash"] and len(summary["frame_stats"]) == 120
    assert not os.path.exists(os.path.join(out, ".partial"))
    assert len(client.scheduler_info()["workers"]) >= 1


def _is_gone(pid):
    """Whether the process has ended (reaped, or a zombie waiting to be)."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] == "Z"
    except OSError:
        return True


def test_the_command_reports_items_and_exits_1_when_one_failed(scenes, tmp_path):
    items_file = tmp_path / "items.jsonl"
    items_file.write_text(f'{{"scene": "{scenes / "tiny.json"}", "seed": 7}}\n'
                          '# a comment\n\n{"scene": "nowhere.json", "name": "lost"}\n')
    env = dict(os.environ)
    done = subprocess.run([sys.executable, "-m", "boreas.dataset", str(tmp_path / "ds"),
                           "--items", str(items_file), "--workers", "0", "--", *RUN_ARGS],
                          capture_output=True, text=True, env=env, timeout=120)
    assert done.returncode == 1, done.stderr
    assert "lost failed: boreas: error: " in done.stderr
    assert "2/2 done (1 failed)" in done.stderr
    entries = {e["item"]: e for e in manifest(tmp_path / "ds")}
    assert entries["tiny_s7"]["status"] == "finished" and entries["tiny_s7"]["seed"] == 7
    assert entries["lost"]["scene"] == str(tmp_path / "nowhere.json")

    usage = subprocess.run([sys.executable, "-m", "boreas.dataset", str(tmp_path / "u"),
                            "--scene", "a.json", "--seeds", "5:2"],
                           capture_output=True, text=True, env=env, timeout=60)
    assert usage.returncode == 2 and "--seeds: the range '5:2' is empty" in usage.stderr
    assert not os.path.exists(tmp_path / "u")


def test_items_are_read_and_refused_by_name(tmp_path):
    assert parse_seeds("0:3,10") == [0, 1, 2, 10]
    for bad in ("3:3", "-1", "1,1", "a", "1:2:3", str(2**64)):
        with pytest.raises(ValueError):
            parse_seeds(bad)
    with pytest.raises(ValueError, match="item 'a_s1' twice"):
        items_from(["x/a.json", "y/a.json"], [1])
    f = tmp_path / "items.jsonl"
    f.write_text('{"scene": "s.json", "seed": 2}\n{"scene": "s.json", "sede": 3}\n')
    with pytest.raises(ValueError, match=r"items.jsonl:2: unknown key 'sede'"):
        read_items_file(str(f))
    f.write_text('{"scene": "s.json", "seed": -2}\n')
    with pytest.raises(ValueError, match=r"items.jsonl:1: seed must be"):
        read_items_file(str(f))
    with pytest.raises(ValueError, match="--out is set by the dataset"):
        dataset(str(tmp_path / "ds"), [], workers=0, run_args=["--out", "x"])
