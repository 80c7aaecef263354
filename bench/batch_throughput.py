#!/usr/bin/env python3
"""Throughput of the Python batch API: simulate_many on random strokes (seeded) from the cue ball at the head spot
on layouts of 1, 3 and 7 object balls, on 1 and 2 threads; shots a second, and the speed-up of two threads.
The single-call path is timed too (predict_shot in a Python loop), to show what the batch saves, and strike_many
(the strikes alone, no paths) on the same strokes.

Usage: PYTHONPATH=<the package> python3 bench/batch_throughput.py [shots]   (bench/NOTES.md, Python batches)
"""
import math
import sys
import time

import numpy as np

import billiard_shot_planner as bsp

LAYOUTS = {
    1: {"one": (0.3, 0.05)},
    3: {"one": (0.3, 0.05), "two": (0.6, -0.3), "three": (0.9, 0.4)},
    7: {"one": (0.3, 0.05), "two": (0.6, -0.3), "three": (0.9, 0.4), "four": (-0.2, 0.45), "five": (1.0, -0.1),
        "six": (0.1, -0.5), "seven": (0.5, 0.3)},
}


def strokes(n, seed=1):
    rng = np.random.default_rng(seed)
    return np.column_stack([rng.uniform(-math.pi, math.pi, n), rng.uniform(0.0, 0.2, n), rng.uniform(0.5, 4.0, n),
                            rng.uniform(-0.3, 0.3, n), rng.uniform(-0.3, 0.3, n)])


def timed(call):
    start = time.perf_counter()
    call()
    return time.perf_counter() - start


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 400
    rows = strokes(n)
    cue_ball = (-0.635, 0.0)
    print(f"{n} random strokes per layout; shots a second (median of 3 runs)")
    print("object balls | loop of predict_shot | simulate_many, 1 thread | 2 threads | speed-up")
    for count, balls in LAYOUTS.items():
        loop = sorted(timed(lambda: [bsp.predict_shot(bsp.Stroke(*r), cue_ball, balls) for r in rows])
                      for _ in range(3))[1]
        one = sorted(timed(lambda: bsp.simulate_many(rows, cue_ball, balls, threads=1)) for _ in range(3))[1]
        two = sorted(timed(lambda: bsp.simulate_many(rows, cue_ball, balls, threads=2)) for _ in range(3))[1]
        print(f"{count} | {n / loop:.0f} | {n / one:.0f} | {n / two:.0f} | {one / two:.2f}")
    print("strike_many, strikes a second: 1 thread | 2 threads")
    many = strokes(20 * n, seed=2)
    one = sorted(timed(lambda: bsp.strike_many(many, cue_ball, LAYOUTS[1], threads=1)) for _ in range(3))[1]
    two = sorted(timed(lambda: bsp.strike_many(many, cue_ball, LAYOUTS[1], threads=2)) for _ in range(3))[1]
    print(f"{len(many) / one:.0f} | {len(many) / two:.0f}")


if __name__ == "__main__":
    main()
