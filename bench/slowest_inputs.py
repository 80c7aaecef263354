#!/usr/bin/env python3
"""The slowest accepted input of each impact_solve problem in a set of JSON inputs (a fuzzing corpus, say).

Runs every file through impact_solve (from the repository's root, as the fuzzer does, so that seeds naming
config/table_9ft.yaml resolve), times it, and prints, per problem, how many inputs were accepted (exit 0), refused
(exit 2) or failed (exit 1, a typed error such as a work limit), with the median and the slowest accepted ones.
Times are wall-clock and include starting the process; the line "process start" gives that floor.

    bench/slowest_inputs.py IMPACT_SOLVE DIR_OR_FILE... [--top N] [--timeout S] [--problems a,b,...]
"""
import argparse
import json
import pathlib
import statistics
import subprocess
import sys
import time

REPO_ROOT = pathlib.Path(__file__).resolve().parent.parent


def inputs(paths):
    for path in map(pathlib.Path, paths):
        if path.is_dir():
            yield from sorted(p for p in path.iterdir() if p.is_file())
        else:
            yield path


def problem_of(data):
    try:
        problem = json.loads(data).get("problem")
    except (ValueError, AttributeError, UnicodeDecodeError, RecursionError):
        return None
    return problem if isinstance(problem, str) else None


def timed_run(binary, data, timeout):
    # coreutils' timeout bounds the run: subprocess's own timeout polls with growing sleeps and would round the times.
    start = time.perf_counter()
    rc = subprocess.run(["timeout", str(timeout), binary], input=data, stdout=subprocess.DEVNULL,
                        stderr=subprocess.DEVNULL, cwd=REPO_ROOT).returncode
    return ("timeout" if rc == 124 else rc), time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("impact_solve")
    parser.add_argument("paths", nargs="+")
    parser.add_argument("--top", type=int, default=3, help="slowest accepted inputs listed per problem")
    parser.add_argument("--problems", default="", help="comma-separated problem names to keep (default: every name)")
    parser.add_argument("--timeout", type=float, default=60.0, help="s per input")
    args = parser.parse_args()

    floor = min(timed_run(args.impact_solve, b'{"problem": "none"}', args.timeout)[1] for _ in range(5))
    print(f"process start (a refused input): {floor * 1e3:.1f} ms")
    by_problem = {}
    known = set(args.problems.split(",")) if args.problems else None
    for path in inputs(args.paths):
        data = path.read_bytes()
        problem = problem_of(data)
        if problem is None or (known and problem not in known):
            continue  # not JSON naming a problem (or not one asked for): refused before any solve
        rc, seconds = timed_run(args.impact_solve, data, args.timeout)
        by_problem.setdefault(problem, []).append((rc, seconds, path.name))

    print("| problem | accepted | refused (2) | failed (1) | other | accepted p50 | slowest accepted | slowest failed |")
    print("|---|---|---|---|---|---|---|---|")
    slowest = []
    for problem, runs in sorted(by_problem.items()):
        accepted = sorted((r for r in runs if r[0] == 0), key=lambda r: r[1])
        count = {code: sum(1 for r in runs if r[0] == code) for code in (0, 1, 2)}
        other = len(runs) - sum(count.values())
        p50 = f"{statistics.median(r[1] for r in accepted) * 1e3:.0f} ms" if accepted else "-"
        top = f"{accepted[-1][1]:.3f} s" if accepted else "-"
        failed = max((r[1] for r in runs if r[0] == 1), default=None)
        worst_failed = f"{failed:.3f} s" if failed is not None else "-"
        print(f"| {problem} | {count[0]} | {count[2]} | {count[1]} | {other} | {p50} | {top} | {worst_failed} |")
        slowest += [(problem,) + r for r in accepted[-args.top:]]
    print("\nSlowest accepted inputs:")
    for problem, _, seconds, name in sorted(slowest, key=lambda r: -r[2]):
        print(f"  {seconds:7.3f} s  {problem:16s} {name}")
    odd = [(p,) + r for p, runs in by_problem.items() for r in runs if r[0] not in (0, 1, 2)]
    for problem, rc, seconds, name in odd:
        print(f"  exit {rc} after {seconds:.1f} s: {problem} {name}", file=sys.stderr)
    return 1 if odd else 0


if __name__ == "__main__":
    sys.exit(main())
