#!/usr/bin/env python3
"""Validation figures from the package's own output (impact_solve), beside the paper's printed values.

Usage: make_figures.py IMPACT_SOLVE OUTPUT_DIR
"""
import json
import math
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

M2 = 2 / math.sqrt(3)


def solve(program, problem):
    out = subprocess.run([program], input=json.dumps(problem), capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def ball_ball_table(program, m2, e1, e2):
    return solve(program, {"problem": "ball_ball_table", "m2": m2, "stiffness_ratio": 1, "e1": e1, "e2": e2,
                           "solver": {"record_samples": True}})


def finish_axes(ax, xlabel, ylabel, title, legend=None):
    """Labels, title, grid, and a legend of the given font size (none if legend is None)."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    if legend is not None:
        ax.legend(**legend)
    ax.grid(alpha=0.3)


def save(fig, out, name):
    fig.tight_layout()
    fig.savefig(f"{out}/{name}", dpi=110)
    plt.close(fig)
    return name


def xy(samples):
    """The planar path of a trajectory's samples."""
    return [s["position"][0] for s in samples], [s["position"][1] for s in samples]


def impulse_curve(ax, result, m2, title, printed=None):
    i1 = [s["impulses"][0] for s in result["samples"]]
    i2 = [s["impulses"][1] for s in result["samples"]]
    ax.plot(i1, i2, color="tab:blue", label="impulse curve (this package)")
    # Bounding ellipse (42): ½I1² + (I1−I2)²/(2m2) − I1 = 0, solved for I2.
    xs = [2 * k / 400 for k in range(401)]
    upper, lower = [], []
    for x in xs:
        r = 2 * m2 * (x - 0.5 * x * x)
        r = math.sqrt(max(r, 0.0))
        upper.append(x + r)
        lower.append(x - r)
    ax.plot(xs, upper, "k--", lw=0.8, label="bounding ellipse (42)")
    ax.plot(xs, lower, "k--", lw=0.8)
    # Compression lines: l1 (v1 = v2): I2 = (1 + m2) I1 − m2; l2 (v2 = 0): I2 = I1.
    ax.plot(xs, [(1 + m2) * x - m2 for x in xs], color="tab:green", lw=0.8, label="l1: end of ball–ball compression")
    ax.plot(xs, xs, color="tab:orange", lw=0.8, label="l2: end of ball–table compression")
    markers = {"end_of_compression": "o", "restart_of_compression": "s", "separation": "x", "reactivation": "^"}
    for e in result["events"]:
        ax.plot(e["impulses"][0], e["impulses"][1], markers.get(e["type"], "."), color="tab:red", ms=6)
    for k, s in enumerate(result["state_starts"]):
        ax.annotate(s["state"], (s["impulses"][0], s["impulses"][1]), textcoords="offset points", xytext=(5, -12),
                    fontsize=8)
    if printed:
        ax.plot(*printed, "*", color="purple", ms=10, label="paper's printed end point")
    ax.plot([], [], "o", color="tab:red", label="end of compression")
    ax.plot([], [], "s", color="tab:red", label="restart of compression")
    ax.plot([], [], "x", color="tab:red", label="separation")
    ax.plot([], [], "^", color="tab:red", label="reactivation")
    ax.set_xlim(-0.05, 2.1)
    ax.set_ylim(-0.3, 2.9)
    finish_axes(ax, "I1 (ball–ball)", "I2 (ball–table)", title + "  states " + " ".join(result["states"]),
                legend={"fontsize": 7, "loc": "upper left"})


def figure_impulse_curves(program, out):
    cases = [("fig1_table1_impulse_curve.png", M2, 0.9, 0.7, "Fig. 1 / Table 1: e1 = 0.9, e2 = 0.7", (1.61377, 1.85565)),
             ("fig7_elastic_impulse_curve.png", M2, 1.0, 1.0, "Fig. 7: elastic", (1.94484, 2.29559)),
             ("fig9_restart_impulse_curve.png", 0.5, 0.9, 0.7, "Fig. 9: m2 = 0.5, restarts of compression", None)]
    names = []
    for name, m2, e1, e2, title, printed in cases:
        fig, ax = plt.subplots(figsize=(7, 6))
        impulse_curve(ax, ball_ball_table(program, m2, e1, e2), m2, title, printed)
        names.append(save(fig, out, name))
    return names


def figure_8(program, out):
    r = ball_ball_table(program, M2, 0.9, 0.7)
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 5))
    a.plot([s["velocities"][0] for s in r["samples"]], [s["velocities"][1] for s in r["samples"]])
    a.plot(0.61377, 0.20947, "*", color="purple", ms=10, label="paper's printed final velocities")
    a.plot(r["v1"], r["v2"], "o", color="tab:red", label="this package")
    finish_axes(a, "v1 (upper ball)", "v2 (lower ball)", "Fig. 8(a): velocities along the collision",
                legend={"fontsize": 8})
    b.plot([s["strain_energies"][0] for s in r["samples"]], [s["strain_energies"][1] for s in r["samples"]], ".",
           ms=2)
    finish_axes(b, "E1 (ball–ball spring)", "E2 (ball–table spring)",
                "Fig. 8(b): strain energies (jumps at ends of compression)")
    return [save(fig, out, "fig8_velocities_energies.png")]


