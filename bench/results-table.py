#!/usr/bin/env python3
# boreas: turns boreas_bench's JSON output into the Markdown table of bench/RESULTS.md, one
# row per benchmark and size with the native and CL figures side by side.
#   usage: boreas_bench --benchmark_out=run1.json --benchmark_repetitions=3 ...  (N times)
#          bench/results-table.py run1.json [run2.json ...]
# Each figure is the best over all repetitions of all files given: on a shared machine other
# work only ever slows a run down, so the best is the closest to what the code can do. The
# spread column (min..max of the CL kernel rate) says how noisy the runs were.
import json
import sys
from collections import defaultdict


def si(value, unit):
    for factor, prefix in ((1e9, "G"), (1e6, "M"), (1e3, "k")):
        if abs(value) >= factor:
            return f"{value / factor:.3g} {prefix}{unit}"
    return f"{value:.3g} {unit}"


def main(paths):
    runs = []
    for path in paths:
        with open(path) as f:
            runs += [b for b in json.load(f)["benchmarks"] if b.get("run_type") == "iteration"]
    # name -> counter -> list of values over repetitions
    values = defaultdict(lambda: defaultdict(list))
    order = []
    for b in runs:
        name = b["run_name"] if "run_name" in b else b["name"]
        if name not in values:
            order.append(name)
        if b.get("error_occurred"):
            values[name]["error"].append(b.get("error_message", "error"))
            continue
        for key in ("items_per_second", "bytes_per_second", "kernel_items/s", "kernel_bytes/s",
                    "vs_copy", "items"):
            values[name][key].append(b.get(key, 0.0))

    def best(name, key):
        v = values[name].get(key)
        return max(v) if v else None

    rows = []
    seen = set()
    for name in order:
        # BM_<Name>/<kind>/<size>[/<variant>], e.g. BM_TreeStep/cl/65536/lagged
        parts = name.split("/")
        family, kind, size = parts[:3]
        variant = "/".join(parts[3:])
        if (family, size, variant) in seen:
            continue
        seen.add((family, size, variant))
        suffix = f"/{variant}" if variant else ""
        native, cl = f"{family}/native/{size}{suffix}", f"{family}/cl/{size}{suffix}"
        n_items = best(native, "items_per_second")
        c_items = best(cl, "items_per_second")
        k_items = best(cl, "kernel_items/s")
        spread = values[cl].get("kernel_items/s", [])
        error = values[cl].get("error")
        items = best(native, "items") or best(cl, "items")
        shown = size if not items or int(items) == int(size) else f"{size} ({si(items, '')})"
        cells = [family + (f" ({variant})" if variant else ""), shown,
                 si(n_items, "/s") if n_items else "-",
                 error[0] if error else (si(c_items, "/s") if c_items else "-"),
                 si(k_items, "/s") if k_items else "-",
                 (f"{si(min(spread), '')}..{si(max(spread), '')}" if len(spread) > 1 else "-"),
                 f"{c_items / n_items:.2f}" if n_items and c_items else "-",
                 si(best(native, "bytes_per_second"), "B/s") if n_items else "-",
                 si(best(cl, "bytes_per_second"), "B/s") if c_items else "-",
                 si(best(cl, "kernel_bytes/s"), "B/s") if k_items else "-",
                 f"{best(cl, 'vs_copy'):.2f}" if c_items else "-"]
        rows.append(cells)
    header = ["benchmark", "items", "native items/s", "CL items/s (wall)",
              "CL items/s (kernel)", "CL kernel spread", "CL/native", "native bytes/s",
              "CL bytes/s (wall)", "CL bytes/s (kernel)", "CL bytes vs CL copy"]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for r in rows:
        print("| " + " | ".join(str(c) for c in r) + " |")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit("usage: results-table.py boreas_bench_output.json [more.json ...]")
    main(sys.argv[1:])
