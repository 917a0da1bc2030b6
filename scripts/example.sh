#!/usr/bin/env bash
# Quick start, first command: set up, build (Release) and run the main job on the project's
# own synthetic example tracks. Output goes to out/.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/setup.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DTRAILRAY_TESTS=OFF >/dev/null
cmake --build build --target trailray

mkdir -p out
build/src/app/trailray stats examples/paraglider_flight.igc examples/hike.gpx | tee out/example-stats.txt
build/src/app/trailray stats --json examples/paraglider_flight.igc examples/hike.gpx > out/example-stats.json
echo
echo "Output: out/example-stats.txt (table) and out/example-stats.json (JSON); binary: build/src/app/trailray"
