#!/usr/bin/env bash
# Benchmark: the track pass (issue 5, "Speed"): `trailray bench tracks` draws seeded random walks
# of 10k, 100k and 1M points and the real tracks of ../shared/data at 1920x1080 with the
# ray-traced capsules, a screen-space ribbon and an 8-sided tube mesh, and prints per dataset
# the median pass times, their ratios and the GPU bytes per point, then the issue's targets at
# the largest walk (capsule <= 1.5x ribbon time, <= 0.7x tube time, <= 1/8 of the tube's memory).
# Builds the trailray target (Release) first; prints figures and always exits 0.
#
#   bench/track_bench.sh [BUILD_DIR] [-- BENCH OPTIONS...]
#
# BUILD_DIR defaults to build-release (configured here when it is not yet). Options after `--`
# go to `trailray bench tracks`, e.g. `-- --points 100000 --frames 5 --json` or `--data none`
# (no real tracks). Runs from the repository root, so --data's default ../shared/data is the
# shared folder beside it. JOBS (default 2) sets the build's parallelism. On llvmpipe the
# default run takes several minutes: the 1M-point tube alone is 16M triangles a frame.

set -u
cd "$(dirname "$0")/.." || exit 0

BUILD=build-release
if [ $# -gt 0 ] && [ "$1" != "--" ]; then BUILD=$1; shift; fi
[ $# -gt 0 ] && [ "$1" = "--" ] && shift

if [ ! -f "$BUILD/build.ninja" ]; then
  cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null ||
    { echo "bench: configuring $BUILD failed. Skipping."; exit 0; }
fi
cmake --build "$BUILD" --target trailray -j"${JOBS:-2}" >/dev/null ||
  { echo "bench: building trailray in $BUILD failed (run cmake --build $BUILD --target trailray). Skipping."; exit 0; }

echo "machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
"$BUILD/src/app/trailray" bench tracks "$@"
status=$?
[ "$status" -eq 0 ] || echo "bench: trailray bench tracks exited $status"
exit 0
