"""Fuzzes the Python bindings' entry points with random and hostile arguments: every call must return or raise
billiard_shot_planner.Error or the TypeError pybind11 raises for an argument of the wrong type, never crash or raise
anything else. Run by test_fuzz.py in a child process, so that a crash fails the test instead of killing pytest.
Usage: python3 fuzz_bindings.py <seed> <rounds>"""
import math
import sys
import tempfile

import numpy as np

import billiard_shot_planner as bsp

NASTY_NUMBERS = [0.0, -0.0, 1.0, -1.0, 1e-300, -1e300, 1e300, math.nan, math.inf, -math.inf, 2**63, -(2**63), 0.5]


def number(rng):
    if rng.random() < 0.5:
        return NASTY_NUMBERS[rng.integers(len(NASTY_NUMBERS))]
    return float(rng.normal(0.0, 10.0 ** rng.integers(-3, 4)))


def anything(rng, depth=0):
    """A value of a random kind: numbers, strings, None, lists and tuples of any length, dicts, arrays."""
    kind = rng.integers(10)
    if kind < 3:
        return number(rng)
    if kind == 3:
        return None
    if kind == 4:
        return ["", "cue", "one", "x" * 1000, "table/cloth/friction", "\0", "é"][rng.integers(7)]
    if kind == 5 and depth < 2:
        return [anything(rng, depth + 1) for _ in range(rng.integers(5))]
    if kind == 6 and depth < 2:
        return tuple(number(rng) for _ in range(rng.integers(5)))
    if kind == 7 and depth < 2:
        return {anything(rng, depth + 1) if rng.random() < 0.2 else "one": anything(rng, depth + 1)
                for _ in range(rng.integers(3))}
    if kind == 8:
        shape = tuple(int(n) for n in rng.integers(0, 4, rng.integers(0, 4)))
        return rng.normal(size=shape) if rng.random() < 0.7 else np.full(shape, math.nan)
    return bool(rng.integers(2))


# Mostly valid arguments with one part spoilt now and then, so that calls reach past the argument checks into the
# engine as well as being refused by them.
SPOIL = 0.08


def spoilt(rng):
    return rng.random() < SPOIL


def point(rng):
    return anything(rng) if spoilt(rng) else (float(rng.uniform(-1.3, 1.3)), float(rng.uniform(-0.65, 0.65)))


def balls(rng):
    if spoilt(rng):
        return anything(rng)
    return {f"b{k}": point(rng) for k in range(rng.integers(0, 4))}


STROKE_RANGES = {"phi": (-4.0, 4.0), "theta": (0.0, 1.2), "speed": (0.05, 6.0), "a": (-0.6, 0.6), "b": (-0.6, 0.6)}


def stroke(rng):
    kwargs = {name: number(rng) if spoilt(rng) else float(rng.uniform(*bounds))
              for name, bounds in STROKE_RANGES.items() if rng.random() < 0.9}
    return bsp.Stroke(**kwargs)


def stroke_row(rng):
    return [number(rng) if spoilt(rng) else float(rng.uniform(*bounds)) for bounds in STROKE_RANGES.values()]


def cheap():
    """A configuration whose calls end quickly, whatever the stroke."""
    config = bsp.Configuration()
    config.update({"solver/max_seconds": 0.5, "motion/max_time": 5.0})
    return config


