#!/usr/bin/env python3
"""Turns the Google Benchmark JSON files (median aggregates) and the service round-trip lines into bench/results.md.

Usage: make_results.py ENGINE.json SICONOS.json ROUNDTRIP.txt OUTPUT.md [INSTRUCTIONS.txt]

INSTRUCTIONS.txt (optional): lines "problem instructions-per-solve" from bench/instruction_counts.cpp.
"""
import json
import platform
import sys

DESCRIPTIONS = {
    "BM_Table1": ("Table 1 ball–ball–table (e 0.9/0.7), this package", "default (closed form)"),
    "BM_Table1Integrated": ("Table 1 ball–ball–table, this package", "numerical integration only, tolerance 1e-{}"),
    "BM_ElasticChain10": ("10-ball elastic chain, this package", "default (closed form)"),
    "BM_MasseStrike": ("massé cue strike (§9.2), this package", "relative tolerance 1e-{}"),
    "BM_Table1PaperMethod": ("Table 1, the paper's fixed-step impulse method", "impulse step 1e-{}"),
    "BM_MassePaperMethod": ("massé cue strike, the paper's fixed-step impulse method", "impulse step 1e-{} (× m·v)"),
    "BM_TrajectoryThreeCushions": ("trajectory with 3 cushion hits, this package", "default"),
    "BM_Landing": ("landing after the massé jump (sliding throughout), this package", "default (closed form)"),
    "BM_LandingIntegrated": ("landing after the massé jump, this package", "numerical integration only, tolerance 1e-{}"),
    "BM_CushionHit": ("sliding ball into a cushion on the cloth, this package", "relative tolerance 1e-{}"),
    "BM_CushionHitPlainTime": ("sliding ball into a cushion on the cloth, this package",
                               "integrator alone in plain time (no quasi-steady slip), tolerance 1e-{}"),
    "BM_MassePlainTime": ("massé cue strike (§9.2), this package",
                          "integrator alone in plain time (no separation clock), tolerance 1e-{}"),
    "BM_SiconosFigure7": ("Fig. 7 elastic ball–ball–table, Siconos", "impulse step 1e-{}"),
    "BM_PackageFigure7": ("Fig. 7 elastic ball–ball–table, this package", None),
    "BM_SiconosChain10": ("10-ball elastic chain, Siconos", "impulse step 1e-{}"),
    "BM_PackageChain10": ("10-ball elastic chain, this package", None),
}


def load(path):
    try:
        return json.load(open(path))
    except (OSError, ValueError):
        return {"benchmarks": []}  # e.g. a run filtered to no benchmark


def medians(data):
    for b in data["benchmarks"]:
        if b.get("aggregate_name") == "median":
            base, _, rest = b["run_name"].partition("/")
            yield base, rest.split("/")[0], b


def setting(base, arg):
    template = DESCRIPTIONS.get(base, (base, "{}"))[1]
    if template is None:  # BM_Package*: −1 is the default, else numerical integration at 1e-arg
        return "default (closed form)" if arg == "-1" else f"numerical integration only, tolerance 1e-{arg}"
    return template.format(arg)


def row(base, arg, b):
    error = b.get("velocity_error")
    what = DESCRIPTIONS.get(base, (base,))[0]
    return (f"| {what} | {setting(base, arg)} | {b['real_time']:.1f} µs | "
            f"{'' if error is None else f'{error:.2g}'} |")


