"""Datasets of ``boreas run`` over many machines: (scene, seed) items mapped over a Dask
cluster (``dask.distributed``), each item's frames, summary and whatever else the run
writes in ``<dataset>/<item>/``, and ``<dataset>/manifest.jsonl`` saying what finished.

Command line (``python -m boreas.dataset --help``)::

    python -m boreas.dataset out/ds --scene a.json --scene b.json --seeds 0:100 \\
        --devices 0:0,0:1 -- --view slice --frames 8
    python -m boreas.dataset out/ds --items items.jsonl --scheduler tcp://host:8786

From Python::

    from boreas.dataset import dataset, items_from
    report = dataset("out/ds", items_from(["a.json"], range(10)), workers=2)

A rerun skips the items that finished (manifest entry finished, files all there, same
scene file contents, seed and run arguments) and runs the others. An item that fails
(a missing or malformed scene, a run that stops with an error) is recorded with the
command's message and exit code, and the rest go on. A worker that dies in the middle of
an item leaves nothing that looks finished (runs write under ``<dataset>/.partial/`` and
are renamed into place when done); the scheduler gives the item to another worker (up to
``distributed.scheduler.allowed-failures`` deaths per item, 3 by default).
"""
from __future__ import annotations

import argparse
import dataclasses
import hashlib
import os
import shlex
import shutil
import sys
import time
import uuid
from typing import Iterable, List, Optional, Sequence, Union

from ._dataset_items import Item, check_items, item_name, items_from, parse_seeds, read_items_file
from ._dataset_manifest import MANIFEST, Manifest, is_finished
from ._dataset_run import PARTIAL, DevicePlugin, find_boreas_cli, run_item

__all__ = ["DatasetReport", "Item", "dataset", "items_from", "main", "parse_seeds",
           "read_items_file"]

# boreas run options the dataset sets itself, per item; refused among the run arguments.
_OWN_OPTIONS = ("--out", "--seed", "--window", "-q", "--quiet")


@dataclasses.dataclass
class DatasetReport:
    """What one call did: the items run now (``entries``: their manifest lines, in the order
    they finished), those skipped as finished before, and the names of the failed ones."""
    manifest: str
    total: int
    skipped: List[str]
    entries: List[dict]

    @property
    def failed(self) -> List[str]:
        return [e["item"] for e in self.entries if e["status"] != "finished"]

    @property
    def finished(self) -> List[str]:
        return [e["item"] for e in self.entries if e["status"] == "finished"]


def dataset(out: str, items: Iterable[Union[Item, tuple, dict]], *, workers: Optional[int] = None,
            scheduler: Optional[str] = None, client=None, devices: Sequence[str] = (),
            run_args: Sequence[str] = (), boreas_cli: Optional[str] = None,
            timeout: Optional[float] = None, progress: bool = True) -> DatasetReport:
    """Runs every item not yet finished in ``out`` and records each in its manifest.

    items: :class:`Item` s, ``(scene, seed)`` pairs or ``{"scene", "seed", "name"}`` dicts.
    Where they run: ``client`` (a ``distributed.Client``), else ``scheduler`` (an address,
    ``tcp://host:8786``), else a ``LocalCluster`` of ``workers`` processes of one thread
    each (default: one per device in ``devices``, else 1, since one run on PoCL already
    uses every core); ``workers=0`` runs them one by one in this process, without Dask.
    devices: device requests (``gpu``, ``cpu``, ``P:D``, part of a name), the worker named
    i taking devices[i % len] as its BOREAS_DEVICE. run_args: given to every ``boreas run``
    (``--view slice``, ``--frames 8``, ...). timeout: seconds per run; a run past it fails.
    The scene files and ``out`` must be at the same paths on every worker (a shared
    file system). Raises ValueError for bad items or arguments, before anything runs.
    """
    items = check_items([_as_item(i) for i in items])
    run_args = _check_run_args(run_args)
    if workers is None:
        workers = max(1, len(devices))
    if workers < 0:
        raise ValueError(f"workers: must be >= 0 (got {workers})")
    if client is None and scheduler is None and find_boreas_cli(boreas_cli) is None:
        raise ValueError("no boreas command: give boreas_cli (--boreas), set $BOREAS_CLI or "
                         "put boreas on PATH")
    os.makedirs(out, exist_ok=True)
    out = os.path.abspath(out)
    with Manifest(out) as manifest:
        records = {i.name: _run_record(i, run_args) for i in items}
        skipped = [i.name for i in items
                   if is_finished(manifest.last.get(i.name), out, records[i.name])]
        todo = [i for i in items if i.name not in skipped]
        report = DatasetReport(manifest.path, len(items), skipped, [])
        meter = _Progress(len(todo), len(skipped), progress)
        results = _results(todo, out, run_args, boreas_cli, timeout, workers, scheduler, client,
                           devices)
        for item, entry in results:
            entry = {**records[item.name], **entry}
            manifest.append(entry)
            report.entries.append(entry)
            meter.update(entry)
        shutil.rmtree(os.path.join(out, PARTIAL), ignore_errors=True)  # killed workers' runs
    meter.finish()
    return report


