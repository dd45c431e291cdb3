"""three.js (npm `three`) in headless Chromium loads and plays a meadow written as clumps
(`boreas export-animation`'s default): every instance node of a clump with morph targets is a
morphed mesh three.js draws without a WebGL error; each clump's loop closes (every instance at the last
key where it was at key 0, within 0.01 mm); and instances of one clump at different phases
do not move alike (their vertices' offsets from the first key differ mid-animation by over 0.01 mm,
far past float rounding).

Run: python3 threejs_clumps.py FILE.glb FRAMES FRAME_TIME OUT_DIR
Exits 77 (skipped) where Chromium or tests/web/node_modules is missing."""
import functools
import html
import http.server
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import threading

HERE = os.path.dirname(os.path.abspath(__file__))


def instance_names(glb):
    """The clump instances' node names, and those whose clump has morph targets (a clump
    that moved less than the tolerance has none, and three.js draws it as a plain mesh)."""
    with open(glb, "rb") as f:
        data = f.read()
    length = struct.unpack_from("<I", data, 12)[0]
    doc = json.loads(data[20:20 + length])
    nodes = [n for n in doc["nodes"] if re.fullmatch(r"meadow\d+_clump\d+_cell\d+", n.get("name", ""))]
    moving = [n["name"] for n in nodes if doc["meshes"][n["mesh"]]["primitives"][0].get("targets")]
    return [n["name"] for n in nodes], moving


def play(out_dir, t):
    class Quiet(http.server.SimpleHTTPRequestHandler):
        def log_message(self, *args):
            pass

    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Quiet, directory=out_dir))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    url = f"http://127.0.0.1:{server.server_address[1]}/morph_play.html?file=clumps.glb&t={t}"
    try:
        dom = subprocess.run(["chromium", "--headless=new", "--no-sandbox", "--use-angle=swiftshader",
                              "--enable-unsafe-swiftshader", "--virtual-time-budget=60000", "--dump-dom", url],
                             check=True, timeout=300, capture_output=True, text=True).stdout
    finally:
        server.shutdown()
    found = re.search(r'<pre id="out">(.*?)</pre>', dom, re.S)
    if not found or not found.group(1).strip():
        sys.exit(f"three.js wrote nothing: {re.search(r'<title>(.*?)</title>', dom) or dom[:300]}")
    played = json.loads(html.unescape(found.group(1)))
    assert played["glError"] == 0, f"WebGL error {played['glError']} drawing the clumps"
    return played["meshes"]


def main():
    if shutil.which("chromium") is None:
        print("skipped: chromium is not installed (scripts/install-deps.sh installs it)")
        return 77
    if not os.path.isdir(os.path.join(HERE, "node_modules", "three")):
        print("skipped: tests/web/node_modules is missing (npm ci in tests/web)")
        return 77
    glb, frames, frame_time, out_dir = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
    os.makedirs(out_dir, exist_ok=True)
    shutil.copy(glb, os.path.join(out_dir, "clumps.glb"))
    for name in ("morph_play.html", "morph_play.js"):
        shutil.copy(os.path.join(HERE, name), out_dir)
    link = os.path.join(out_dir, "node_modules")
    if not os.path.exists(link):
        os.symlink(os.path.join(HERE, "node_modules"), link)
    every, names = instance_names(glb)
    assert names, "no moving clump instances in the file"
    first, middle, last = (play(out_dir, k * frame_time) for k in (0, frames // 2, frames - 1))
    missing = sorted(set(names) - set(first))
    assert not missing, f"three.js has no morphed mesh for {missing[:5]}"
    moves = {}
    for name in names:
        a, b, c = first[name]["xyz"], middle[name]["xyz"], last[name]["xyz"]
        assert max(abs(x - y) for x, y in zip(a, c)) <= 1e-5, f"{name}: the loop does not close"
        moves[name] = [y - x for x, y in zip(a, b)]
    by_clump = {}
    for name in names:
        by_clump.setdefault(name.rsplit("_cell", 1)[0], []).append(name)
    alike = differ = 0
    for group in by_clump.values():
        for other in group[1:]:
            d = max(abs(x - y) for x, y in zip(moves[group[0]], moves[other]))
            differ += d > 1e-5
            alike += d <= 1e-5
    assert differ > 0, "every instance of a clump moves alike"
    print(f"three.js plays {len(names)} moving clump instances (of {len(every)}) ({len(by_clump)} clumps); loops close; "
          f"{differ} of {differ + alike} pairs with the clump's first instance move differently at key {frames // 2}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
