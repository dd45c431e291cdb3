"""The items of a dataset (boreas.dataset): a scene file and a seed each, with a name that
is the item's folder. From the command line's ``--scene``/``--seeds`` or an items file of
JSON lines."""
from __future__ import annotations

import dataclasses
import json
import os
import re
from typing import Iterable, List, Optional, Sequence

# An item's name is a folder name on every file system a cluster may share.
_NAME = re.compile(r"^[A-Za-z0-9][A-Za-z0-9._-]{0,127}$")


@dataclasses.dataclass(frozen=True)
class Item:
    """One run of ``boreas run``: ``scene`` (an absolute path) with ``--seed seed`` (None:
    the scene's own seeds), written into ``<dataset>/<name>/``."""
    name: str
    scene: str
    seed: Optional[int] = None


def item_name(scene: str, seed: Optional[int]) -> str:
    """``forest.json``, 7 -> ``forest_s7``; no seed -> ``forest``. Characters a folder
    name should not hold become ``-``."""
    stem = os.path.splitext(os.path.basename(scene))[0] or "scene"
    stem = re.sub(r"[^A-Za-z0-9._-]", "-", stem).lstrip(".-_") or "scene"
    return stem if seed is None else f"{stem}_s{seed}"


def _check_seed(seed, where: str) -> Optional[int]:
    if seed is None:
        return None
    if isinstance(seed, bool) or not isinstance(seed, int) or not 0 <= seed < 2**64:
        raise ValueError(f"{where}: seed must be a whole number in [0, 2^64 - 1] (got {seed!r})")
    return seed


def parse_seeds(text: str) -> List[int]:
    """``"0:100"`` (a range, the end excluded), ``"3,5,9"``, ``"7"`` or a mix
    (``"0:4,10"``), in that order; duplicates refused."""
    seeds: List[int] = []
    for part in text.split(","):
        part = part.strip()
        bounds = part.split(":")
        if len(bounds) > 2 or not all(re.fullmatch(r"[0-9]+", b) for b in bounds):
            raise ValueError(f"--seeds: expected N, A:B or a comma-separated list of them "
                             f"(got {text!r})")
        values = [int(b) for b in bounds]
        if len(values) == 2 and values[1] <= values[0]:
            raise ValueError(f"--seeds: the range {part!r} is empty (its end is excluded)")
        seeds.extend(range(values[0], values[1]) if len(values) == 2 else values)
    for s in seeds:
        _check_seed(s, "--seeds")
    if len(set(seeds)) != len(seeds):
        raise ValueError(f"--seeds: {text!r} names a seed twice")
    return seeds


def items_from(scenes: Sequence[str], seeds: Optional[Iterable[int]] = None) -> List[Item]:
    """Every scene with every seed (scene-major); no seeds: each scene once with its own."""
    seed_list: List[Optional[int]] = list(seeds) if seeds is not None else [None]
    return check_items([Item(item_name(s, seed), os.path.abspath(s), seed)
                        for s in scenes for seed in seed_list])


def read_items_file(path: str) -> List[Item]:
    """JSON lines of ``{"scene": PATH, "seed": N, "name": NAME}`` (seed and name optional;
    relative scene paths are found beside the items file; blank lines and lines starting
    with ``#`` are skipped). Errors name the file and line."""
    base = os.path.dirname(os.path.abspath(path))
    items: List[Item] = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if not line.strip() or line.lstrip().startswith("#"):
                continue
            where = f"{path}:{number}"
            try:
                entry = json.loads(line)
            except json.JSONDecodeError as e:
                raise ValueError(f"{where}: not JSON: {e.msg}") from None
            if not isinstance(entry, dict) or not isinstance(entry.get("scene"), str):
                raise ValueError(f'{where}: expected an object with a "scene" path')
            unknown = set(entry) - {"scene", "seed", "name"}
            if unknown:
                raise ValueError(f"{where}: unknown key {sorted(unknown)[0]!r} "
                                 f'(expected "scene", "seed", "name")')
            seed = _check_seed(entry.get("seed"), where)
            scene = os.path.normpath(os.path.join(base, entry["scene"]))
            name = entry.get("name", item_name(scene, seed))
            if not isinstance(name, str):
                raise ValueError(f"{where}: name must be a string")
            items.append(Item(name, scene, seed))
    return check_items(items)


def check_items(items: List[Item]) -> List[Item]:
    """Refuses names that are not plain folder names and two items of one name."""
    seen = {}
    for item in items:
        if not _NAME.match(item.name):
            raise ValueError(f"item {item.name!r}: a name is 1-128 letters, digits, '.', '_' "
                             f"or '-', starting with a letter or digit")
        if item.name in seen:
            raise ValueError(f"item {item.name!r} twice: {seen[item.name].scene} (seed "
                             f"{seen[item.name].seed}) and {item.scene} (seed {item.seed}); "
                             f"give the items names in an items file")
        seen[item.name] = item
    return items
