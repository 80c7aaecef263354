#!/usr/bin/env python3
"""The pot probability of every cue-ball position on a grid, for one object ball and one pocket, on a Dask cluster.

For each grid point the robot aims at the ghost ball (the cue ball's centre where it touches the object ball on the
line to the pocket) with a level centre hit, and its execution noise (FastFiz's level 1, billiard_shot_planner.Noise)
spreads `samples` strokes around that aim; the fraction that pots the ball in the pocket without scratching is the
point's probability. Each point's strokes are one task (billiard_shot_planner.distributed.simulate_chunk), all
submitted at once to the cluster's workers; the map is printed with the shots a second.

    python3 examples/dask_pot_map.py --workers 2              # a LocalCluster of 2 worker processes
    python3 examples/dask_pot_map.py --scheduler tcp://host:8786   # a cluster: dask-scheduler, dask-worker ...

Every worker machine needs the package importable (the same build, or PYTHONPATH to it).
"""
import argparse
import math
import time

import numpy as np
from distributed import Client, LocalCluster

import billiard_shot_planner as bsp
from billiard_shot_planner.distributed import simulate_chunk

OBJECT_BALL = (0.8, 0.3)
POCKET = "top_right"  # the (+x, +y) corner pocket, (1.27, 0.635)
POCKET_CENTRE = (1.27, 0.635)


def ghost_ball_aim(cue_ball, radius):
    to_pocket = np.subtract(POCKET_CENTRE, OBJECT_BALL)
    to_pocket /= np.linalg.norm(to_pocket)
    ghost = np.asarray(OBJECT_BALL) - 2.0 * radius * to_pocket
    aim = ghost - np.asarray(cue_ball)
    return math.atan2(aim[1], aim[0])


def grid_points(n):
    xs = np.linspace(-1.0, 0.5, n)
    ys = np.linspace(-0.5, 0.5, max(2, n // 2))
    return [(x, y) for y in ys for x in xs]


def noisy_strokes(phi, samples, rng, radius, speed=2.5):
    noise = bsp.Noise()
    return np.column_stack([phi + noise.phi * rng.standard_normal(samples),
                            np.abs(noise.theta * rng.standard_normal(samples)),
                            speed + noise.speed * rng.standard_normal(samples),
                            noise.a / radius * rng.standard_normal(samples),
                            noise.b / radius * rng.standard_normal(samples)])


def pot_map(client, grid, samples, seed):
    """The probability per grid point, and the shots simulated: one task per point, all submitted at once."""
    configuration = bsp.Configuration()
    radius = configuration["ball_radius"]
    rng = np.random.default_rng(seed)
    tasks = [client.submit(simulate_chunk, noisy_strokes(ghost_ball_aim(cue_ball, radius), samples, rng, radius),
                           cue_ball, {"one": OBJECT_BALL}, configuration, pure=False) for cue_ball in grid]
    probabilities = []
    for batch in client.gather(tasks):
        pots = (batch["pocket"][:, 1] == POCKET) & (batch["pocket"][:, 0] == "")
        probabilities.append(float(np.mean(pots)))
    return probabilities, samples * len(grid)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scheduler", help="address of a running dask-scheduler (default: a LocalCluster)")
    parser.add_argument("--workers", type=int, default=2, help="worker processes of the LocalCluster")
    parser.add_argument("--grid", type=int, default=8, help="points along x (half as many along y)")
    parser.add_argument("--samples", type=int, default=64, help="noisy strokes per point")
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    grid = grid_points(args.grid)
    cluster = None if args.scheduler else LocalCluster(n_workers=args.workers, threads_per_worker=1,
                                                       dashboard_address=None)
    with Client(args.scheduler or cluster) as client:
        start = time.perf_counter()
        probabilities, shots = pot_map(client, grid, args.samples, args.seed)
        seconds = time.perf_counter() - start
    if cluster:
        cluster.close()
    print(f"pot probability of ball 'one' at {OBJECT_BALL} into pocket {POCKET}, from each cue-ball position:")
    for (x, y), p in zip(grid, probabilities):
        print(f"  cue ball ({x:+.2f}, {y:+.2f}): {p:.2f}")
    print(f"{shots} shots in {seconds:.1f} s: {shots / seconds:.0f} shots a second")


if __name__ == "__main__":
    main()
