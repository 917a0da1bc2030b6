#!/usr/bin/env bash
# Fuzzes the track readers and the tile decoders with libFuzzer (clang, ASan + UBSan).
#
#   scripts/fuzz.sh [SECONDS_PER_TARGET]      (default 60; 0 = regression inputs only)
#
# 1. configures build-sanitize if needed (scripts/sanitizer_tree.sh: the clang tree that also
#    runs the test suite under the sanitizers) and builds the fuzz targets in it -> fuzz_gpx,
#    fuzz_igc, fuzz_tcx, fuzz_fit, fuzz_kml (KML and KMZ), fuzz_geojson, fuzz_airspace,
#    fuzz_task (XCTrack tasks, XCSoar tasks, IGC C records), fuzz_heatmap (heatmap descriptions, counts tiles), fuzz_tile,
#    fuzz_quantized_mesh (Cesium terrain tiles),
#    fuzz_terrain_text (config, URL templates, Cache-Control, disk cache entries)
#    fuzz_track_text (--range / --occlusion-fade, --color-by names, colour values and ranges, points CSV)
#    fuzz_film_text (video: --camera-path files, --duration/--speed/--from/--to/--trail)
#    fuzz_serve_request (serve: request targets, path segments as numbers, the web root's answers)
#    fuzz_exif (photos: JPEG and HEIC bytes through the EXIF reader, exiv2 underneath; seeds ../shared/data/photos/)
#    fuzz_places (--places: ele text, tag values, .osm XML through the libosmium reader)
# 2. regressions: runs each fuzzer once over every file in tests/fuzz/regressions/<format>/
# 3. fuzzes each target for SECONDS_PER_TARGET, FUZZ_JOBS targets at a time (default: one per
#    core; each libFuzzer process uses one). The corpus lives in fuzz-corpus/<format>/
#    (git-ignored, kept between runs); seeds are read in place from ../shared/data/<format>/
#    (../shared/data/tiles/ for tile; never copied) and from the regression inputs.
# A crash, hang (-timeout=10) or excess memory (-rss_limit_mb=2048) is copied into
# tests/fuzz/regressions/<format>/ and makes the script exit 1 after all targets have run.
# Environment: FUZZ_TARGETS="gpx igc tcx fit kml geojson airspace task heatmap tile quantized_mesh terrain_text track_text film_text serve_request exif places" picks targets; FUZZ_MAX_LEN (default 1048576) caps
# input size -- the real files make MB-sized inputs, which run at ~20-100 exec/s under
# ASan, so FUZZ_MAX_LEN=16384 explores much faster.
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2
ROOT=$(pwd)

SECONDS_PER_TARGET=${1:-60}
TARGETS=${FUZZ_TARGETS:-gpx igc tcx fit kml geojson airspace task heatmap tile quantized_mesh terrain_text track_text film_text serve_request exif places}
FUZZ_JOBS=${FUZZ_JOBS:-$(nproc)}
DATA="$ROOT/../shared/data"
REGRESSIONS="$ROOT/tests/fuzz/regressions"
CORPUS="$ROOT/fuzz-corpus"

source scripts/compiler_cache.sh
source scripts/sanitizer_tree.sh
BUILD=$sanitizer_tree
ARTIFACTS="$ROOT/$BUILD/artifacts"
LOGS="$ROOT/$BUILD/logs"

echo "== configure + build the fuzz targets ($BUILD)"
configure_sanitizer_tree || { echo "fuzz: configure failed" >&2; exit 2; }
build_targets=()
for t in $TARGETS; do build_targets+=("fuzz_$t"); done
ninja -C "$BUILD" "${build_targets[@]}" || { echo "fuzz: build failed" >&2; exit 2; }

export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
mkdir -p "$ARTIFACTS" "$LOGS"
failed=()
regressed=""

# report LOG: the sanitizer's error line, the top frames of its first stack, its summary.
report() {
  awk '/ERROR: |runtime error:|contract violated|ALARM|out-of-memory/ && !e {print; e=1; next}
       e && /^ *#[0-9]+ / && !done {if (++n <= 6) print; next}
       e && n > 0 {done=1}
       /^SUMMARY/ {print}' "$1" | head -n 12 | sed 's/^/  | /'
}

# save_artifacts FORMAT: moves what libFuzzer left for FORMAT into the regression inputs.
# Succeeds (0) when there was nothing to save.
save_artifacts() {
  local fmt=$1 f saved=0
  mkdir -p "$REGRESSIONS/$fmt"
  for f in "$ARTIFACTS/$fmt"/crash-* "$ARTIFACTS/$fmt"/timeout-* "$ARTIFACTS/$fmt"/oom-* \
           "$ARTIFACTS/$fmt"/leak-* "$ARTIFACTS/$fmt"/slow-unit-*; do
    [ -f "$f" ] || continue
    case $(basename "$f") in slow-unit-*) rm -f "$f"; continue ;; esac
    cp "$f" "$REGRESSIONS/$fmt/" && rm -f "$f"
    echo "fuzz: saved $REGRESSIONS/$fmt/$(basename "$f")"
    saved=1
  done
  return $saved
}

