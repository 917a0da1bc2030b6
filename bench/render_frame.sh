#!/usr/bin/env bash
# Benchmark: the renderer's frame, pass by pass (issue 4, "Speed"): `trailray render --profile
# --frames 20 --size 1280x720` over the shared Interlaken DEM (swisstopo DHM25), every effect
# on, the tint instead of imagery (no network). Prints the frame profiler's table: CPU and GPU
# mean and median milliseconds per pass over the 20 frames rendered after the tiles are loaded.
# Builds nothing; always exits 0.
#
#   bench/render_frame.sh [TRAILRAY_BINARY] [FRAMES] [SIZE]
#
# TRAILRAY_BINARY defaults to build/src/app/trailray (relative to the repository root), FRAMES
# to 20, SIZE to 1280x720. With --verbose's first lines the GL renderer is named (llvmpipe or a
# GPU): quote it with the figures. The view is the README's picture, with a low evening sun so
# the shadow maps have long shadows to draw.

set -u
cd "$(dirname "$0")/.." || exit 0
ROOT=$(pwd)

TRAILRAY=${1:-build/src/app/trailray}
case $TRAILRAY in /*) ;; *) TRAILRAY="$ROOT/$TRAILRAY" ;; esac
FRAMES=${2:-20}
SIZE=${3:-1280x720}
DEM="$ROOT/../shared/data/dem/interlaken_dhm25_wgs84.tif"

if [ ! -x "$TRAILRAY" ]; then
  echo "bench: $TRAILRAY not found; build the trailray target first. Skipping."
  exit 0
fi
if [ ! -f "$DEM" ]; then
  echo "bench: $DEM not found (../shared/data absent). Skipping."
  exit 0
fi

WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
# A private config and cache: the user's configured sources must not change the figures.
XDG_CONFIG_HOME="$WORK/config" XDG_CACHE_HOME="$WORK/cache" TRAILRAY_CONFIG= \
  "$TRAILRAY" render --terrain "$DEM" --imagery none \
  --look-at 46.705,7.872,900 --distance 10500 --heading 18 --pitch -22 --time 2024-06-18T17:30:00Z \
  --size "$SIZE" --profile --frames "$FRAMES" --verbose -o "$WORK/frame.png" 2>"$WORK/log.txt"
status=$?
grep -E "GL renderer|GL version" "$WORK/log.txt"
echo "view: Interlaken DEM, $SIZE, $FRAMES frames after loading, every effect on"
awk '/^frame profile/ { on = 1 } /^trailray:/ { on = 0 } on' "$WORK/log.txt"
[ "$status" -eq 0 ] || { echo "bench: trailray render exited $status:"; cat "$WORK/log.txt"; }
exit 0
