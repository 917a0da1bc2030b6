#!/usr/bin/env python3
"""Times `trailray score` against igc-xc-score (npm, pinned in bench/xcscore) on the flights of
../shared/data/igc/scoring/EXPECTED.tsv, one row per test case (rules and options as there), and
checks that both give the same score. Prints a table, the medians and the speed ratios.

  bench/score_bench.py TRAILRAY [RUNS]

Both are timed around their solver only (launch/landing detection and optimisation; not the
IGC parse, not the process start): trailray's `solve_seconds` from --json, igc-xc-score's
solver() call inside node. Each the median of RUNS runs, alternating. The whole trailray process
(reading the file, starting the binary) is shown too.
"""
import csv
import json
import os
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "..", "shared", "data", "igc", "scoring")


def ours(binary, row, path, runs):
    args = [binary, "score", "--json", "--rules", row["rules"]]
    if row["options"] == "hp=true":
        args += ["--distance", "geodesic"]
    if row["options"] == "trim=false":
        args += ["--no-trim"]
    t0 = time.perf_counter()
    out = subprocess.run(args + [path], capture_output=True, text=True, check=True).stdout
    wall = time.perf_counter() - t0
    doc = json.loads(out)
    return doc["solve_seconds"], wall, doc


def reference(row, path):
    args = ["node", os.path.join(HERE, "xcscore", "score.mjs"), row["rules"]]
    if row["options"] == "hp=true":
        args.append("hp")
    if row["options"] == "trim=false":
        args.append("notrim")
    out = subprocess.run(args + [path], capture_output=True, text=True, check=True).stdout
    return json.loads(out.strip().splitlines()[-1])


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 0
    binary, runs = sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 3
    tsv = os.path.join(DATA, "EXPECTED.tsv")
    if not os.path.exists(tsv):
        print(f"score bench: {tsv} absent. Skipping.")
        return 0
    if not os.path.isdir(os.path.join(HERE, "xcscore", "node_modules")):
        subprocess.run(["npm", "ci", "--silent"], cwd=os.path.join(HERE, "xcscore"), check=True)
    print(f"cores {os.cpu_count()}, load {os.getloadavg()[0]:.2f}; trailray {binary}, {runs} runs each")
    print(f"{'flight':<34} {'rules':<9} {'opt':<10} {'fixes':>6} {'trailray':>9} {'xc-score':>9} {'ratio':>7} {'process':>8}  score (ours / ref)")
    ratios, ours_t, ref_t, equal = [], [], [], 0
    rows = list(csv.DictReader(open(tsv), delimiter="\t"))
    for row in rows:
        path = os.path.normpath(os.path.join(DATA, row["path"]))
        ts, walls, refs = [], [], []
        for _ in range(runs):
            t, wall, doc = ours(binary, row, path, runs)
            ref = reference(row, path)
            ts.append(t)
            walls.append(wall)
            refs.append(ref["seconds"])
        t, wall = statistics.median(ts), statistics.median(walls)
        ref["seconds"] = statistics.median(refs)
        same = abs(doc["score"] - ref["score"]) < 1e-9 and doc["type"] == ref["type"]
        equal += same
        ratio = ref["seconds"] / t
        ratios.append(ratio)
        ours_t.append(t)
        ref_t.append(ref["seconds"])
        name = os.path.basename(path).replace("xcscore_", "")[:34]
        print(f"{name:<34} {row['rules']:<9} {row['options']:<10} {doc['landing']['fix'] - doc['launch']['fix'] + 1:>6} "
              f"{t:>8.4f}s {ref['seconds']:>8.3f}s {ratio:>6.1f}x {wall:>7.3f}s  {doc['score']} / {ref['score']}"
              f"{'' if same else '  DIFFERENT (' + doc['type'] + ' / ' + ref['type'] + ')'}")
    print(f"median: trailray {statistics.median(ours_t):.3f}s, igc-xc-score {statistics.median(ref_t):.3f}s, "
          f"median ratio {statistics.median(ratios):.1f}x, smallest ratio {min(ratios):.1f}x (target >= 10x)")
    print(f"equal scores: {equal} of {len(rows)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
