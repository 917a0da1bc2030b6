#!/usr/bin/env bash
# The GPU bundle (scripts/gpu-bundle.sh) as a bare machine would run it: at most 60 MiB; every
# library its files need is in the bundle or glibc's; run with an empty environment, every
# library of the bundle's is loaded from the bundle (none from this machine's build packages),
# and it renders a picture and runs the track benchmark (here on Mesa's EGL, the driver the
# machine provides; on a GPU machine the driver's).
#   gpu_bundle_test.sh PROGRAM SOURCE_DIR
set -euo pipefail
program=$1
source_dir=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/trailray-gpu-bundle-XXXXXX")
trap 'rm -rf "$work"' EXIT
bundle=$work/bundle
fail() { echo "FAIL: $*" >&2; exit 1; }

GPU_BUNDLE_PROGRAM=$program "$source_dir/scripts/gpu-bundle.sh" "$bundle"
[ "$(du -sb "$bundle" | cut -f1)" -le $((60 * 1024 * 1024)) ] || fail "over 60 MiB"

glibc='^(libc|libm|libdl|libpthread|librt|libresolv|libutil|ld-linux-x86-64)\.so'
for elf in "$bundle/bin/trailray-gpu" "$bundle"/lib/*; do
  for needed in $(readelf -d "$elf" | awk '/NEEDED/ {gsub(/[][]/, "", $5); print $5}'); do
    [[ $needed =~ $glibc ]] && continue
    [ -f "$bundle/lib/$needed" ] || fail "$(basename "$elf") needs $needed, which the bundle lacks"
  done
done

# An empty environment: nothing of the build's on any path.
log=$work/loaded.txt
env -i PATH=/usr/bin:/bin LD_DEBUG=libs "$bundle/trailray" render --terrain none --imagery none --size 320x200 \
  --color '#ff00ff' -o "$work/frame.png" "$bundle/data/paraglider_flight.igc" 2>"$log" ||
  { tail -20 "$log" >&2; fail "render failed"; }
[ -s "$work/frame.png" ] || fail "no picture"
for lib in "$bundle"/lib/*; do
  soname=$(basename "$lib")
  # Every library the bundle carries that was loaded came from the bundle.
  if grep -q "calling init: .*/$soname\$" "$log"; then
    grep -q "calling init: $bundle/lib/$soname\$" "$log" || fail "$soname loaded from elsewhere: $(grep "calling init: .*/$soname\$" "$log")"
  fi
done
grep -q "calling init: $bundle/lib/libEGL.so.1" "$log" || fail "EGL not loaded from the bundle"

env -i PATH=/usr/bin:/bin "$bundle/trailray" bench tracks --data none --points 2000 --frames 1 --size 320x200 \
  >"$work/bench.txt" 2>&1 || { cat "$work/bench.txt" >&2; fail "bench failed"; }
grep -q "capsule" "$work/bench.txt" || { cat "$work/bench.txt" >&2; fail "bench printed no capsule figure"; }
# The bundle reads no GDAL raster: it says so and names the program that does.
if env -i PATH=/usr/bin:/bin "$bundle/trailray" render --terrain "$bundle/data/paraglider_flight.igc" --imagery none \
  -o "$work/x.png" "$bundle/data/paraglider_flight.igc" 2>"$work/raster.txt"; then fail "a raster source was accepted"; fi
grep -q "tile folders and .mbtiles" "$work/raster.txt" || { cat "$work/raster.txt" >&2; fail "no clear error for a raster"; }
echo "gpu bundle: $(du -sh "$bundle" | cut -f1), $(ls "$bundle/lib" | wc -l) libraries, renders and benchmarks with an empty environment"
