#!/usr/bin/env bash
# Benchmark: a command's whole process, start-up included, against gpsbabel on the same file
# (issue "lean and quick"): `trailray stats` of a small GPX (aim: at most 1.5x gpsbabel's time)
# and `trailray stats --json` of the largest GPX in ../shared/data (aim: at least 5x faster than
# gpsbabel), and `trailray --version` alone. Runs are interleaved (trailray, gpsbabel, trailray,
# ...) so that the machine's drift falls on both alike; medians are printed. Also counts the
# shared libraries the binary loads. Builds nothing; prints figures and always exits 0.
#
#   bench/startup_speed.sh [TRAILRAY_BINARY] [RUNS]     (defaults build/src/app/trailray, 31)
#
# Environment: STARTUP_SMALL_GPX, STARTUP_BIG_GPX pick other files.
set -u
cd "$(dirname "$0")/.." || exit 0
ROOT=$(pwd)
TRAILRAY=${1:-build/src/app/trailray}
case $TRAILRAY in /*) ;; *) TRAILRAY="$ROOT/$TRAILRAY" ;; esac
RUNS=${2:-31}
DATA="$ROOT/../shared/data"
# Small: a real 68-point Garmin Connect export when the shared data is there, else the example hike.
SMALL=${STARTUP_SMALL_GPX:-$DATA/gpx/gpsbabel_garminconnect.gpx}
[ -f "$SMALL" ] || SMALL=$ROOT/examples/hike.gpx
BIG=${STARTUP_BIG_GPX:-$(find "$DATA" -name '*.gpx' -printf '%s %p\n' 2>/dev/null | sort -rn | head -n1 | cut -d' ' -f2-)}

[ -x "$TRAILRAY" ] || { echo "bench: $TRAILRAY not found; build it first (ninja -C build trailray)"; exit 0; }
command -v gpsbabel >/dev/null || { echo "bench: gpsbabel not found (scripts/setup.sh installs it)"; exit 0; }
[ -n "$BIG" ] && [ -f "$BIG" ] || { echo "bench: no GPX under $DATA; measuring the small file only"; BIG=""; }

echo "bench: host $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "bench: $TRAILRAY loads $(ldd "$TRAILRAY" | grep -c '=>') shared libraries (ldd)"
/usr/bin/python3 - "$TRAILRAY" "$RUNS" "$SMALL" "$BIG" <<'PY'
import os, statistics, subprocess, sys, time
trailray, runs, small, big = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
null = open(os.devnull, "w")

def once(cmd):
    t = time.perf_counter()
    r = subprocess.run(cmd, stdout=null, stderr=subprocess.PIPE)
    dt = time.perf_counter() - t
    if r.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)}: exit {r.returncode}: {r.stderr.decode()[:300]}")
    return dt

def interleaved(cmds):
    for c in cmds.values(): once(c)  # warm-up: the files and libraries in the page cache
    times = {name: [] for name in cmds}
    for _ in range(runs):
        for name, c in cmds.items(): times[name].append(once(c))
    return {name: statistics.median(t) for name, t in times.items()}

def gpsbabel(path): return ["gpsbabel", "-i", "gpx", "-f", path, "-o", "unicsv", "-F", os.devnull]

cases = [("trailray --version", {"trailray": [trailray, "--version"]}, None),
         (f"stats {os.path.basename(small)} ({os.path.getsize(small)} bytes)",
          {"trailray": [trailray, "stats", small], "gpsbabel": gpsbabel(small)}, ("at most", 1.5))]
if big:
    cases.append((f"stats --json {os.path.basename(big)} ({os.path.getsize(big)} bytes)",
                  {"trailray": [trailray, "stats", "--json", big], "gpsbabel": gpsbabel(big)}, ("at least", 5.0)))
print(f"bench: medians of {runs} interleaved runs, whole processes")
print(f"{'case':72} {'trailray ms':>12} {'gpsbabel ms':>12}  ratio")
for title, cmds, aim in cases:
    try:
        m = interleaved(cmds)
    except RuntimeError as e:
        print(f"{title:72} failed: {e}")
        continue
    line = f"{title:72} {m['trailray'] * 1e3:12.1f}"
    if "gpsbabel" in m:
        ratio = m["trailray"] / m["gpsbabel"]
        line += f" {m['gpsbabel'] * 1e3:12.1f}  trailray/gpsbabel {ratio:.2f}"
        kind, target = aim
        if kind == "at most":
            line += f" (aim: at most {target}x: {'met' if ratio <= target else 'missed'})"
        else:
            line += f", speed-up {1 / ratio:.2f}x (aim: at least {target}x: {'met' if 1 / ratio >= target else 'missed'})"
    print(line)
PY
exit 0
