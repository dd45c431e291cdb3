"""three.js (npm `three`) in headless Chromium plays a meadow and two imported trees of one
model as boreas simulated them: at key k, every vertex of every morphed mesh, placed by
three.js (Mesh.getVertexPosition and the node's matrix), lies within the export's
tolerance of the vertex a twin world of the same inputs has after k frames. The page also
draws the frame (WebGL must take the int16 morph targets without an error).

Run with the boreas package on PYTHONPATH: python3 threejs_morphs.py OUT_DIR
Exits 77 (skipped) where Chromium or tests/web/node_modules is missing."""
import functools
import html
import http.server
import json
import os
import re
import shutil
import subprocess
import sys
import threading

import numpy as np

import boreas

HERE = os.path.dirname(os.path.abspath(__file__))
MODEL = os.path.join(HERE, "..", "fuzz", "corpus", "obj", "branched_tree.obj")
FRAMES, FRAME_TIME, STEPS, KEY = 12, 1.0 / 24.0, 2, 7
TOLERANCE = 1e-3  # m, the export's default


def scene():
    """A 3 x 2 m meadow and two imported trees of one model (one turned and larger) in wind."""
    w = boreas.World(grid={"origin": (-16.0, 0.0, -16.0), "cell_size": 2.0, "resolution": (16, 8, 16)},
                     waves=[{"direction": (1.0, 0.2), "amplitude": 9.0, "wavelength": 20.0,
                             "speed": 6.0, "sharpness": 0.0}])
    meadow = w.add_meadow(center=(2.0, 0.0, 0.0), size=(3.0, 2.0), density=60.0)
    trees = [w.add_mesh_tree(MODEL, (-3.0, 0.0, 0.0), cache=False),
             w.add_mesh_tree(MODEL, (-3.0, 0.0, 4.0), yaw=0.9, scale=1.4, cache=False)]
    return w, meadow, trees


def boreas_vertices():
    """{mesh name: (n, 3)} as the twin world has them after KEY frames."""
    w, meadow, trees = scene()
    with w:
        for _ in range(KEY * STEPS):
            w.step(FRAME_TIME / STEPS)
        strips, counts = meadow.vertices()
        out = {"meadow0_piece0": np.concatenate(
            [strips[c, :counts[c]]["position"] for c in range(len(counts))]).astype(np.float64)}
        for i, t in enumerate(trees):
            for part in ("trunk", "leaves"):
                out[f"mesh_tree{i}_{part}"] = t.vertices(part)["position"].astype(np.float64)
        return out


def threejs_vertices(out_dir):
    glb = os.path.join(out_dir, "morphs.glb")
    w, meadow, trees = scene()
    with w:
        w.export_animation([], glb, frames=FRAMES, frame_time=FRAME_TIME, steps_per_frame=STEPS,
                           meadows=[meadow], mesh_trees=trees, morph_tolerance=TOLERANCE)
    for name in ("morph_play.html", "morph_play.js"):
        shutil.copy(os.path.join(HERE, name), out_dir)
    link = os.path.join(out_dir, "node_modules")
    if not os.path.exists(link):
        os.symlink(os.path.join(HERE, "node_modules"), link)

    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Quiet, directory=out_dir))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    url = (f"http://127.0.0.1:{server.server_address[1]}/morph_play.html?file=morphs.glb"
           f"&t={KEY * FRAME_TIME}")
    try:
        dom = subprocess.run(["chromium", "--headless=new", "--no-sandbox", "--use-angle=swiftshader",
                              "--enable-unsafe-swiftshader", "--virtual-time-budget=60000",
                              "--dump-dom", url], check=True, timeout=300, capture_output=True,
                             text=True).stdout
    finally:
        server.shutdown()
    found = re.search(r'<pre id="out">(.*?)</pre>', dom, re.S)
    if not found or not found.group(1).strip():
        sys.exit(f"three.js wrote nothing: {re.search(r'<title>(.*?)</title>', dom) or dom[:300]}")
    played = json.loads(html.unescape(found.group(1)))
    return played


def main():
    if shutil.which("chromium") is None:
        print("skipped: chromium is not installed (scripts/install-deps.sh installs it)")
        return 77
    if not os.path.isdir(os.path.join(HERE, "node_modules", "three")):
        print("skipped: tests/web/node_modules is missing (npm ci in tests/web)")
        return 77
    out_dir = sys.argv[1]
    os.makedirs(out_dir, exist_ok=True)
    played = threejs_vertices(out_dir)
    want = boreas_vertices()
    assert played["glError"] == 0, f"WebGL error {played['glError']} drawing the morphs"
    meshes = played["meshes"]
    assert set(want) <= set(meshes), f"three.js has {sorted(meshes)}, boreas {sorted(want)}"
    worst = 0.0
    for name, positions in want.items():
        got = np.array(meshes[name]["xyz"], np.float64).reshape(-1, 3)
        assert got.shape == positions.shape, f"{name}: {got.shape} vertices, boreas {positions.shape}"
        off = np.linalg.norm(got - positions, axis=1).max()
        print(f"{name}: {len(got)} vertices, {meshes[name]['targets']} targets, "
              f"within {off * 1000:.3f} mm of boreas at key {KEY}")
        worst = max(worst, off)
    assert worst <= TOLERANCE + 2e-5, f"three.js plays a vertex {worst * 1000:.3f} mm from boreas"
    print(f"three.js plays the meadow and imported trees within {worst * 1000:.3f} mm of boreas")
    return 0


if __name__ == "__main__":
    sys.exit(main())
