#!/usr/bin/env python3
"""Times world.wind.sample of 1,000,000 points from Python (into a preallocated out=) and
the same call from C (boreas_sample_timing, built beside the module) on the same world,
and prints both medians and their ratio. Rounds alternate between the two, so that a
machine busy with something else slows both alike.

    python3 sample_bench.py <build>/python/boreas_sample_timing [--points N] [--runs N]
"""
import argparse
import statistics
import subprocess
import sys
import time

import numpy as np

import boreas


def make_world():
    """The world of sample_timing.c."""
    grid = boreas.Grid(origin=(-32.0, 0.0, -32.0), cell_size=2.0, resolution=(32, 8, 32))
    waves = [boreas.Wave(direction=(0.8, 0.6), amplitude=5.0, wavelength=40.0, speed=6.0,
                         sharpness=1.0),
             boreas.Wave(direction=(0.6, 0.8), amplitude=2.0, wavelength=15.0, speed=4.0,
                         sharpness=3.0),
             boreas.Wave(direction=(1.0, 0.2), amplitude=1.0, wavelength=7.0, speed=3.0,
                         sharpness=2.0)]
    world = boreas.World(grid=grid, waves=waves)
    for _ in range(2):
        world.step(1 / 30)
    return world


def python_times(world, points, runs):
    rng = np.random.default_rng(12345)
    pts = rng.uniform(0.0, 1.0, size=(points, 3)).astype(np.float32)
    pts[:, [0, 2]] = 80.0 * pts[:, [0, 2]] - 40.0
    pts[:, 1] *= 20.0
    out = np.empty_like(pts)
    world.wind.sample(pts, out=out)  # warm-up
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        world.wind.sample(pts, out=out)
        times.append(time.perf_counter() - t0)
    return times


def c_median(program, points, runs):
    result = subprocess.run([program, str(points), str(runs)], check=True,
                            capture_output=True, text=True)
    return float(result.stdout.split()[1])


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("program", help="path of boreas_sample_timing")
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--runs", type=int, default=21, help="calls timed per round")
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args(argv)
    with make_world() as world:
        device = world.device.name
        py, c = [], []
        for _ in range(args.rounds):
            c.append(c_median(args.program, args.points, args.runs))
            py.append(statistics.median(python_times(world, args.points, args.runs)))
    c_s, py_s = statistics.median(c), statistics.median(py)
    print(f"device: {device}")
    print(f"points: {args.points}, {args.rounds} rounds of {args.runs} calls (medians)")
    print(f"C      boreas_wind_sample: {1e3 * c_s:8.3f} ms")
    print(f"Python world.wind.sample : {1e3 * py_s:8.3f} ms")
    print(f"ratio Python / C         : {py_s / c_s:8.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
