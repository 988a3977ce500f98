#!/usr/bin/env python3
"""Compares two builds of kutlog-bench row by row, for a change meant to cost no speed.

One run of each on this shared machine drifts by up to 20 % between runs minutes apart, more
than the few percent a refactor may cost, so the two binaries run alternately, `--rounds` times
each, with the page's flags (medians of 5 repetitions, random interleaving). A row's time is
the median over the rounds of its per-run medians; the ratio is before / after (above 1: the
new build is faster). Prints the rows the two builds share, slowest first.

  python3 scripts/bench-ab.py BEFORE/bench/kutlog-bench build/bench/kutlog-bench \\
      --rounds 3 --filter '<the README's page filter>'
"""
import argparse
import json
import statistics
import subprocess
import sys
import tempfile


def run(binary, bench_filter, out):
    subprocess.run([binary, f"--benchmark_filter={bench_filter}", "--benchmark_repetitions=5",
                    "--benchmark_report_aggregates_only=true",
                    "--benchmark_enable_random_interleaving=true", "--benchmark_min_time=0.05",
                    f"--benchmark_out={out}", "--benchmark_out_format=json"],
                   check=True, stdout=subprocess.DEVNULL)
    with open(out) as file:
        return {row["run_name"]: row["real_time"] for row in json.load(file)["benchmarks"]
                if row.get("aggregate_name") == "median"}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--filter", default=".")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--slower", type=float, default=0.97,
                        help="flag rows whose ratio is below this (default: 3 %% slower)")
    args = parser.parse_args()
    runs = {"before": [], "after": []}
    with tempfile.TemporaryDirectory() as scratch:
        for round_index in range(args.rounds):
            for side in ("before", "after"):
                binary = getattr(args, side)
                runs[side].append(run(binary, args.filter, f"{scratch}/{side}{round_index}.json"))
                print(f"round {round_index + 1}: {side} done", file=sys.stderr)
    shared = set.intersection(*(set(rows) for side in runs.values() for rows in side))
    ratios = sorted((statistics.median(r[name] for r in runs["before"]) /
                     statistics.median(r[name] for r in runs["after"]), name) for name in shared)
    flagged = [name for ratio, name in ratios if ratio < args.slower]
    print(f"{len(shared)} rows; median ratio {statistics.median(r for r, _ in ratios):.3f}; "
          f"{len(flagged)} below {args.slower}")
    print("| before / after | row |\n|---:|---|")
    for ratio, name in ratios:
        print(f"| {ratio:.3f} | {name} |")
    return 1 if flagged else 0


if __name__ == "__main__":
    sys.exit(main())