def peer_comparison(siconos, package, problem):
    """Time ratio at equal or better accuracy: Siconos at its smallest step against the package's default."""
    peer = [(int(arg), b) for base, arg, b in siconos if base == f"BM_Siconos{problem}"]
    ours = [b for base, arg, b in package if base == f"BM_Package{problem}" and arg == "-1"]
    if not peer or not ours:
        return None
    _, finest = max(peer, key=lambda p: p[0])
    ours = ours[0]
    ratio = finest["real_time"] / ours["real_time"]
    # Siconos is first order (error ∝ step, time ∝ 1/step): the time it would need for the package's error.
    # Below 1e-14 an error is at the reference's own accuracy: no finer claim is made.
    needed = finest["real_time"] * finest["velocity_error"] / max(ours["velocity_error"], 1e-14)
    return (f"- {problem}: Siconos at its finest step takes {finest['real_time'] / 1e6:.3g} s for an error of "
            f"{finest['velocity_error']:.2g}; the package takes {ours['real_time']:.1f} µs for "
            f"{ours['velocity_error']:.2g}: **{ratio:,.0f}× faster while more accurate**. At the package's accuracy "
            f"(taken as no better than 1e-14, the reference's own) Siconos would need about {needed / 1e6:.2g} s "
            f"(first-order extrapolation, {needed / ours['real_time']:.2g}× the package's time).")


INSTRUCTION_PROBLEMS = {
    "table1": "Table 1 ball–ball–table, default",
    "chain10": "10-ball elastic chain, default",
    "landing": "landing after the massé jump, default",
    "masse": "massé cue strike, default (tolerance 1e-12)",
    "cushion": "sliding ball into a cushion on the cloth, default",
    "trajectory": "trajectory with 3 cushion hits, default",
    "prediction": "the service's massé shot (strike and trajectory, library side)",
}


def instruction_table(path):
    """The callgrind counts as a table; nothing when the file is missing or empty (valgrind not installed)."""
    try:
        counts = [line.split() for line in open(path) if line.strip()]
    except OSError:
        return []
    if not counts:
        return []
    return [
        "## Instructions per solve (callgrind)",
        "",
        "Counted around a loop of solves (bench/instruction_counts.cpp): unlike the times above, they do not move with "
        "the load of a shared host, so they compare runs of different days.",
        "",
        "| problem | instructions per solve |",
        "|---|---|",
        *(f"| {INSTRUCTION_PROBLEMS.get(name, name)} | {int(count):,} |" for name, count in counts),
        "",
    ]


def main():
    engine, peer, roundtrip, output = sys.argv[1:5]
    instructions = sys.argv[5] if len(sys.argv) > 5 else None
    engine_data, peer_data = load(engine), load(peer)
    engine_rows = list(medians(engine_data))
    peer_rows = list(medians(peer_data))
    siconos = [r for r in peer_rows if r[0].startswith("BM_Siconos")]
    package = [r for r in peer_rows if r[0].startswith("BM_Package")]
    context = engine_data.get("context") or peer_data.get("context", {})
    header = ["| problem | setting | time per solve | velocity error |", "|---|---|---|---|"]
    comparisons = [c for c in (peer_comparison(siconos, package, p) for p in ("Figure7", "Chain10")) if c]
    lines = [
        "# Benchmark results",
        "",
        f"Machine: {context.get('num_cpus', '?')} CPUs at {context.get('mhz_per_cpu', '?')} MHz, "
        f"{platform.platform()}; {context.get('date', '')}. Median of 10 repetitions (Google Benchmark; Siconos 3, "
        "one solve each).",
        "",
        "## This package and the paper's method",
        "",
        *header,
        *(row(*r) for r in engine_rows),
        "",
        "## Side by side with Siconos (Debian 4.4.0; MultipleImpact, BiStiffness law; both models coincide when every contact "
        "is elastic)",
        "",
        *header,
        *(row(*r) for r in siconos + package),
        "",
        *comparisons,
        "",
        "Velocity error: largest difference of the final velocities (m/s; rad/s for spins) from a converged solution, "
        "the package's numerical integration alone in plain time (no closed form, separation clock or quasi-steady "
        "slip) at tolerance 1e-14 (bench/bench_problems.hpp); for Table 1 with "
        "the paper's method, from the converged values of docs/validation.md (Table 1). Siconos is timed inside "
        "MultipleImpact::compute only.",
        "",
        open(roundtrip).read().strip(),
        "",
        *(instruction_table(instructions) if instructions else []),
    ]
    open(output, "w").write("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
