"""The manifest of a dataset (boreas.dataset): ``<dataset>/manifest.jsonl``, one JSON line
per finished or failed item, appended by the client alone as results arrive. The last
line of an item is its state; a rerun skips an item whose last line says finished and
whose files are all there with their sizes."""
from __future__ import annotations

import errno
import fcntl
import json
import os
from typing import Dict, List, Optional

MANIFEST = "manifest.jsonl"


class Manifest:
    """The manifest, open for appending and locked (``flock``) against a second client
    writing the same dataset at the same time."""

    def __init__(self, dataset_dir: str):
        self.path = os.path.join(dataset_dir, MANIFEST)
        self.last = read_manifest(self.path)
        self._file = open(self.path, "a", encoding="utf-8")
        try:
            fcntl.flock(self._file, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError as e:
            self._file.close()
            if e.errno in (errno.EAGAIN, errno.EACCES):
                raise RuntimeError(f"{self.path}: another boreas.dataset is writing this "
                                   f"dataset") from None
            raise

    def append(self, entry: dict) -> None:
        """One line, flushed and synced: a client killed later loses no finished item."""
        self._file.write(json.dumps(entry, sort_keys=False) + "\n")
        self._file.flush()
        os.fsync(self._file.fileno())
        self.last[entry["item"]] = entry

    def close(self) -> None:
        self._file.close()  # closing releases the lock

    def __enter__(self) -> "Manifest":
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def read_manifest(path: str) -> Dict[str, dict]:
    """The last entry of each item. A line cut short (a client killed while writing it)
    is skipped: its item is run again."""
    last: Dict[str, dict] = {}
    if not os.path.exists(path):
        return last
    with open(path, encoding="utf-8") as f:
        for line in f:
            try:
                entry = json.loads(line)
            except json.JSONDecodeError:
                continue
            if isinstance(entry, dict) and isinstance(entry.get("item"), str):
                last[entry["item"]] = entry
    return last


def is_finished(entry: Optional[dict], dataset_dir: str, run: dict) -> bool:
    """Whether an item needs no rerun: finished, made with the same scene file contents,
    seed and ``boreas run`` arguments (``run``: the keys an entry records of them), and
    every file it listed is there with its size."""
    if not entry or entry.get("status") != "finished":
        return False
    if any(entry.get(key) != value for key, value in run.items()):
        return False
    files: List[dict] = entry.get("files") or []
    for f in files:
        path = os.path.join(dataset_dir, f.get("path", ""))
        if not os.path.isfile(path) or os.path.getsize(path) != f.get("size"):
            return False
    return bool(files)