MASSE = {"problem": "shot", "ball_position": [0.0, 0.0], "cue_mass": 0.5018,
         "cue_direction": [-0.2761, -0.1388, -0.9511], "cue_speed": 3.089095, "ball_mass": 0.17,
         "ball_radius": 0.0286, "hit_normal": [0.480151, -0.102889, 0.871131],
         "cue_contact": {"restitution": 0.656532, "friction": 0.7, "eta2": 7},
         "table_contact": {"restitution": 0.51625, "friction": 0.152479, "eta2": 10}, "stiffness_ratio": 0.8,
         "planar": True, "table": {"length": 40, "width": 40, "pockets": []}, "sample_spacing": 0.02}


def planar_path(program, v, w):
    r = solve(program, {"problem": "ball_motion", "position": [0, 0], "v": v, "omega": w, "ball_radius": 0.0286,
                        "planar": True, "table": {"length": 40, "width": 40, "pockets": []}, "sample_spacing": 0.02})
    return xy(r["samples"])


def figure_masse(program, out):
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 5.5))
    shot = solve(program, MASSE)["trajectory"]
    a.plot(*xy(shot["samples"]), label="this package (literal cue direction)")
    a.plot(*planar_path(program, [-1.67629, -0.075349, 0.637937], [40.3064, 83.6145, -15.4927]), "--",
           label="from the paper's prediction (57)")
    a.plot(*planar_path(program, [-1.67063, -0.274431, 0], [28.4584, 79.1561, 0]), ":",
           label="from the measurement (56)")
    finish_axes(a, "x (m)", "y (m)", "Massé shot of §9.2: planar paths from (0, 0)", legend={"fontsize": 8})
    for eta2 in range(2, 8):
        problem = dict(MASSE)
        problem["cue_contact"] = dict(MASSE["cue_contact"], eta2=eta2)
        t = solve(program, problem)["trajectory"]
        b.plot(*xy(t["samples"]), label=f"η² (cue–ball) = {eta2}")
    finish_axes(b, "x (m)", "y (m)", "Fig. 16(d): paths for η² from 2 to 7", legend={"fontsize": 8})
    return [save(fig, out, "masse_paths.png")]


# The planar states (v, ω) right after the strike of docs/validation.md's massé fits, as masse_fit prints them.
MASSE_STATES = [
    ("the measurement (56)", [-1.67063, -0.274431, 0], [28.4584, 79.1561, 0], ":"),
    ("the paper's prediction (57)", [-1.67629, -0.075349, 0.637937], [40.3064, 83.6145, -15.4927], "--"),
    ("fit 1: η² of both contacts", [-1.4532, 0.0790, 0], [25.186, 87.304, 0], "-"),
    ("fit 1 with all four constants", [-1.5728, 0.0671, 0], [26.904, 81.961, 0], "-"),
    ("fit 3: η² and the cue's direction", [-1.5257, 0.0617, 0], [22.780, 85.804, 0], "-"),
]
FIT_TIME = 1.5  # s after the strike, where the fits' paths are compared with (56)'s


def figure_masse_fit(program, out):
    fig, a = plt.subplots(figsize=(8, 5.5))
    for label, v, w, style in MASSE_STATES:
        r = solve(program, {"problem": "ball_motion", "position": [0, 0], "v": v, "omega": w, "ball_radius": 0.0286,
                            "planar": True, "table": {"length": 40, "width": 40, "pockets": []},
                            "sample_spacing": 0.02})
        line, = a.plot(*xy(r["samples"]), style, label=f"from {label}")
        at = min(r["samples"], key=lambda s: abs(s["t"] - FIT_TIME))
        a.plot(at["position"][0], at["position"][1], "o", color=line.get_color(), ms=5)
    finish_axes(a, "x (m)", "y (m)", f"Massé shot of §9.2 fitted to its measurement (dots: {FIT_TIME} s)",
                legend={"fontsize": 8})
    a.set_aspect("equal")
    return [save(fig, out, "masse_fit_paths.png")]


