#!/usr/bin/env python3
"""Turns Google Benchmark's JSON (median aggregates) and the service round-trip line into bench/results.md.

Usage: make_results.py RESULTS.json ROUNDTRIP.txt OUTPUT.md
"""
import json
import platform
import sys

DESCRIPTIONS = {
    "BM_Table1": ("Table 1 ball–ball–table, this package", "relative tolerance 1e-{}"),
    "BM_ElasticChain10": ("10-ball elastic chain, this package", "relative tolerance 1e-{}"),
    "BM_MasseStrike": ("massé cue strike (§9.2), this package", "relative tolerance 1e-{}"),
    "BM_Table1PaperMethod": ("Table 1, the paper's fixed-step impulse method", "impulse step 1e-{}"),
    "BM_TrajectoryThreeCushions": ("trajectory with 3 cushion hits, this package", "default"),
}


def main():
    results, roundtrip, output = sys.argv[1:4]
    try:
        data = json.load(open(results))
    except (OSError, ValueError):
        data = {"benchmarks": []}  # e.g. a run filtered to no benchmark
    rows = []
    for b in data["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        base, _, arg = b["run_name"].partition("/")
        what, setting = DESCRIPTIONS.get(base, (base, "{}"))
        error = b.get("velocity_error")
        rows.append(f"| {what} | {setting.format(arg)} | {b['real_time']:.1f} µs | "
                    f"{'' if error is None else f'{error:.2g}'} |")
    context = data.get("context", {})
    lines = [
        "# Benchmark results",
        "",
        f"Machine: {context.get('num_cpus', '?')} CPUs at {context.get('mhz_per_cpu', '?')} MHz, "
        f"{platform.platform()}; {context.get('date', '')}. Median of 10 repetitions (Google Benchmark).",
        "",
        "| problem | setting | time per solve | velocity error |",
        "|---|---|---|---|",
        *rows,
        "",
        "Velocity error: for this package, the largest difference of the final velocities from a solve with 100× "
        "tighter tolerance; for the paper's method, from the converged values of ../shared/spec/paper_errata.md.",
        "",
        open(roundtrip).read().strip(),
        "",
    ]
    open(output, "w").write("\n".join(lines))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