def _as_item(i) -> Item:
    if isinstance(i, Item):
        return Item(i.name, os.path.abspath(i.scene), i.seed)
    if isinstance(i, dict):
        scene, seed = i["scene"], i.get("seed")
        return Item(i.get("name") or item_name(scene, seed), os.path.abspath(scene), seed)
    scene, seed = i
    return Item(item_name(scene, seed), os.path.abspath(scene), seed)


def _check_run_args(run_args: Sequence[str]) -> List[str]:
    run_args = list(run_args)
    for a in run_args:
        if a.split("=")[0] in _OWN_OPTIONS:
            raise ValueError(f"run arguments: {a.split('=')[0]} is set by the dataset per item")
    return run_args


def _run_record(item: Item, run_args: List[str]) -> dict:
    """What makes an item's run what it is, recorded in its entry and compared on a rerun."""
    try:
        with open(item.scene, "rb") as f:
            digest: Optional[str] = hashlib.sha256(f.read()).hexdigest()
    except OSError:
        digest = None
    return {"item": item.name, "scene": item.scene, "scene_sha256": digest, "seed": item.seed,
            "args": run_args}


def _results(todo, out, run_args, boreas_cli, timeout, workers, scheduler, client, devices):
    """(item, entry) as runs end: in this process (workers 0), else through Dask."""
    if not todo:
        return
    if client is None and scheduler is None and workers == 0:
        for item in todo:
            yield item, run_item(item, out, run_args, boreas_cli, timeout)
        return
    from distributed import Client, LocalCluster, as_completed
    own_cluster = own_client = None
    try:
        if client is None:
            if scheduler is None:
                own_cluster = LocalCluster(n_workers=workers, threads_per_worker=1,
                                           processes=True, dashboard_address=None,
                                           host="127.0.0.1")
            client = own_client = Client(scheduler or own_cluster)
        if devices:
            client.register_worker_plugin(DevicePlugin(devices), name=DevicePlugin.name)
        run = uuid.uuid4().hex[:8]  # keys of this call only: a shared scheduler keeps others
        futures = {client.submit(run_item, item, out, run_args, boreas_cli, timeout, pure=False,
                                 key=f"boreas-item-{item.name}-{run}"): item for item in todo}
        for future in as_completed(futures):
            yield futures[future], _entry_of(future)
    finally:
        if own_client is not None:
            own_client.close()
        if own_cluster is not None:
            own_cluster.close()


def _entry_of(future) -> dict:
    """The entry a task returned, or a failed one for a task that raised (the item's
    workers died allowed-failures + 1 times: KilledWorker; a full disk, ...)."""
    error = future.exception()
    if error is None:
        return future.result()
    return {"status": "failed", "state_hash": None, "files": [], "timings": None,
            "error": {"message": f"{type(error).__name__}: {error}", "exit_code": None}}


