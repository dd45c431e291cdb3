#!/usr/bin/env python3
"""A stand of 100 trees in gusty wind: how far the tops of a few of them sway over time.

Ten by ten trees of three species, 6 m apart, in a wind of three sine-sum waves plus gusts
that sweep the stand now and then, stepped at 30 Hz. Each step records the top of four
trees (the tip, the last control point, of the branch that reaches highest at rest); the
plot shows each top's horizontal displacement from its rest position over time, in the
wind's direction and across it. Written as a PNG with matplotlib when it is installed, else as CSV.

    build/boreas-python python/examples/gusty_stand.py --seconds 20 --out gusty_stand.png

(build/boreas-python: the interpreter the package is built for, with the package on its
path; python3 works where the package is installed.)
"""
import argparse
import csv
import os
import sys
import time

import numpy as np

import boreas

SPECIES = ["quaking_aspen", "black_tupelo", "ca_black_oak"]
SPACING = 6.0  # m between neighbouring trees
WATCHED = [0, 14, 55, 99]  # trees whose tips are recorded (row-major in the 10 x 10 grid)
WIND_DIRECTION = np.array([0.8, 0.0, 0.6])  # the main wave's, on the ground (x, z)


def build(world):
    """Plants the stand (one batch call) and starts the gusts; returns the trees."""
    rows = [(SPACING * (i % 10), 0.0, SPACING * (i // 10)) for i in range(100)]
    rng = np.random.default_rng(7)
    trees = world.add_trees(
        species=[SPECIES[i % 3] for i in range(100)],
        position=rows,
        rotation=rng.uniform(0, 2 * np.pi, 100).tolist(),
        seed=[1 + 2 * (i % 2) for i in range(100)],  # 6 grown models shared by 100 trees
        mode="exact",
        response="damped")
    for k, delay in enumerate((1.0, 6.0, 11.0, 15.0)):
        world.wind.add_gust(direction=tuple(WIND_DIRECTION), strength=6.0 + 2.0 * k,
                            delay=delay, rise=0.8, hold=1.5, fall=2.0,
                            center=(27.0, 5.0, 27.0), radius=40.0)
    return trees


def tips(trees, top):
    """(len(trees), 3) m: the tip of branch top[i] of tree i."""
    return np.array([t.branches["control_points"][b, 3] for t, b in zip(trees, top)])


def run(seconds, rate):
    grid = boreas.Grid(origin=(-10.0, 0.0, -10.0), cell_size=2.0, resolution=(40, 12, 40))
    waves = [
        boreas.Wave(direction=(0.8, 0.6), amplitude=5.0, wavelength=40.0, speed=6.0,
                    sharpness=1.0),
        boreas.Wave(direction=(0.6, 0.8), amplitude=2.0, wavelength=15.0, speed=4.0,
                    sharpness=3.0),
        boreas.Wave(direction=(1.0, 0.2), amplitude=1.0, wavelength=7.0, speed=3.0,
                    sharpness=2.0),
    ]
    with boreas.World(grid=grid, waves=waves) as world:
        start = time.perf_counter()
        trees = build(world)
        print(f"planted 100 trees in {time.perf_counter() - start:.2f} s on "
              f"{world.device.name}")
        watched = [trees[i] for i in WATCHED]
        # The branch of each watched tree whose tip is highest at rest: the tree's top.
        top = [int(np.argmax(t.branches["control_points"][:, 3, 1])) for t in watched]
        rest = tips(watched, top)
        downwind = WIND_DIRECTION / np.linalg.norm(WIND_DIRECTION)
        across = np.cross([0.0, 1.0, 0.0], downwind)
        steps = max(1, int(round(seconds * rate)))
        times = np.zeros(steps)
        along = np.zeros((steps, len(watched)))
        side = np.zeros((steps, len(watched)))
        start = time.perf_counter()
        for s in range(steps):
            world.step(1.0 / rate)
            moved = tips(watched, top) - rest
            times[s] = world.time
            along[s] = moved @ downwind
            side[s] = moved @ across
        elapsed = time.perf_counter() - start
        stats = world.step_stats
        print(f"{steps} steps in {elapsed:.2f} s ({1000 * elapsed / steps:.1f} ms each; "
              f"{stats.branches_stepped} branches stepped)")
    return times, along, side


def write_png(path, times, along, side):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    for k, tree in enumerate(WATCHED):
        label = f"tree {tree} ({SPECIES[tree % 3]})"
        axes[0].plot(times, along[:, k], label=label)
        axes[1].plot(times, side[:, k], label=label)
    axes[0].set_ylabel("downwind (m)")
    axes[1].set_ylabel("across the wind (m)")
    axes[1].set_xlabel("time (s)")
    axes[0].set_title("Tree tops of a 100-tree stand in gusty wind")
    axes[0].legend(loc="upper right", fontsize="small")
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def write_csv(path, times, along, side):
    with open(path, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["time_s"] + [f"tree{t}_downwind_m" for t in WATCHED]
                     + [f"tree{t}_across_m" for t in WATCHED])
        for s in range(len(times)):
            out.writerow([f"{times[s]:.4f}"] + [f"{x:.5f}" for x in along[s]]
                         + [f"{x:.5f}" for x in side[s]])


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=20.0, help="simulated time (s)")
    parser.add_argument("--rate", type=float, default=30.0, help="steps per second (Hz)")
    parser.add_argument("--out", default="gusty_stand.png",
                        help="the plot (PNG); a .csv beside it without matplotlib")
    args = parser.parse_args(argv)
    times, along, side = run(args.seconds, args.rate)
    print(f"largest displacement of a top downwind: {along.max():.3f} m")
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        path = os.path.splitext(args.out)[0] + ".csv"
        write_csv(path, times, along, side)
    else:
        path = args.out
        write_png(path, times, along, side)
    print(f"wrote {path}")
    # The stand must have moved: a tip that never left its rest position means no wind.
    return 0 if np.abs(along).max() > 1e-3 else 1


if __name__ == "__main__":
    sys.exit(main())
