"""docs/viewer plays an exported file as its README says to watch one: the repository's
root served (three.js from tests/web/node_modules), the viewer opened on the file in
headless Chromium. Its probe page (viewer_probe.html) reads the viewer's own renderer: the
file loaded (the viewer's line names its clip), the model covers part of the frame, the
animation's clock advanced under the viewer's own loop, and the sway changed pixels.

Run: python3 viewer_plays.py FILE.glb. Exits 77 (skipped) where Chromium or
tests/web/node_modules is missing."""
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

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
SERVED_AS = "/under-test.glb"


def serve(glb):
    """The repository's root over HTTP, and the file under test at SERVED_AS."""

    class Root(http.server.SimpleHTTPRequestHandler):
        def translate_path(self, path):
            if path.split("?")[0] == SERVED_AS:
                return glb
            return super().translate_path(path)

        def log_message(self, *args):
            pass

    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Root, directory=ROOT))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


def main():
    if shutil.which("chromium") is None:
        print("skipped: chromium is not installed (scripts/install-deps.sh installs it)")
        return 77
    if not os.path.isdir(os.path.join(HERE, "node_modules", "three")):
        print("skipped: tests/web/node_modules is missing (npm ci in tests/web)")
        return 77
    glb = os.path.abspath(sys.argv[1])
    server = serve(glb)
    url = f"http://127.0.0.1:{server.server_address[1]}/tests/web/viewer_probe.html?file={SERVED_AS}"
    try:
        dom = subprocess.run(["chromium", "--headless=new", "--no-sandbox", "--use-angle=swiftshader",
                              "--enable-unsafe-swiftshader", "--virtual-time-budget=90000",
                              "--dump-dom", url], check=True, timeout=300, capture_output=True,
                             text=True).stdout
    finally:
        server.shutdown()
    found = re.search(r'<pre id="out">(.*?)</pre>', dom, re.S)
    if not found or not found.group(1).strip():
        sys.exit(f"the probe wrote nothing: {dom[:300]}")
    seen = json.loads(html.unescape(found.group(1)))
    print(json.dumps(seen))
    assert "error" not in seen, seen["error"]
    assert seen["loaded"], f"the viewer did not load the file: {seen['info']!r}"
    assert re.search(r"under-test\.glb: [0-9.]+ s, [1-9][0-9]* tracks", seen["info"]), seen["info"]
    # At least 0.5 % of the frame: a grove framed by the viewer covers far more.
    assert seen["playing"], "the viewer's clip is not running"
    assert seen["covered"] > 0.005 * seen["pixels"], f"the model covers {seen['covered']} pixels"
    # The probe waits up to 60 s for the viewer's loop to play 0.1 s; drawn in software under
    # Chromium's virtual time the loop gets few frames (0.01-0.4 s played in trials), so
    # what must show is that it moved at all, and that the frame changed with it.
    assert seen["t1"] > seen["t0"], f"the animation's clock went {seen['t0']} -> {seen['t1']} s"
    assert seen["changed"] > 0, "the frame did not change as the animation played"
    print(f"the viewer loaded {os.path.basename(glb)}: the model covers {seen['covered']} of "
          f"{seen['pixels']} pixels, {seen['t1'] - seen['t0']:.2f} s played, {seen['changed']} changed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
