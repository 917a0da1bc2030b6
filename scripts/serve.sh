#!/usr/bin/env bash
# The browser in one command: set up, build trailray and its web app (Release, no tests), then
# run `trailray serve` with the arguments given (tracks, --terrain, --color-by ...) from the
# folder you are in, so relative paths work. Open the address it prints.
#   scripts/serve.sh --terrain none --color '#ff00ff' examples/hike.gpx
#   scripts/serve.sh --terrain dem.tif flights/*.igc
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
(
  cd "$root"
  scripts/setup.sh
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build --target trailray
  TRAILRAY_WEB_TESTS=OFF scripts/web.sh
)
exec "$root/build/src/app/trailray" serve "$@"
