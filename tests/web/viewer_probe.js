// Waits for docs/viewer (in a frame, served from the repository's root as its README says)
// to load ?file= and start its animation, then reads the viewer's own renderer: how many
// pixels the model covers (drawn against drawn without it), whether its clip's action runs,
// how far the mixer's clock moved under the viewer's own loop, and how many pixels that
// motion changed.
// Writes {loaded, info, playing, covered, t0, t1, changed, pixels} as JSON into #out, or {error}.
const file = new URLSearchParams(location.search).get('file');
const frame = document.createElement('iframe');
frame.width = 320;
frame.height = 240;
frame.src = '/docs/viewer/?file=' + encodeURIComponent(file);
document.body.appendChild(frame);
const out = (o) => { document.getElementById('out').textContent = JSON.stringify(o); };
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

// The viewer's frame as it stands, drawn and read back in one task (no preserved buffer).
function pixels(v) {
  v.renderer.render(v.scene, v.camera);
  const gl = v.renderer.getContext();
  const w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
  const p = new Uint8Array(4 * w * h);
  gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, p);
  return p;
}
function differing(a, b) {
  let n = 0;
  for (let i = 0; i < a.length; i += 4)
    if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 6) ++n;
  return n;
}

(async () => {
  let v = null;
  for (let k = 0; k < 600 && !(v && v.mixer && v.model); ++k) {
    await sleep(100);
    v = frame.contentWindow && frame.contentWindow.boreasViewer;
  }
  const info = frame.contentDocument ? frame.contentDocument.getElementById('info').textContent : '';
  if (!(v && v.mixer && v.model)) return out({ loaded: false, info });
  v.model.visible = false;
  const empty = pixels(v);
  v.model.visible = true;
  const first = pixels(v), t0 = v.mixer.time;
  // Software drawing makes the viewer's frames slow and few: wait for its own loop to
  // play 0.1 s of the clip (up to 60 s), not for a fixed time.
  for (let k = 0; k < 600 && v.mixer.time - t0 < 0.1; ++k) await sleep(100);
  const later = pixels(v), t1 = v.mixer.time;
  out({ loaded: true, info, playing: Boolean(v.action && v.action.isRunning()),
        covered: differing(empty, first), t0, t1,
        changed: differing(first, later), pixels: first.length / 4 });
})().catch((e) => out({ error: String(e) }));