def call(entry, rng, config):
    if entry == "strike":
        bsp.strike(anything(rng) if spoilt(rng) else stroke(rng), point(rng), balls(rng), configuration=config)
    elif entry == "predict_shot":
        bsp.predict_shot(stroke(rng), point(rng), balls(rng), configuration=config)
    elif entry == "cue":
        x, y = float(rng.uniform(-1.0, 1.0)), float(rng.uniform(-0.5, 0.5))
        tip = anything(rng) if spoilt(rng) else (x - 0.03, y + float(rng.normal(0.0, 0.02)), 0.0286)
        direction = anything(rng) if spoilt(rng) else (1.0, float(rng.normal(0.0, 0.1)), -float(rng.uniform(0, 1)))
        cue = bsp.Cue(tip, direction, number(rng) if spoilt(rng) else float(rng.uniform(0.1, 5.0)))
        bsp.predict_shot(cue, (x, y), balls(rng), configuration=config)
    elif entry == "simulate_many":
        rows = anything(rng) if spoilt(rng) else np.array([stroke_row(rng) for _ in range(rng.integers(0, 4))])
        bsp.simulate_many(rows, point(rng), balls(rng), configuration=config, threads=int(rng.integers(-1, 3)))
    elif entry == "plan_shot":
        bsp.plan_shot(point(rng), balls(rng), target=anything(rng) if spoilt(rng) else "",
                      pocket=int(rng.integers(-2, 8)) if spoilt(rng) else -1,
                      budget=float(rng.choice([-1.0, math.nan])) if spoilt(rng) else 0.05,
                      rollouts=int(rng.integers(-1, 3)) if spoilt(rng) else 8, configuration=config)
    elif entry == "configuration":
        c = bsp.Configuration()
        name = rng.choice(c.names() + list(c.choices()) + ["table/pockets", "no/such", ""])
        if rng.random() < 0.5:
            c[name] = anything(rng)
        else:
            c.update({name: anything(rng), rng.choice(c.names()): anything(rng)})
    elif entry == "load":
        with tempfile.NamedTemporaryFile("w", suffix=".yaml") as file:
            file.write(rng.choice(["table: [", "table: {cloth: {friction: []}}", "{a: 1}", "- 1\n- 2", "cue_mass: .nan",
                                   "table: {pockets: [[1, 2, 3], {centre: [1], radius: 2}]}", "motion: 3", "", "~"]))
            file.flush()
            bsp.Configuration.load(file.name)
    elif entry == "converters":
        bsp.from_pooltool(number(rng), number(rng), number(rng), number(rng), number(rng))
        bsp.to_fastfiz(stroke(rng), ball_radius=number(rng))
    elif entry == "sample":
        shot = bsp.predict_shot(bsp.Stroke(speed=1.0), (-0.5, 0.0), configuration=config)
        path = shot.ball("cue")
        path.sample(number(rng))
        path.position_at(number(rng))
    elif entry == "multiple_impact":
        d = int(rng.integers(1, 5))
        mass = anything(rng) if spoilt(rng) else np.diag(rng.uniform(0.1, 3.0, d))
        velocity = anything(rng) if spoilt(rng) else rng.normal(size=d)
        contacts = []
        for k in range(int(rng.integers(0 if spoilt(rng) else 1, 4))):
            contact = {"normal": anything(rng) if spoilt(rng) else rng.normal(size=d),
                       "restitution": number(rng) if spoilt(rng) else float(rng.uniform(0, 1)),
                       "stiffness": number(rng) if spoilt(rng) else float(rng.uniform(0.1, 10))}
            if rng.random() < 0.5:
                contact["friction"] = number(rng) if spoilt(rng) else float(rng.uniform(0, 1))
                contact["tangent"] = anything(rng) if spoilt(rng) else rng.normal(size=(2, d))
            if rng.random() < 0.3:
                contact["normal_law"] = anything(rng) if spoilt(rng) else {"type": "elastic_plastic",
                                                                            "yield_speed": float(rng.uniform(0.1, 3))}
            contacts.append(contact)
        bsp.multiple_impact(mass, velocity, contacts if not spoilt(rng) else anything(rng), max_seconds=0.5)
    elif entry == "fit_tracks":
        times = np.sort(rng.uniform(0.0, 1.0, int(rng.integers(2, 8))))
        track = np.column_stack([times, rng.uniform(-1, 1, times.size), rng.uniform(-0.5, 0.5, times.size)])
        if spoilt(rng):
            track[rng.integers(track.shape[0]), rng.integers(3)] = number(rng)
        if spoilt(rng):
            track = anything(rng) if rng.random() < 0.5 else track[:, :2]
        shot = {"stroke": stroke(rng), "cue_ball": point(rng), "tracks": {"cue": track}}
        if spoilt(rng):
            shot[str(anything(rng))] = anything(rng)
        bsp.fit_tracks(anything(rng) if spoilt(rng) else [shot], ["motion/sliding_friction"], configuration=config,
                       position_sigma=number(rng) if spoilt(rng) else 0.01, max_seconds=0.2)


ENTRIES = ["strike", "predict_shot", "cue", "simulate_many", "plan_shot", "configuration", "load", "converters",
           "sample", "fit_tracks", "multiple_impact"]


def main(seed, rounds):
    rng = np.random.default_rng(seed)
    config = cheap()
    outcomes = {entry: [0, 0] for entry in ENTRIES}
    for _ in range(rounds):
        for entry in ENTRIES:
            try:
                call(entry, rng, config)
                outcomes[entry][0] += 1
            except (bsp.Error, TypeError):
                outcomes[entry][1] += 1
    for entry, (returned, refused) in outcomes.items():
        print(f"{entry}: {returned} returned, {refused} refused")


if __name__ == "__main__":
    main(int(sys.argv[1]), int(sys.argv[2]))
