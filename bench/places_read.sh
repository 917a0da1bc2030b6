#!/usr/bin/env bash
# Benchmark: reading the places of a ~100 MB OpenStreetMap extract (--places), trailray against
# `osmium tags-filter` on the same file. Builds nothing; prints figures and always exits 0.
#
#   bench/places_read.sh [TRAILRAY_BINARY] [RUNS]
#
# The file is made here, in a temporary folder (never in the repository): BENCH_COPIES (default
# 34) copies of ../shared/data/osm/nominatim_apidb-test-data.pbf, each with its ids moved past the
# others' and shifted 0.5 degree east (bench/make_big_osm.py), written as one sorted .osm.pbf of
# about 95 MB (13 million nodes), renumbered. BENCH_OSM=FILE uses a file of your own instead; BENCH_KEEP=1 keeps the folder.
#
#   trailray  `trailray stats --places FILE TRACK`: the whole file read (no area filter: the
#             worst case), its summits and huts kept, a one-point track measured against them
#   osmium    `osmium tags-filter FILE` with the same tags (nodes: natural=peak,volcano,saddle,
#             mountain_pass=yes, tourism=alpine_hut,wilderness_hut, place=city,town,village,hamlet;
#             natural=water ways and relations, with the nodes they use), written as .osm.pbf
# Each runs RUNS times (default 5) after one warm-up, interleaved; the median wall time and
# the peak RSS (/usr/bin/time -f %M) of each are printed.

set -u
cd "$(dirname "$0")/.." || exit 0
ROOT=$(pwd)
TRAILRAY=${1:-build/src/app/trailray}
case $TRAILRAY in /*) ;; *) TRAILRAY="$ROOT/$TRAILRAY" ;; esac
RUNS=${2:-5}
TIME=/usr/bin/time
SOURCE="$ROOT/../shared/data/osm/nominatim_apidb-test-data.pbf"

for tool in osmium python3 "$TIME"; do
  command -v "$tool" >/dev/null 2>&1 || { echo "bench: $tool not found (scripts/setup.sh); nothing measured."; exit 0; }
done
TMP=$(mktemp -d "${TMPDIR:-/tmp}/trailray-places-bench.XXXXXX") || exit 0
if [ "${BENCH_KEEP:-0}" = 1 ]; then echo "bench: keeping $TMP"; else trap 'rm -rf "$TMP"' EXIT; fi

FILE=${BENCH_OSM:-$TMP/big.osm.pbf}
if [ -z "${BENCH_OSM:-}" ]; then
  [ -f "$SOURCE" ] || { echo "bench: $SOURCE absent; nothing measured."; exit 0; }
  echo "bench: writing ${BENCH_COPIES:-34} shifted copies of $(basename "$SOURCE") into $FILE ..."
  python3 "$ROOT/bench/make_big_osm.py" "$SOURCE" "$FILE" --copies "${BENCH_COPIES:-34}" || { echo "bench: generating failed"; exit 0; }
fi
echo "bench: $(stat -c %s "$FILE") bytes; $(osmium fileinfo -e -g data.count.nodes "$FILE") nodes," \
     "$(osmium fileinfo -e -g data.count.ways "$FILE") ways, $(osmium fileinfo -e -g data.count.relations "$FILE") relations"
echo "bench: host $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
TRACK="$TMP/one.gpx"
echo '<gpx version="1.1"><trk><trkseg><trkpt lat="47.06" lon="9.6"><ele>2500</ele></trkpt></trkseg></trk></gpx>' > "$TRACK"

trailray_cmd=("$TRAILRAY" stats --places "$FILE" "$TRACK")
osmium_cmd=(osmium tags-filter "$FILE" n/natural=peak,volcano,saddle n/mountain_pass=yes
            n/tourism=alpine_hut,wilderness_hut n/place=city,town,village,hamlet wr/natural=water
            -o "$TMP/filtered.osm.pbf" --overwrite)

declare -A times peaks
for name in trailray osmium; do times[$name]=""; peaks[$name]=0; done
run() {  # run NAME CMD...: one timed run, its wall seconds and peak KiB appended
  local name=$1; shift
  local start end kib
  start=$(date +%s.%N)
  "$TIME" -f %M -o "$TMP/rss" "$@" >/dev/null 2>"$TMP/err" || { echo "bench: $name failed: $(tail -2 "$TMP/err")"; return; }
  end=$(date +%s.%N)
  kib=$(tail -1 "$TMP/rss")
  times[$name]+="$(echo "$end - $start" | bc -l) "
  [ "$kib" -gt "${peaks[$name]}" ] && peaks[$name]=$kib
}
"${trailray_cmd[@]}" >/dev/null 2>&1; "${osmium_cmd[@]}" >/dev/null 2>&1  # warm-up: the file in the page cache
for ((i = 0; i < RUNS; ++i)); do
  run trailray "${trailray_cmd[@]}"
  run osmium "${osmium_cmd[@]}"
done
median() { tr ' ' '\n' | grep -v '^$' | sort -g | awk '{a[NR]=$1} END {if (NR) print (NR % 2 ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2)}'; }
printf '\n%-10s %12s %14s\n' tool "median s" "peak RSS MiB"
for name in trailray osmium; do
  printf '%-10s %12.2f %14.1f\n' "$name" "$(echo "${times[$name]}" | median)" "$(echo "${peaks[$name]} / 1024" | bc -l)"
done
exit 0
