#!/usr/bin/env bash
# The GPU bundle: a self-contained folder that measures trailray on a machine with a GPU and
# nothing of ours (only glibc and the GPU driver's EGL: no Mesa, no Debian development packages).
# It holds trailray-gpu (`render` and `bench`, reading terrain from tile folders and MBTiles, so
# no GDAL or libcurl), every shared library it needs that glibc does not provide, the example
# flight, a launcher and run.sh. EGL (glvnd) picks the machine's driver, the NVIDIA one there.
#
#   scripts/gpu-bundle.sh [OUT]     (default out/gpu-bundle; at most 60 MiB, checked)
#   then, on the GPU machine:  OUT/run.sh      (frame times into OUT/results/)
#
# Environment: GPU_BUNDLE_PROGRAM=path/to/trailray-gpu bundles that program instead of building
# it (in build/, Release).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/gpu-bundle}
program=${GPU_BUNDLE_PROGRAM:-}
if [ -z "$program" ]; then
  [ -f build/CMakeCache.txt ] || scripts/setup.sh
  source scripts/compiler_cache.sh
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
  cmake --build build --target trailray-gpu
  program=build/src/app/trailray-gpu
fi
[ -x "$program" ] || { echo "gpu-bundle: $program is not a program" >&2; exit 1; }

rm -rf "$out"
mkdir -p "$out/bin" "$out/lib" "$out/data" "$out/results"
cp "$program" "$out/bin/trailray-gpu"
# glibc's libraries are the machine's own (they must match its kernel and its driver).
glibc='^(libc|libm|libdl|libpthread|librt|libresolv|libutil|ld-linux-x86-64)\.so'
ldd "$program" | awk '$2 == "=>" && $3 ~ /^\// {print $1, $3}' | while read -r soname path; do
  if [[ $soname =~ $glibc ]]; then continue; fi
  cp -L "$path" "$out/lib/$soname"
done
strip --strip-unneeded "$out/bin/trailray-gpu" "$out/lib/"*.so* 2>/dev/null || true
cp examples/paraglider_flight.igc "$out/data/"

cat > "$out/trailray" <<'SH'
#!/bin/sh
# trailray-gpu with the bundle's libraries first on the path (glibc and EGL's driver are the machine's).
here=$(cd "$(dirname "$0")" && pwd)
LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" exec "$here/bin/trailray-gpu" "$@"
SH
cat > "$out/run.sh" <<'SH'
#!/bin/sh
# The GPU's figures: the GL device, the track pass at 10k to 1M points (bench tracks), and the
# full frame at 1920x1080 with every effect (render --profile: shadows, SSAO, atmosphere, the
# flight's tubes and curtain over the neutral ground), each into results/ and on the screen.
set -e
here=$(cd "$(dirname "$0")" && pwd)
cd "$here"
stamp=$(date -u +%Y%m%dT%H%M%SZ)
./trailray bench tracks --data none --points 10000,100000,1000000 --frames 20 2>&1 | tee "results/bench-tracks-$stamp.txt"
./trailray render --verbose --profile --frames 20 --size 1920x1080 --terrain none --imagery none \
  --color-by vspeed --curtain -o "results/frame-$stamp.png" data/paraglider_flight.igc 2>&1 | tee "results/render-profile-$stamp.txt"
SH
chmod +x "$out/trailray" "$out/run.sh"

bytes=$(du -sb "$out" | cut -f1)
limit=$((60 * 1024 * 1024))
echo "gpu-bundle: $out: $(ls "$out/lib" | wc -l) libraries, $((bytes / 1024 / 1024)) MiB ($bytes bytes; at most $limit)"
[ "$bytes" -le "$limit" ] || { echo "gpu-bundle: over 60 MiB" >&2; exit 1; }
