#!/usr/bin/env bash
# Quick start, first command: set up, build (Release) and run the main job on the project's
# own synthetic example tracks. Output goes to out/.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/setup.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DTRAILRAY_TESTS=OFF >/dev/null
cmake --build build --target trailray trailray_python

mkdir -p out
build/src/app/trailray stats examples/paraglider_flight.igc examples/hike.gpx | tee out/example-stats.txt
build/src/app/trailray stats --json examples/paraglider_flight.igc examples/hike.gpx > out/example-stats.json

# Height above ground along the flight, from the swisstopo DEM in the shared data (the default
# online source needs the network, which this machine may not have).
dem=../shared/data/dem/interlaken_dhm25_wgs84.tif
if [ -f "$dem" ]; then
  echo
  build/src/app/trailray elevation --terrain "$dem" examples/paraglider_flight.igc | tee out/example-elevation.txt
  build/src/app/trailray elevation --terrain "$dem" --csv examples/paraglider_flight.igc > out/example-elevation.csv
  # The flight on the terrain, framed automatically, lit by the sun of its day at noon, coloured
  # by vertical speed (sink blue, climb red) with a curtain down to the ground.
  build/src/app/trailray render --terrain "$dem" --imagery none --size 1280x720 --color-by vspeed --curtain \
    -o out/example-render.png examples/paraglider_flight.igc
else
  echo "($dem absent: skipping the elevation example)"
fi
# The same from Python (src/python/): `import trailray` with build/python on the path.
echo
PYTHONPATH=build/python /usr/bin/python3 - <<'PY'
import trailray
track = trailray.read("examples/paraglider_flight.igc").tracks[0]
km = track.stats()["clean"]["distance_2d_m"] / 1000
print(f"python: {track.name}: {len(track)} points, {km:.3f} km, xcontest score {trailray.score(track)['score']}")
PY
echo
echo "Output: out/example-stats.txt (table), out/example-stats.json (JSON), out/example-elevation.txt and .csv,"
echo "out/example-render.png (picture);"
echo "binary: build/src/app/trailray; Python: export PYTHONPATH=$PWD/build/python, then /usr/bin/python3 -c 'import trailray'"