class _Progress:
    """Items done / to do with a rate on stderr, and each failure as it comes."""

    def __init__(self, todo: int, skipped: int, show: bool):
        self.todo, self.done, self.failed, self.show = todo, 0, 0, show
        self.start = time.monotonic()
        if show:
            print(f"boreas.dataset: {todo} items to run, {skipped} finished before",
                  file=sys.stderr, flush=True)

    def update(self, entry: dict) -> None:
        self.done += 1
        if entry["status"] != "finished":
            self.failed += 1
            if self.show:
                print(f"boreas.dataset: {entry['item']} failed: {entry['error']['message']}",
                      file=sys.stderr, flush=True)
        if self.show:
            rate = self.done / max(time.monotonic() - self.start, 1e-9)
            print(f"boreas.dataset: {self.done}/{self.todo} done ({self.failed} failed), "
                  f"{rate * 60:.1f} items/min", file=sys.stderr, flush=True)

    def finish(self) -> None:
        if self.show:
            print(f"boreas.dataset: {self.done - self.failed} finished, {self.failed} failed "
                  f"in {time.monotonic() - self.start:.1f} s", file=sys.stderr, flush=True)


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="python -m boreas.dataset",
        description="Run boreas on (scene, seed) items over a Dask cluster into a dataset "
                    "folder: <out>/<item>/ per item and <out>/manifest.jsonl.",
        epilog="Arguments after -- go to every `boreas run` (e.g. -- --view slice --frames 8). "
               "Exit codes: 0 every item finished, 1 an item failed (see the manifest), "
               "2 bad arguments or items.")
    p.add_argument("out", help="the dataset folder")
    p.add_argument("--scene", action="append", default=[], metavar="FILE",
                   help="a scene file (repeatable); each is run with every seed of --seeds")
    p.add_argument("--seeds", metavar="SEEDS",
                   help="A:B (the end excluded), N or a comma-separated list of them; "
                        "omitted: the scenes' own seeds")
    p.add_argument("--items", metavar="FILE",
                   help='JSON lines of {"scene": FILE, "seed": N, "name": NAME} (seed, name '
                        "optional; scenes relative to the file); instead of --scene")
    p.add_argument("--workers", type=int, metavar="N",
                   help="worker processes of the local cluster (default: one per device, "
                        "else 1); 0: run in this process without Dask")
    p.add_argument("--scheduler", metavar="ADDRESS",
                   help="a running dask-scheduler (tcp://host:8786) instead of a local cluster")
    p.add_argument("--devices", metavar="LIST",
                   help="comma-separated device requests (gpu, cpu, P:D, a name): worker i "
                        "gets the i-th (BOREAS_DEVICE)")
    p.add_argument("--boreas", metavar="PATH", help="the boreas command (default: $BOREAS_CLI, "
                   "the build tree's, or boreas on PATH)")
    p.add_argument("--timeout", type=float, metavar="SECONDS", help="a run longer fails")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress")
    return p


def main(argv: Optional[Sequence[str]] = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    run_args = argv[argv.index("--") + 1:] if "--" in argv else []
    argv = argv[:argv.index("--")] if "--" in argv else argv
    parser = _parser()
    a = parser.parse_args(argv)
    try:
        if bool(a.items) == bool(a.scene):
            raise ValueError("give the items as --scene (with --seeds) or as --items, one of them")
        if a.items and a.seeds:
            raise ValueError("--seeds goes with --scene; an items file gives each item's seed")
        items = (read_items_file(a.items) if a.items
                 else items_from(a.scene, parse_seeds(a.seeds) if a.seeds else None))
        devices = [d for d in (a.devices or "").split(",") if d]
        report = dataset(a.out, items, workers=a.workers, scheduler=a.scheduler,
                         devices=devices, run_args=run_args, boreas_cli=a.boreas,
                         timeout=a.timeout, progress=not a.quiet)
    except (ValueError, OSError, RuntimeError) as e:
        parser.exit(2, f"{parser.prog}: error: {e}\n")
    return 1 if report.failed else 0


if __name__ == "__main__":
    # Through the package's module, not this __main__ copy: Dask sends run_item to the
    # workers by its module's name.
    from boreas.dataset import main as _main
    sys.exit(_main())
