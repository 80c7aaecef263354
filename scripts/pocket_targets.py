#!/usr/bin/env python3
"""Effective target sizes of the 9-ft table's pockets under `table.pocket_model: jaws`.

What it measures: a lone ball, struck with natural-roll follow (b = 0.4) so that it rolls, is sent along parallel
lines at an approach angle theta to a pocket, theta measured from the pocket's centreline (the corner's 45-degree
bisector, the side pocket's normal to the rail). The effective target is the width, perpendicular to the lines, of
the set of lines whose ball drops in that pocket; its offset is the middle of that set measured from the line through
the middle of the mouth, positive towards the far jaw (the jaw the ball runs towards). The lateral offset is scanned in
steps (--step) and every edge is bisected to --tol. Each line starts 0.5 m before the mouth (or 0.15 m before the rail
when that start would be behind a rail; lines that cannot start on the cloth count as misses, as the source bounds its
rail-first lines by the table) and its stroke is scaled so that the ball reaches the mouth at 0.4 m/s (slow) or 1.7 m/s
(fast). The set need not be one interval (rail-first rebounds, rattles), so all intervals are kept. Per sweep it also
counts scan lines by mechanism: potted clean, off a jaw point, rail first, after 2+ facings, and misses that stopped
within a ball's diameter of the mouth ("hung").

Compared with: David G. Alciatore ("Dr. Dave"), The Illustrated Principles of Pool and Billiards, technical proofs
  TP 3.5 "Effective target sizes for slow shots into a side pocket at different angles",
         https://billiards.colostate.edu/technical_proofs/TP_3-5.pdf
  TP 3.6 "Effective target sizes for slow shots into a corner pocket at different angles",
         https://billiards.colostate.edu/technical_proofs/TP_3-6.pdf
His proofs give equations and plots, not tables: ALCIATORE below are his equations evaluated at those angles (his
pockets: side mouth 5.0625 in, walls 14 deg, hole radius 3 in, shelf 0.1875 in; corner mouth 4.5875 in, walls 7 deg,
hole radius 2.75 in, shelf 1.125 in, 8-ft table; ball radius 1.125 in; mirror reflections, slow shots).

Usage: pocket_targets.py IMPACT_SOLVE [--out PNG] [--csv CSV] [--step MM] [--tol MM] [--jobs N]
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

INCH = 0.0254
LENGTH, WIDTH = 2.54, 1.27
RADIUS = 0.028575
RUN_UP = 0.5  # m rolled to the mouth
RAIL_RUN_UP = 0.15  # m rolled before a rail-first line's rail
ARRIVAL = {"slow": 0.4, "fast": 1.7}  # m/s at the mouth: each line's stroke is scaled for it
GROW, MAX_OFFSET = 0.03, 0.4  # m: how the scan of the lateral offset grows beyond the mouth, and its limit
ANGLES = {"corner": [0, 5, 10, 15, 20, 25, 30, 35, 40, 44], "side": list(range(0, 66, 5))}

# Alciatore's effective target s (in) and offset (s_right - s_left)/2 (in), his equations evaluated (slow shots).
ALCIATORE = {
    "side": {0: (3.23, 0.0), 5: (3.21, 0.03), 10: (3.16, 0.06), 15: (3.08, 0.09), 20: (2.96, 0.12), 25: (2.81, 0.15),
             30: (2.63, 0.18), 35: (2.42, 0.21), 40: (2.18, 0.24), 45: (1.92, 0.27), 50: (1.57, 0.27),
             55: (1.12, 0.23), 60: (0.69, 0.20), 65: (0.27, 0.19)},
    "corner": {0: (2.67, 0.0), 5: (2.65, 0.03), 10: (2.61, 0.05), 15: (2.53, 0.08), 20: (2.42, 0.11),
               25: (2.29, 0.13), 28.17: (2.19, 0.15), 30: (2.32, 0.06), 35: (2.68, -0.18), 40: (2.94, -0.39),
               44: (2.95, -0.47)},
}


def pocket_places():
    """The two pockets measured: id, middle of the mouth, centreline heading into the pocket."""
    half = 4.5625 * INCH / (2 * math.sqrt(2))  # the corner's jaw points stand mouth/sqrt(2) from the corner
    return {
        "corner": {"id": "bottom_left", "mouth_middle": (-LENGTH / 2 + half, -WIDTH / 2 + half), "axis_deg": 225.0},
        "side": {"id": "bottom_side", "mouth_middle": (0.0, -WIDTH / 2), "axis_deg": 270.0},
    }


def clear(point):
    """Whether a ball centred at `point` stands on the cloth clear of the rails' noses."""
    return abs(point[0]) <= LENGTH / 2 - RADIUS - 0.0005 and abs(point[1]) <= WIDTH / 2 - RADIUS - 0.0005


