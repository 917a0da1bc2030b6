#!/usr/bin/env bash
# Benchmark: `trailray stats --json` against gpsbabel, ogr2ogr and gpxpy on one big GPX file
# (generated here, >=100,000 points, Garmin Connect layout). Builds nothing; prints figures
# and always exits 0.
#
#   bench/stats_speed.sh [TRAILRAY_BINARY] [RUNS]
#
# TRAILRAY_BINARY defaults to build/src/app/trailray (relative to the repository root), RUNS
# to 5 (gpxpy gets at most 3: it is slow). Environment: BENCH_POINTS (default 120000),
# BENCH_KEEP=1 keeps the temporary directory.
#
# Peak RSS comes from one run under /usr/bin/time -f %M; wall times from hyperfine (Debian
# package, installed by scripts/setup.sh) over RUNS runs after a warm-up. The table shows the
# median wall time and the peak RSS. Targets: trailray >=10x faster
# than gpsbabel, >=40x faster than gpxpy, trailray's peak memory < 3x the file size.

set -u
cd "$(dirname "$0")/.." || exit 0
ROOT=$(pwd)

TRAILRAY=${1:-build/src/app/trailray}
case $TRAILRAY in /*) ;; *) TRAILRAY="$ROOT/$TRAILRAY" ;; esac
RUNS=${2:-5}
GPXPY_RUNS=$(( RUNS < 3 ? RUNS : 3 ))
POINTS=${BENCH_POINTS:-120000}
PY=/usr/bin/python3
TIME=/usr/bin/time

if [ ! -x "$TIME" ]; then
  echo "bench: $TIME not found (Debian package 'time'); cannot measure. Skipping."
  exit 0
fi

TMP=$(mktemp -d "${TMPDIR:-/tmp}/trailray-bench.XXXXXX") || { echo "bench: mktemp failed"; exit 0; }
if [ "${BENCH_KEEP:-0}" = 1 ]; then
  echo "bench: keeping $TMP"
else
  trap 'rm -rf "$TMP"' EXIT
fi

FILE="$TMP/big.gpx"
echo "bench: generating $POINTS points into $FILE ..."
if ! "$PY" "$ROOT/bench/make_big_gpx.py" "$FILE" --points "$POINTS"; then
  echo "bench: generating the GPX file failed; nothing measured."
  exit 0
fi
SIZE=$(stat -c %s "$FILE")
echo "bench: $(printf "%'d" "$SIZE" 2>/dev/null || echo "$SIZE") bytes, $POINTS points"
echo "bench: host $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
echo

have() { command -v "$1" >/dev/null 2>&1; }

RESULTS="$TMP/results.txt"   # lines: tool status wall_s peak_kib
: > "$RESULTS"

# run_tool NAME RUNS CMD...: one run under /usr/bin/time for the peak RSS (KiB) and the output,
# then the timed runs: through hyperfine when present (no shell, one warm-up run: nothing but
# the command is timed), else from the clock around each /usr/bin/time call (which then counts
# the fork of /usr/bin/time and date, a few ms, against every tool alike).
run_tool() {
  local name=$1 runs=$2
  shift 2
  rm -rf "$TMP/ogr_out.csv"
  if ! "$TIME" -f '%e %M' -o "$TMP/time.txt" "$@" >"$TMP/$name.out" 2>"$TMP/$name.err"; then
    echo "$name failed 0 0" >> "$RESULTS"
    echo "bench: $name failed: $*"
    sed 's/^/  | /' "$TMP/$name.err" | head -n 8
    tail -n 3 "$TMP/time.txt" | sed 's/^/  | /'
    return
  fi
  local kib
  kib=$(tail -n1 "$TMP/time.txt" | cut -d' ' -f2)
  if have hyperfine; then
    hyperfine -N --style none --warmup 1 --runs "$runs" --prepare "rm -f $TMP/ogr_out.csv" \
      --export-json "$TMP/$name.json" -- "$*" >/dev/null 2>"$TMP/$name.hf.err" || {
      echo "bench: hyperfine failed for $name"; sed 's/^/  | /' "$TMP/$name.hf.err" | head -n 5; return; }
    "$PY" -c 'import json,sys; [print(sys.argv[2], "ok", "%.5f" % t, sys.argv[3]) for t in json.load(open(sys.argv[1]))["results"][0]["times"]]' \
      "$TMP/$name.json" "$name" "$kib" >> "$RESULTS"
    return
  fi
  local i
  for ((i = 1; i <= runs; i++)); do
    rm -rf "$TMP/ogr_out.csv"
    local t0 t1
    t0=$(date +%s%N)
    "$TIME" -f '%e %M' -o "$TMP/time.txt" "$@" >/dev/null 2>&1
    t1=$(date +%s%N)
    echo "$name ok $(awk -v a="$t0" -v b="$t1" 'BEGIN {printf "%.4f", (b - a) / 1e9}') $kib" >> "$RESULTS"
  done
}


if [ -x "$TRAILRAY" ]; then
  echo "bench: trailray   ($TRAILRAY) x$RUNS"
  run_tool trailray "$RUNS" "$TRAILRAY" stats --json "$FILE"
else
  echo "bench: trailray binary $TRAILRAY not found; build it first (ninja -C build trailray)"
  echo "trailray missing 0 0" >> "$RESULTS"
fi

if have gpsbabel; then
  echo "bench: gpsbabel   x$RUNS"
  run_tool gpsbabel "$RUNS" gpsbabel -i gpx -f "$FILE" -o unicsv -F /dev/null
else
  echo "gpsbabel missing 0 0" >> "$RESULTS"
fi

if have ogr2ogr; then
  # The GPX driver's track_points layer has one feature per <trkpt>: every point is read.
  echo "bench: ogr2ogr    x$RUNS"
  run_tool ogr2ogr "$RUNS" ogr2ogr -f CSV "$TMP/ogr_out.csv" "$FILE" track_points
else
  echo "ogr2ogr missing 0 0" >> "$RESULTS"
fi

if "$PY" -c 'import gpxpy' 2>/dev/null; then
  echo "bench: gpxpy      x$GPXPY_RUNS"
  run_tool gpxpy "$GPXPY_RUNS" "$PY" "$ROOT/bench/gpxpy_stats.py" "$FILE"
else
  echo "gpxpy missing 0 0" >> "$RESULTS"
fi
echo

if [ -s "$TMP/trailray.out" ]; then
  # The figures trailray reported, beside gpxpy's (falls back to raw output if the schema moves).
  "$PY" - "$TMP/trailray.out" <<'PYJSON' 2>/dev/null || { echo "trailray (first 300 bytes):"; head -c 300 "$TMP/trailray.out"; echo; }
import json, sys
doc = json.load(open(sys.argv[1]))
for f in doc["files"]:
    for t in f["tracks"]:
        r = t["raw"]
        print("trailray: points %d length_2d %.1f m duration %.0f s (raw)"
              % (r["points"], r["distance_2d_m"], r["duration_s"]))
PYJSON
fi
if [ -s "$TMP/gpxpy.out" ]; then
  echo "gpxpy: $(head -n1 "$TMP/gpxpy.out")"
  echo
fi

"$PY" - "$RESULTS" "$SIZE" "$POINTS" <<'EOF' || echo "bench: summary failed"
import statistics
import sys

results, size, points = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
runs = {}
status = {}
for line in open(results):
    name, st, wall, kib = line.split()
    status[name] = st if status.get(name, "ok") == "ok" else status[name]
    if st == "ok":
        runs.setdefault(name, []).append((float(wall), int(kib)))

order = ["trailray", "gpsbabel", "ogr2ogr", "gpxpy"]
med = {}
peak = {}
print("%-10s %5s %12s %12s %14s" % ("tool", "runs", "median s", "peak MiB", "points/s"))
for name in order:
    if status.get(name, "missing") != "ok" or name not in runs:
        print("%-10s %5s %12s %12s %14s" % (name, "-", status.get(name, "missing"), "-", "-"))
        continue
    r = runs[name]
    med[name] = statistics.median(w for w, _ in r)
    peak[name] = max(k for _, k in r) / 1024.0
    pps = points / med[name] if med[name] > 0 else float("inf")
    print("%-10s %5d %12.4f %12.1f %14s" % (name, len(r), med[name], peak[name], "{:,.0f}".format(pps)))
print()
print("file: %.1f MiB, %d points" % (size / 1048576.0, points))


def ratio(peer):
    if "trailray" not in med or peer not in med:
        return None
    return med[peer] / max(med["trailray"], 1e-6)


def verdict(ok):
    return "met" if ok else "NOT met"


lines = []
for peer, target in (("gpsbabel", 10.0), ("ogr2ogr", None), ("gpxpy", 40.0)):
    r = ratio(peer)
    label = "%s/trailray" % peer
    if r is None:
        lines.append("%-24s %10s" % (label, "n/a"))
    elif target is None:
        lines.append("%-24s %9.1fx   (no target)" % (label, r))
    else:
        lines.append("%-24s %9.1fx   target >= %gx: %s" % (label, r, target, verdict(r >= target)))
if "trailray" in peak:
    m = peak["trailray"] * 1048576.0 / size
    lines.append("%-24s %9.2fx   target < 3x: %s" % ("trailray peak RSS/file", m, verdict(m < 3.0)))
else:
    lines.append("%-24s %10s" % ("trailray peak RSS/file", "n/a"))
print("\n".join(lines))
EOF
exit 0
