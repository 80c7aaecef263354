"""Batches of shots on a Dask cluster (Debian's python3-distributed): simulate_many split into chunks, each chunk a
task on a worker process, the answers put back together in the order of the rows — the same arrays simulate_many
gives in one process.

    from distributed import Client, LocalCluster
    from billiard_shot_planner.distributed import simulate_many_on

    with LocalCluster(n_workers=2, threads_per_worker=1) as cluster, Client(cluster) as client:
        batch = simulate_many_on(client, strokes, cue_ball=(-0.635, 0.0), balls={"one": (0.3, 0.05)})

Point the Client at a scheduler (`dask-scheduler`, then `dask-worker tcp://host:8786` on each machine, every machine
with this package importable) to spread a batch over many machines. docs/python.md, Dask.
"""
import numpy as np

from ._core import Configuration, simulate_many

ARRAYS = ("velocity", "angular_velocity", "final_position", "pocket")


def simulate_chunk(strokes, cue_ball, balls, configuration):
    """One task: simulate_many on the worker, one thread (the cluster's workers are the parallelism)."""
    return simulate_many(strokes, cue_ball, balls, configuration, threads=1)


def simulate_many_on(client, strokes, cue_ball, balls=None, configuration=None, chunk_size=256):
    """simulate_many of `strokes` ((N, 5)) on the Dask `client`'s workers, `chunk_size` rows a task; the same dict."""
    strokes = np.asarray(strokes, dtype=float)
    if strokes.ndim != 2 or strokes.shape[1] != 5:
        # The in-process call names the field exactly as it would.
        return simulate_many(strokes, cue_ball, balls, configuration or Configuration())
    if chunk_size < 1:
        raise ValueError("chunk_size must be >= 1")
    configuration = configuration or Configuration()
    chunks = [strokes[i : i + chunk_size] for i in range(0, len(strokes), chunk_size)] or [strokes]
    futures = client.map(simulate_chunk, chunks, cue_ball=cue_ball, balls=balls, configuration=configuration,
                         pure=False)
    parts = client.gather(futures)
    batch = {"ids": parts[0]["ids"], "error": [e for part in parts for e in part["error"]]}
    for name in ARRAYS:
        batch[name] = np.concatenate([part[name] for part in parts])
    return batch