def line_start(place, theta, offset):
    """Heading (deg), start and length to the mouth of the line at `offset` (m, towards the far jaw) from the mouth's
    middle. The start is RUN_UP before the line crosses the mouth (the line through the jaw points) or, when that is
    behind a rail (a rail-first line), RAIL_RUN_UP before the centre comes within a radius of the rail's nose line;
    None when neither is clear on the cloth."""
    phi = place["axis_deg"] - theta
    u = (math.cos(math.radians(phi)), math.sin(math.radians(phi)))
    far = (u[1], -u[0])
    axis = (math.cos(math.radians(place["axis_deg"])), math.sin(math.radians(place["axis_deg"])))
    mx, my = place["mouth_middle"]
    px, py = mx + offset * far[0], my + offset * far[1]
    at = lambda t: (px + t * u[0], py + t * u[1])  # noqa: E731
    mouth = -offset * (far[0] * axis[0] + far[1] * axis[1]) / (u[0] * axis[0] + u[1] * axis[1])
    start = mouth - RUN_UP
    if not clear(at(start)):
        rails = [(-WIDTH / 2 + RADIUS - py) / u[1]] + ([(-LENGTH / 2 + RADIUS - px) / u[0]] if u[0] < 0 else [])
        start = min(rails) - RAIL_RUN_UP
    if not clear(at(start)):
        return phi, None, None
    return phi, at(start), mouth - start


def request(phi, start, cue_speed):
    """A table_shot of a lone cue ball (fields from docs/cli.md's example) on the jaws table."""
    return {"problem": "table_shot", "cue_mass": 0.54, "ball_mass": 0.17, "ball_radius": RADIUS,
            "cue_contact": {"restitution": 0.75, "friction": 0.7, "eta2": 1.2},
            "table_contact": {"restitution": 0.5, "friction": 0.2, "eta2": 10}, "stiffness_ratio": 0.8,
            "table": {"pocket_model": "jaws"},
            "cue": {"phi_deg": phi, "speed": cue_speed, "a": 0.0, "b": 0.4},
            "balls": [{"id": "cue", "position": list(start)}]}


def summarise(answer, place, start):
    """Whether the ball dropped in the target pocket, the cushions it met, its speed when it first met a jaw or dropped,
    how far it rolled before it stopped sliding, and whether it stopped in the jaws (within a diameter of the mouth)."""
    ball = answer["balls"][0]
    events = ball["events"]
    contacts = [e["cushion"] for e in events if e["type"] == "cushion_hit"]
    first = next((e for e in events if e["type"] == "pocketed"
                  or e["type"] == "cushion_hit" and not e["cushion"].startswith("rail")), None)
    roll = next((e for e in events if e["type"] == "slide_to_roll"), None)
    hung = ball["outcome"] == "rest" and math.dist(ball["final_position"][:2], place["mouth_middle"]) < 2 * RADIUS
    return {"pot": ball["outcome"] == "pocketed" and ball["pocket"] == place["id"],
            "outcome": "hung" if hung else ball["outcome"], "contacts": contacts,
            "arrival": math.hypot(*first["v"][:2]) if first else None,
            "roll_after": math.dist(roll["position"][:2], start) if roll else None}


def run(solver, phi, start, cue_speed):
    done = subprocess.run([solver], input=json.dumps(request(phi, start, cue_speed)), capture_output=True, text=True)
    if done.returncode != 0:
        return None, f"error {done.returncode}: {done.stderr.strip()[:80]}"
    return json.loads(done.stdout), None


def calibrate(solver):
    """Ball speed per cue speed and the rolling deceleration, from a straight roll into the side pocket."""
    answer, error = run(solver, 270.0, (0.0, -0.1), 1.0)
    if error:
        sys.exit(f"impact_solve failed: {error}")
    events = answer["balls"][0]["events"]
    rolling = next(e for e in events if e["type"] == "slide_to_roll")
    dropped = next(e for e in events if e["type"] == "pocketed")
    v1, v2 = math.hypot(*rolling["v"][:2]), math.hypot(*dropped["v"][:2])
    distance = math.dist(rolling["position"][:2], dropped["position"][:2])
    return {"solver": solver, "ratio": math.hypot(*events[0]["v"][:2]), "decel": (v1**2 - v2**2) / (2 * distance)}