SNOOKER_TABLE = "config/tables/snooker_mathavan.yaml"
SNOOKER_BALL = {"ball_radius": 0.02625, "ball_mass": 0.1406}
CUSHION_DATA = "test/data/measurements/cushion_rebound_mathavan2010.csv"


def measured_rebounds(root):
    rows = [line.split(",") for line in open(f"{root}/{CUSHION_DATA}") if line[0].isdigit()]
    return [(float(v_in), float(v_out)) for v_in, v_out in rows]


def rebound(program, root, v_in, cushion=None):
    """v_out of a ball rolling straight into the snooker table's +x cushion at v_in (the file's cushion, or `cushion`
    over it), from impact_solve's ball_motion: the ball starts 0.1 mm from the cushion's nose."""
    radius = SNOOKER_BALL["ball_radius"]
    rise = 0.4  # the nose 7R/5 above the cloth: (h − R)/R
    start = 3.569 / 2 - radius * math.sqrt(1 - rise * rise) - 1e-4
    problem = {"problem": "ball_motion", "position": [start, 0], "v": [v_in, 0, 0], "omega": [0, v_in / radius, 0],
               "table_file": f"{root}/{SNOOKER_TABLE}", "max_time": 0.1, **SNOOKER_BALL}
    if cushion:
        problem["table"] = {"cushion": cushion}
    events = solve(program, problem)["events"]
    hit = next(e for e in events if e["type"] == "cushion_hit")
    return -hit["v"][0]


def ratio_rms(program, root, data, cushion=None):
    errors = [(rebound(program, root, v_in, cushion) - v_out) / v_in for v_in, v_out in data]
    return math.sqrt(sum(e * e for e in errors) / len(errors))


def best_constant_restitution(program, root, data):
    """The constant law's restitution with the least RMS error of v_out/v_in (golden-section search)."""
    def cost(e):
        return ratio_rms(program, root, data, {"restitution": e, "law": {"type": "constant"}})
    lo, hi = 0.6, 1.0
    g = (math.sqrt(5) - 1) / 2
    a, b = hi - g * (hi - lo), lo + g * (hi - lo)
    fa, fb = cost(a), cost(b)
    while hi - lo > 1e-4:
        if fa < fb:
            hi, b, fb = b, a, fa
            a = hi - g * (hi - lo)
            fa = cost(a)
        else:
            lo, a, fa = a, b, fb
            b = lo + g * (hi - lo)
            fb = cost(b)
    return (lo + hi) / 2


def figure_cushion(program, out, root):
    data = measured_rebounds(root)
    e_best = best_constant_restitution(program, root, data)
    linear = {"restitution": e_best, "law": {"type": "constant"}}
    speeds = [0.2 + 0.05 * k for k in range(66)]
    fig, a = plt.subplots(figsize=(7.5, 4.8))
    a.plot([v for v, _ in data], [w / v for v, w in data], "ko", ms=5,
           label="measured (Mathavan, Jackson & Parkin 2010, Fig. 7a)")
    rms = ratio_rms(program, root, data)
    a.plot(speeds, [rebound(program, root, v) / v for v in speeds], "-", color="tab:red",
           label=f"elastic–plastic law, the shipped snooker table (RMS {rms:.3f})")
    rms_linear = ratio_rms(program, root, data, linear)
    a.plot(speeds, [rebound(program, root, v, linear) / v for v in speeds], "--", color="tab:blue",
           label=f"best constant restitution, e = {e_best:.3f} (RMS {rms_linear:.3f})")
    finish_axes(a, "speed into the cushion (m/s)", "v_out / v_in",
                "A rolling ball into a snooker cushion: rebound against speed", legend={"fontsize": 8})
    a.set_ylim(0.6, 1.0)
    return [save(fig, out, "cushion_rebounds.png")]


def main():
    program, out = sys.argv[1], sys.argv[2]
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    names = (figure_impulse_curves(program, out) + figure_8(program, out) + figure_masse(program, out) +
             figure_masse_fit(program, out) + figure_cushion(program, out, root))
    for n in names:
        print(f"{out}/{n}")


if __name__ == "__main__":
    main()