echo
echo "== regression inputs (tests/fuzz/regressions/<format>/)"
for fmt in $TARGETS; do
  bin="$BUILD/fuzz/fuzz_$fmt"
  shopt -s nullglob
  inputs=("$REGRESSIONS/$fmt"/*)
  shopt -u nullglob
  if [ ${#inputs[@]} -eq 0 ]; then
    echo "$fmt: no regression inputs"
    continue
  fi
  # Run each input on its own so that one failure does not hide the others.
  bad=0
  for f in "${inputs[@]}"; do
    if ! "$bin" -rss_limit_mb=2048 -timeout=10 "$f" >"$LOGS/regression-$fmt.log" 2>&1; then
      echo "$fmt: FAILS on $f"
      report "$LOGS/regression-$fmt.log"
      bad=1
    fi
  done
  if [ $bad -eq 0 ]; then
    echo "$fmt: ${#inputs[@]} regression inputs pass"
  else
    failed+=("$fmt (regression)")
    regressed+=" $fmt "
  fi
done

# fuzz_one FORMAT: fuzzes one target; its report goes to $LOGS/summary-FORMAT.txt and it
# leaves $LOGS/failed-FORMAT when it found something (the targets run side by side).
fuzz_one() {
  local fmt=$1 bin="$BUILD/fuzz/fuzz_$1" out="$LOGS/summary-$1.txt"
  local seeds=() dict=() seed_dir="$DATA/$fmt" log="$LOGS/fuzz-$fmt.log" rc execs cov before
  rm -f "$LOGS/failed-$fmt"
  mkdir -p "$CORPUS/$fmt" "$ARTIFACTS/$fmt" "$REGRESSIONS/$fmt"
  [ "$fmt" = tile ] && seed_dir="$DATA/tiles"
  [ "$fmt" = exif ] && seed_dir="$DATA/photos"  # real JPEG and HEIC photos (those over FUZZ_MAX_LEN are cut)
  [ "$fmt" = task ] && seed_dir="$DATA/tasks"  # .xctsk, XCTSK: texts, IGC files with C records (XCSoar .tsk: the regressions)
  {
    if [ "$fmt" = terrain_text ] || [ "$fmt" = track_text ] || [ "$fmt" = film_text ] || [ "$fmt" = serve_request ] || [ "$fmt" = heatmap ] || [ "$fmt" = quantized_mesh ] || [ "$fmt" = places ]; then
      :  # seeded by its regression inputs (a config, a template, a header, a cache entry)
    elif [ -d "$seed_dir" ]; then
      seeds+=("$seed_dir")
    else
      echo "$fmt: $seed_dir absent; not seeding from shared data"
    fi
    seeds+=("$REGRESSIONS/$fmt")
    [ -f "$ROOT/fuzz/$fmt.dict" ] && dict=(-dict="$ROOT/fuzz/$fmt.dict")
    echo "$fmt: $bin, corpus $CORPUS/$fmt, log $log"
    "$bin" "${dict[@]}" -max_total_time="$SECONDS_PER_TARGET" -max_len="${FUZZ_MAX_LEN:-1048576}" -rss_limit_mb=2048 \
      -timeout=10 -print_final_stats=1 \
      -artifact_prefix="$ARTIFACTS/$fmt/" "$CORPUS/$fmt" "${seeds[@]}" >"$log" 2>&1
    rc=$?
    execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | awk '{s += $2} END {print s + 0}')
    # A crash ends the run before the final stats: take the last progress line instead.
    [ "$execs" = 0 ] && execs=$(grep -oE '^#[0-9]+' "$log" | tail -n1 | tr -d '#')
    cov=$(grep -oE '(INITED|DONE|pulse|NEW|REDUCE) +cov: [0-9]+ ft: [0-9]+ corp: [0-9]+/[0-9]+[a-zA-Z]*' "$log" | tail -n1)
    if save_artifacts "$fmt" && [ $rc -eq 0 ]; then
      echo "$fmt: ok, $execs executions; $cov"
      # Keep the corpus small: merge it into the inputs that still add coverage (the big
      # inputs real files produce make it grow by ~100 MB a run otherwise).
      rm -rf "$CORPUS/$fmt.merged" && mkdir -p "$CORPUS/$fmt.merged"
      if "$bin" -merge=1 -max_len=1048576 -rss_limit_mb=2048 -timeout=10 \
           "$CORPUS/$fmt.merged" "$CORPUS/$fmt" >"$LOGS/merge-$fmt.log" 2>&1; then
        before=$(du -sh "$CORPUS/$fmt" | cut -f1)
        rm -rf "${CORPUS:?}/$fmt" && mv "$CORPUS/$fmt.merged" "$CORPUS/$fmt"
        echo "$fmt: corpus minimised, $before -> $(du -sh "$CORPUS/$fmt" | cut -f1)"
      else
        rm -rf "$CORPUS/$fmt.merged"
        echo "$fmt: corpus merge failed (see $LOGS/merge-$fmt.log); corpus kept as is"
      fi
    else
      echo "$fmt: FAILED (libFuzzer exit $rc) after $execs executions; $cov"
      report "$log"
      touch "$LOGS/failed-$fmt"
    fi
  } >"$out" 2>&1
}

if [ "$SECONDS_PER_TARGET" -gt 0 ] 2>/dev/null; then
  echo
  echo "== fuzzing, ${SECONDS_PER_TARGET}s per target, $FUZZ_JOBS at a time"
  fuzzed=()
  for fmt in $TARGETS; do
    if [[ $regressed == *" $fmt "* ]]; then
      echo "$fmt: not fuzzed: its regression inputs fail (it would only find those again)"
      continue
    fi
    # At most FUZZ_JOBS targets at once: wait for one to end before starting the next.
    while [ "$(jobs -rp | wc -l)" -ge "$FUZZ_JOBS" ]; do wait -n; done
    fuzz_one "$fmt" &
    fuzzed+=("$fmt")
  done
  wait
  for fmt in "${fuzzed[@]}"; do
    cat "$LOGS/summary-$fmt.txt"
    [ -f "$LOGS/failed-$fmt" ] && failed+=("$fmt")
  done
fi

echo
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: FAILED: ${failed[*]} (inputs saved under tests/fuzz/regressions/; logs in $LOGS)"
  exit 1
fi
echo "fuzz: all clean"