def shoot(setup, pocket, theta, offset, arrival):
    """One line: the stroke that brings the rolling ball to the mouth at `arrival` m/s, and what became of it."""
    place = pocket_places()[pocket]
    phi, start, length = line_start(place, theta, offset)
    if start is None:
        return {"pot": False, "outcome": "no_start", "contacts": [], "arrival": None, "roll_after": None}
    cue_speed = math.sqrt(arrival**2 + 2 * setup["decel"] * length) / setup["ratio"]
    answer, error = run(setup["solver"], phi, start, cue_speed)
    if error:
        return {"pot": False, "outcome": error, "contacts": [], "arrival": None, "roll_after": None}
    return summarise(answer, place, start)


def edge(setup, pocket, theta, arrival, inside, outside, tol):
    """Bisect between a potting offset and a missing one down to tol; the edge's offset."""
    while abs(outside - inside) > tol:
        middle = 0.5 * (inside + outside)
        if shoot(setup, pocket, theta, middle, arrival)["pot"]:
            inside = middle
        else:
            outside = middle
    return 0.5 * (inside + outside)


def scan(pool, setup, pocket, theta, arrival, offsets):
    return list(pool.map(lambda o: shoot(setup, pocket, theta, o, arrival), offsets))


def sweep(pool, setup, pocket, theta, arrival, step, tol):
    """The potting intervals (m) at one angle and speed, and the per-line results of the scan. The scan covers the
    mouth and two balls either side, and grows outwards by GROW while its outer GROW still pots (rail-first lines)."""
    mouth = (4.5625 if pocket == "corner" else 5.0625) * INCH
    count = int(round((mouth / 2 + 2 * RADIUS + 0.012) / step))
    offsets = [k * step for k in range(-count, count + 1)]
    results = scan(pool, setup, pocket, theta, arrival, offsets)
    chunk = int(round(GROW / step))
    while any(r["pot"] for r in results[:chunk]) and offsets[0] > -MAX_OFFSET:
        more = [offsets[0] - k * step for k in range(chunk, 0, -1)]
        offsets, results = more + offsets, scan(pool, setup, pocket, theta, arrival, more) + results
    while any(r["pot"] for r in results[-chunk:]) and offsets[-1] < MAX_OFFSET:
        more = [offsets[-1] + k * step for k in range(1, chunk + 1)]
        offsets, results = offsets + more, results + scan(pool, setup, pocket, theta, arrival, more)
    pots = [r["pot"] for r in results]
    flips = [k for k in range(len(pots) - 1) if pots[k] != pots[k + 1]]
    jobs = [pool.submit(edge, setup, pocket, theta, arrival, offsets[k + (not pots[k])], offsets[k + pots[k]], tol)
            for k in flips]
    edges = [offsets[0]] * pots[0] + [job.result() for job in jobs] + [offsets[-1]] * pots[-1]
    return list(zip(edges[0::2], edges[1::2])), list(zip(offsets, results))


def mechanisms(lines):
    """How the potting lines of a scan got in: counts of clean drops, jaw points, rail-first, rattles (2+ facings)."""
    pots = [r for _, r in lines if r["pot"]]
    return {"clean": sum(not r["contacts"] for r in pots),
            "point": sum(any(c.endswith(".point") for c in r["contacts"]) for r in pots),
            "rail_first": sum(bool(r["contacts"]) and r["contacts"][0].startswith("rail") for r in pots),
            "rattle": sum(sum(c.endswith(".facing") for c in r["contacts"]) >= 2 for r in pots),
            "hung": sum(r["outcome"] == "hung" for _, r in lines),
            "odd": sum(r["outcome"] in ("no_start",) or r["outcome"].startswith("error") for _, r in lines)}


def measure(solver, step, tol, jobs):
    """Every pocket, speed and angle: one row each."""
    setup = calibrate(solver)
    print(f"ball speed {setup['ratio']:.4f} x cue speed; rolling deceleration {setup['decel']:.4f} m/s^2", flush=True)
    rows = []
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        for pocket, angles in ANGLES.items():
            for label, arrival in ARRIVAL.items():
                for theta in angles:
                    intervals, lines = sweep(pool, setup, pocket, theta, arrival, step, tol)
                    rows.append(row(pocket, label, theta, intervals, lines))
                    print(format_row(rows[-1]), flush=True)
    return rows


