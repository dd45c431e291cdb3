"""three.js (npm `three`) in headless Chromium plays a boreas animation as boreas simulated
it: the tree mask of its frame k, seen side-on, against boreas's own mesh of step k (a
twin world of the same inputs, stepped k frames, its branch mesh and leaf quads
rasterized here), intersection over union at least 0.85.

Run with the boreas package on PYTHONPATH: python3 threejs_silhouette.py OUT_DIR
Exits 77 (skipped) where Chromium or tests/web/node_modules is missing."""
import functools
import http.server
import os
import shutil
import subprocess
import sys
import threading

import numpy as np

import boreas

HERE = os.path.dirname(os.path.abspath(__file__))
FRAMES, FRAME_TIME, KEY = 25, 1.0 / 12.0, 24  # the frame compared: the last, 2 s in
SIZE, POOL = 512, 2  # pixels of the screenshot; masks compared on 2 x 2 blocks
BOX = (-13.0, -1.0, 15.0, 27.0)  # x0, y0, x1, y1 (m): the view along -z


def grove():
    """Two aspens of one template (one turned and larger) and an oak in a steady 20 m/s wind."""
    w = boreas.World(grid={"origin": (-24.0, 0.0, -24.0), "cell_size": 2.0, "resolution": (24, 14, 24)},
                     waves=[{"direction": (1.0, 0.2), "amplitude": 20.0, "wavelength": 30.0,
                             "speed": 6.0, "sharpness": 0.0}])
    trees = [w.add_tree("quaking_aspen", position=(0.0, 0.0, 0.0)),
             w.add_tree("quaking_aspen", position=(6.0, 0.0, -5.0), rotation=1.2, scale=1.2),
             w.add_tree("ca_black_oak", position=(-7.0, 0.0, 4.0), seed=6)]
    return w, trees


def rasterize(triangles):
    """Pixels any triangle touches (sampled at sub-pixel spacing), (SIZE, SIZE) bool."""
    x0, y0, x1, y1 = BOX
    px = (triangles[..., 0] - x0) / (x1 - x0) * SIZE
    py = (y1 - triangles[..., 1]) / (y1 - y0) * SIZE
    p = np.stack([px, py], axis=-1)  # (N, 3, 2)
    edge = np.max(np.linalg.norm(p - np.roll(p, 1, axis=1), axis=-1), axis=1)
    n = np.clip(np.ceil(edge * 2).astype(int), 1, 64)
    mask = np.zeros((SIZE, SIZE), bool)
    for k in np.unique(n):
        t = p[n == k]
        i, j = np.meshgrid(np.arange(k + 1), np.arange(k + 1), indexing="ij")
        keep = i + j <= k
        a, b = i[keep] / k, j[keep] / k
        pts = (t[:, None, 0] * (1 - a - b)[None, :, None] + t[:, None, 1] * a[None, :, None]
               + t[:, None, 2] * b[None, :, None]).reshape(-1, 2)
        ix, iy = np.floor(pts[:, 0]).astype(int), np.floor(pts[:, 1]).astype(int)
        ok = (ix >= 0) & (ix < SIZE) & (iy >= 0) & (iy < SIZE)
        mask[iy[ok], ix[ok]] = True
    return mask


def boreas_mask(frames):
    w, trees = grove()
    with w:
        for _ in range(frames):
            w.step(FRAME_TIME)
        tris = []
        for t in trees:
            v, f = t.mesh()
            tris.append(v["position"][f].astype(np.float64))
            leaves = t.leaves
            axis = leaves["axis"].astype(np.float64)
            across = np.cross(axis, leaves["normal"].astype(np.float64))
            across /= np.linalg.norm(across, axis=1, keepdims=True)
            half = 0.5 * leaves["width"][:, None] * across
            base = leaves["position"].astype(np.float64)
            tip = base + leaves["length"][:, None] * axis
            c = [base - half, base + half, tip + half, tip - half]  # as export-animation's quads
            tris.append(np.stack([c[0], c[1], c[2]], axis=1))
            tris.append(np.stack([c[0], c[2], c[3]], axis=1))
        return rasterize(np.concatenate(tris))


def threejs_mask(out_dir):
    glb = os.path.join(out_dir, "silhouette.glb")
    w, trees = grove()
    with w:
        w.export_animation(trees, glb, frames=FRAMES, frame_time=FRAME_TIME, max_level=2)
    for name in ("silhouette.html", "silhouette.js"):
        shutil.copy(os.path.join(HERE, name), out_dir)
    link = os.path.join(out_dir, "node_modules")
    if not os.path.exists(link):
        os.symlink(os.path.join(HERE, "node_modules"), link)
    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    handler = functools.partial(Quiet, directory=out_dir)
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    shot = os.path.join(out_dir, "silhouette_threejs.png")
    url = (f"http://127.0.0.1:{server.server_address[1]}/silhouette.html?file=silhouette.glb"
           f"&t={KEY * FRAME_TIME}&w={SIZE}&h={SIZE}&box={','.join(map(str, BOX))}")
    try:
        subprocess.run(["chromium", "--headless=new", "--no-sandbox", "--use-angle=swiftshader",
                        "--enable-unsafe-swiftshader", "--hide-scrollbars",
                        f"--window-size={SIZE},{SIZE + 200}", "--virtual-time-budget=60000",
                        f"--screenshot={shot}", url], check=True, timeout=300,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    finally:
        server.shutdown()
    import matplotlib.image
    image = matplotlib.image.imread(shot)
    return image[:SIZE, :SIZE, :3].max(axis=2) > 0.5


def pooled(mask):
    return mask.reshape(SIZE // POOL, POOL, SIZE // POOL, POOL).any(axis=(1, 3))


def main():
    if shutil.which("chromium") is None:
        print("skipped: chromium is not installed (scripts/install-deps.sh installs it)")
        return 77
    if not os.path.isdir(os.path.join(HERE, "node_modules", "three")):
        print("skipped: three.js is not installed (tests/web: npm ci)")
        return 77
    out_dir = sys.argv[1]
    os.makedirs(out_dir, exist_ok=True)
    ours, theirs = pooled(boreas_mask(KEY)), pooled(threejs_mask(out_dir))
    rest = pooled(boreas_mask(0))

    def iou(a, b):
        return (a & b).sum() / max((a | b).sum(), 1)

    print(f"tree mask at frame {KEY}: boreas {ours.sum()} blocks, three.js {theirs.sum()}, "
          f"IoU {iou(ours, theirs):.3f} (boreas's rest pose against its frame {KEY}: "
          f"{iou(ours, rest):.3f})")
    import matplotlib.image
    matplotlib.image.imsave(os.path.join(out_dir, "silhouette_compare.png"),
                            np.stack([theirs, ours, np.zeros_like(ours)], axis=-1).astype(np.float32))
    # At least 0.85, and closer than the pose the wind moved the trees from.
    return 0 if ours.sum() > 100 and iou(ours, theirs) >= max(0.85, iou(ours, rest)) else 1


if __name__ == "__main__":
    sys.exit(main())
