"""One item of a dataset (boreas.dataset), run on a Dask worker (or in the caller's
process): ``boreas run`` in a subprocess with the worker's device, into a folder of its
own under ``<dataset>/.partial/``, renamed to ``<dataset>/<item>/`` only once the run
finished, so that a half-written item never looks finished."""
from __future__ import annotations

import errno
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import time
import uuid
from typing import List, Optional, Sequence

from ._dataset_items import Item

# Runs in progress write here, on the dataset's own file system (a rename is atomic).
PARTIAL = ".partial"
# The most of a failed run's stderr an entry keeps (characters, its end).
_MAX_ERROR = 4000


def find_boreas_cli(explicit: Optional[str] = None) -> Optional[str]:
    """The ``boreas`` command: the one given, else $BOREAS_CLI, else the build tree's
    (``<build>/render/boreas`` beside ``<build>/python/boreas``), else ``boreas`` on PATH."""
    for candidate in (explicit, os.environ.get("BOREAS_CLI"),
                      os.path.join(os.path.dirname(__file__), "..", "..", "render", "boreas")):
        if candidate and os.path.isfile(candidate) and os.access(candidate, os.X_OK):
            return os.path.abspath(candidate)
    if explicit or os.environ.get("BOREAS_CLI"):
        return None  # named but not there: no silent fallback to another build
    return shutil.which("boreas")


def run_item(item: Item, dataset_dir: str, run_args: Sequence[str] = (),
             boreas_cli: Optional[str] = None, timeout: Optional[float] = None) -> dict:
    """Runs the item and returns its manifest entry (status, state_hash, files, timings,
    error); a run that fails is an entry, not an exception."""
    start = time.time()
    partial = os.path.join(dataset_dir, PARTIAL, f"{item.name}.{uuid.uuid4().hex[:12]}")
    os.makedirs(partial)
    cli = find_boreas_cli(boreas_cli)
    if cli is None:
        exit_code, message = None, (f"no boreas command on {socket.gethostname()}: give its "
                                    f"path (--boreas, $BOREAS_CLI) or put it on PATH")
    else:
        exit_code, message = _run_cli(_argv(cli, item, partial, run_args), timeout)
    entry = {"item": item.name, "status": "failed", "state_hash": None, "files": [],
             "timings": {"start": start, "end": None, "seconds": None, **worker_info()},
             "error": None}
    if exit_code == 0:
        entry["state_hash"] = _state_hash(partial)
        _move_into_place(partial, os.path.join(dataset_dir, item.name))
        entry["files"] = list_files(dataset_dir, item.name)
        entry["status"] = "finished"
    else:
        shutil.rmtree(partial, ignore_errors=True)
        entry["error"] = {"message": message, "exit_code": exit_code}
    end = time.time()
    entry["timings"].update(end=end, seconds=round(end - start, 3))
    return entry


def _argv(cli: str, item: Item, out: str, run_args: Sequence[str]) -> List[str]:
    argv = [cli, "run", item.scene, "--out", out, "--quiet"]
    if item.seed is not None:
        argv += ["--seed", str(item.seed)]
    return argv + list(run_args)


def _run_cli(argv: List[str], timeout: Optional[float]):
    """(exit code, the CLI's message): 0 and "" when it finished; None for a run that
    timed out or could not start."""
    try:
        done = subprocess.run(argv, stdin=subprocess.DEVNULL, capture_output=True, text=True,
                              errors="replace", timeout=timeout, preexec_fn=_die_with_parent)
    except subprocess.TimeoutExpired:
        return None, f"boreas run timed out after {timeout} s"
    except OSError as e:
        return None, f"cannot start {argv[0]}: {e.strerror}"
    if done.returncode == 0:
        return 0, ""
    if done.returncode < 0:
        return done.returncode, f"boreas run was killed by signal {-done.returncode}"
    # The CLI's own words ("boreas: error: scene.json: /run/frames: ..."), else its tail.
    lines = [l for l in done.stderr.splitlines() if l.startswith("boreas: error")]
    message = "\n".join(lines) if lines else done.stderr.strip()[-_MAX_ERROR:]
    return done.returncode, message or f"boreas run exited with {done.returncode}"


def _die_with_parent() -> None:
    """In the child before exec (Linux): a SIGKILL when the worker that started it dies,
    so a killed worker leaves no run writing on behind it."""
    if sys.platform.startswith("linux"):
        import ctypes
        pr_set_pdeathsig = 1
        ctypes.CDLL(None, use_errno=True).prctl(pr_set_pdeathsig, int(signal.SIGKILL), 0, 0, 0)


def _state_hash(out: str) -> Optional[str]:
    try:
        with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
            return json.load(f).get("state_hash")
    except (OSError, ValueError):
        return None


def _move_into_place(partial: str, final: str) -> None:
    """Renames the finished run to the item's folder, replacing what an earlier run that
    did not finish (or is being redone) left there."""
    for _ in range(3):
        if os.path.lexists(final):
            shutil.rmtree(final) if os.path.isdir(final) else os.remove(final)
        try:
            os.rename(partial, final)
            return
        except OSError as e:
            # Another attempt at this item (a worker presumed dead) renamed in between.
            if e.errno not in (errno.ENOTEMPTY, errno.EEXIST):
                raise
    raise RuntimeError(f"{final}: could not be replaced (another run keeps writing it)")


def list_files(dataset_dir: str, name: str) -> List[dict]:
    """Every file of the item's folder: its path relative to the dataset and its size."""
    files = []
    for root, _, names in os.walk(os.path.join(dataset_dir, name)):
        for n in names:
            path = os.path.join(root, n)
            files.append({"path": os.path.relpath(path, dataset_dir).replace(os.sep, "/"),
                          "size": os.path.getsize(path)})
    return sorted(files, key=lambda f: f["path"])


def worker_info() -> dict:
    """Where an item ran: the Dask worker's address ("local" outside Dask), host, process
    and device request ($BOREAS_DEVICE; None: the best device)."""
    address = "local"
    try:
        from distributed import get_worker
        address = get_worker().address
    except (ImportError, ValueError):
        pass
    return {"worker": address, "host": socket.gethostname(), "pid": os.getpid(),
            "device": os.environ.get("BOREAS_DEVICE")}


class DevicePlugin:
    """A Dask worker plugin: the worker named i (LocalCluster names its workers 0, 1, ...;
    ``dask-worker --name 3``) runs its items on devices[i % len(devices)] by setting
    BOREAS_DEVICE in its process; a worker with another name keeps its own BOREAS_DEVICE.
    Registered with the client, it reaches workers that start (or restart) later too."""
    name = "boreas-device"

    def __init__(self, devices: Sequence[str]):
        self.devices = list(devices)

    def setup(self, worker) -> None:
        name = str(worker.name)
        if self.devices and name.isdigit():
            os.environ["BOREAS_DEVICE"] = self.devices[int(name) % len(self.devices)]