def row(pocket, label, theta, intervals, lines):
    width = sum(b - a for a, b in intervals)
    arrivals = sorted(r["arrival"] for _, r in lines if r["pot"] and r["arrival"])
    rolls = [r["roll_after"] for _, r in lines if r["roll_after"] is not None]
    paper = ALCIATORE[pocket].get(theta)
    return {"pocket": pocket, "speed": label, "theta_deg": theta, "width_in": width / INCH,
            "offset_in": (intervals[0][0] + intervals[-1][1]) / 2 / INCH if intervals else float("nan"),
            "intervals_mm": " ".join(f"[{a * 1e3:.1f},{b * 1e3:.1f}]" for a, b in intervals),
            "arrival_mps": arrivals[len(arrivals) // 2] if arrivals else float("nan"),
            "max_slide_m": max(rolls) if rolls else float("nan"),
            "alciatore_in": paper[0] if paper else float("nan"),
            "alciatore_offset_in": paper[1] if paper else float("nan"), **mechanisms(lines)}


def format_row(r):
    return (f"{r['pocket']:6s} {r['speed']:4s} {r['theta_deg']:5.1f} deg  s = {r['width_in']:.2f} in "
            f"(Alciatore {r['alciatore_in']:.2f})  offset {r['offset_in']:+.2f} in  arrives {r['arrival_mps']:.2f} m/s"
            f"  {r['intervals_mm']}  clean {r['clean']} point {r['point']} rail-first {r['rail_first']} "
            f"rattle {r['rattle']} hung {r['hung']} odd {r['odd']}")


def plot(rows, path):
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5), sharex="col", gridspec_kw={"height_ratios": [2, 1]})
    for col, pocket in enumerate(ANGLES):
        paper = sorted(ALCIATORE[pocket].items())
        panels = [("width_in", "effective target s (in)"), ("offset_in", "target offset (in)")]
        for k, (key, ylabel) in enumerate(panels):
            ax = axes[k][col]
            for label, style in (("slow", "o-"), ("fast", "s--")):
                mine = [r for r in rows if r["pocket"] == pocket and r["speed"] == label]
                ax.plot([r["theta_deg"] for r in mine], [r[key] for r in mine], style, ms=4,
                        label=f"jaws model, {label} ({ARRIVAL[label]} m/s at the mouth)")
            ax.plot([a for a, _ in paper], [v[k] for _, v in paper], "k*", ms=9,
                    label=f"Alciatore TP {'3.6' if pocket == 'corner' else '3.5'} (slow)")
            ax.set_ylabel(ylabel)
            ax.grid(alpha=0.3)
        axes[0][col].set_title(f"{pocket} pocket ({'bottom_left' if pocket == 'corner' else 'bottom_side'})")
        axes[0][col].set_ylim(bottom=0)
        axes[0][col].legend(fontsize=8, loc="lower left")
        axes[1][col].set_xlabel("approach angle from the pocket's centreline (deg)")
    fig.suptitle("Effective pocket targets, 9-ft table, WPA jaws, rolling ball (offset + towards the far jaw)")
    fig.tight_layout()
    fig.savefig(path, dpi=130)


def write_csv(rows, path):
    with open(path, "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


def main():
    repo = Path(__file__).resolve().parent.parent
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("impact_solve", help="path of the impact_solve binary")
    parser.add_argument("--out", default=str(repo / "docs/figures/pocket_effective_targets.png"))
    parser.add_argument("--csv", help="also write the table as CSV")
    parser.add_argument("--step", type=float, default=0.5, help="scan step of the lateral offset, mm")
    parser.add_argument("--tol", type=float, default=0.1, help="bisection tolerance of each edge, mm")
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    args = parser.parse_args()
    began = time.time()
    rows = measure(args.impact_solve, args.step * 1e-3, args.tol * 1e-3, args.jobs)
    plot(rows, args.out)
    if args.csv:
        write_csv(rows, args.csv)
    print(f"{len(rows)} sweeps in {time.time() - began:.0f} s; figure {args.out}")


if __name__ == "__main__":
    main()
