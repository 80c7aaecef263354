"""A batch on a Dask cluster of two worker processes (a LocalCluster) gives the arrays simulate_many gives in this
process, row for row, and a configuration travels to the workers whole (pickled by its parameters)."""
import math
import pickle

import numpy as np
import pytest

import billiard_shot_planner as bsp

distributed = pytest.importorskip("distributed")
from billiard_shot_planner.distributed import simulate_many_on  # noqa: E402

CUE, BALLS = (-0.635, 0.0), {"one": (0.3, 0.05), "two": (0.6, -0.3)}


def strokes(n=40, seed=11):
    rng = np.random.default_rng(seed)
    return np.column_stack([rng.uniform(-math.pi, math.pi, n), rng.uniform(0.0, 0.2, n), rng.uniform(0.5, 4.0, n),
                            rng.uniform(-0.3, 0.3, n), rng.uniform(-0.3, 0.3, n)])


def test_a_configuration_pickles_whole():
    config = bsp.Configuration()
    config["table/cloth/friction"] = 0.31
    config["cue_end_mass"] = math.inf
    copy = pickle.loads(pickle.dumps(config))
    assert all(copy[name] == config[name] for name in config.names())


def test_a_batch_on_two_workers_equals_the_batch_in_process():
    rows = strokes()
    rows[3, 3] = 1.5  # a row with an error travels back too
    config = bsp.Configuration()
    config["motion/sliding_friction"] = 0.25
    here = bsp.simulate_many(rows, CUE, BALLS, config)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            there = simulate_many_on(client, rows, CUE, BALLS, config, chunk_size=7)
    assert there["ids"] == here["ids"]
    for name in ("velocity", "angular_velocity", "final_position"):
        assert np.array_equal(there[name], here[name], equal_nan=True), name
    assert np.array_equal(there["pocket"], here["pocket"])  # strings: no NaN
    assert [e is None for e in there["error"]] == [e is None for e in here["error"]]
    assert there["error"][3].field == "a" and there["error"][3].code == "invalid_argument"
