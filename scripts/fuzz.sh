#!/usr/bin/env bash
# Fuzzes the track readers and the tile decoders with libFuzzer (clang, ASan + UBSan).
#
#   scripts/fuzz.sh [SECONDS_PER_TARGET]      (default 60; 0 = regression inputs only)
#
# 1. configures and builds build-fuzz (clang, -DTRAILRAY_FUZZ=ON) -> fuzz_gpx, fuzz_igc, fuzz_tcx, fuzz_fit, fuzz_kml (KML and KMZ), fuzz_geojson, fuzz_task (XCTrack tasks, IGC C records), fuzz_tile,
#    fuzz_terrain_text (config, URL templates, Cache-Control, disk cache entries)
#    fuzz_track_text (--range / --occlusion-fade, --color-by names, colour values and ranges, points CSV)
#    fuzz_film_text (video: --camera-path files, --duration/--speed/--from/--to/--trail)
#    fuzz_serve_request (serve: request targets, path segments as numbers, the web root's answers)
# 2. regressions: runs each fuzzer once over every file in tests/fuzz/regressions/<format>/
# 3. fuzzes each target for SECONDS_PER_TARGET. The corpus lives in fuzz-corpus/<format>/
#    (git-ignored, kept between runs); seeds are read in place from ../shared/data/<format>/
#    (../shared/data/tiles/ for tile; never copied) and from the regression inputs.
# A crash, hang (-timeout=10) or excess memory (-rss_limit_mb=2048) is copied into
# tests/fuzz/regressions/<format>/ and makes the script exit 1 after all targets have run.
# Environment: FUZZ_TARGETS="gpx igc tcx fit kml geojson airspace task tile terrain_text track_text film_text serve_request" picks targets; FUZZ_MAX_LEN (default 1048576) caps
# input size -- the real files make MB-sized inputs, which run at ~20-100 exec/s under
# ASan, so FUZZ_MAX_LEN=16384 explores much faster. One process per target, one at a time.
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2
ROOT=$(pwd)

SECONDS_PER_TARGET=${1:-60}
TARGETS=${FUZZ_TARGETS:-gpx igc tcx fit kml geojson airspace task tile terrain_text track_text film_text serve_request}
BUILD=build-fuzz
DATA="$ROOT/../shared/data"
REGRESSIONS="$ROOT/tests/fuzz/regressions"
CORPUS="$ROOT/fuzz-corpus"
ARTIFACTS="$ROOT/$BUILD/artifacts"
LOGS="$ROOT/$BUILD/logs"

if ! command -v clang++ >/dev/null 2>&1; then
  echo "fuzz: clang++ not found (scripts/setup.sh installs clang and libclang-rt-14-dev)" >&2
  exit 2
fi

echo "== configure + build ($BUILD)"
if [ -f "$BUILD/CMakeCache.txt" ] && ! grep -q '^CMAKE_CXX_COMPILER:.*clang' "$BUILD/CMakeCache.txt"; then
  echo "fuzz: $BUILD was configured with another compiler; reconfiguring from scratch"
  rm -rf "$BUILD"
fi
source scripts/compiler_cache.sh
CC=clang CXX=clang++ cmake -S . -B "$BUILD" -G Ninja -DTRAILRAY_FUZZ=ON -DTRAILRAY_TESTS=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo "${launcher[@]}" >/dev/null || { echo "fuzz: configure failed" >&2; exit 2; }
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

if [ "$SECONDS_PER_TARGET" -gt 0 ] 2>/dev/null; then
  echo
  echo "== fuzzing, ${SECONDS_PER_TARGET}s per target"
  for fmt in $TARGETS; do
    bin="$BUILD/fuzz/fuzz_$fmt"
    if [[ $regressed == *" $fmt "* ]]; then
      echo "$fmt: not fuzzed: its regression inputs fail (it would only find those again)"
      continue
    fi
    mkdir -p "$CORPUS/$fmt" "$ARTIFACTS/$fmt" "$REGRESSIONS/$fmt"
    seeds=()
    seed_dir="$DATA/$fmt"
    [ "$fmt" = tile ] && seed_dir="$DATA/tiles"
    [ "$fmt" = task ] && seed_dir="$DATA/tasks"  # .xctsk, XCTSK: texts, IGC files with C records
    if [ "$fmt" = terrain_text ] || [ "$fmt" = track_text ] || [ "$fmt" = film_text ] || [ "$fmt" = serve_request ]; then
      :  # seeded by its regression inputs (a config, a template, a header, a cache entry)
    elif [ -d "$seed_dir" ]; then
      seeds+=("$seed_dir")
    else
      echo "$fmt: $seed_dir absent; not seeding from shared data"
    fi
    seeds+=("$REGRESSIONS/$fmt")
    dict=()
    [ -f "$ROOT/fuzz/$fmt.dict" ] && dict=(-dict="$ROOT/fuzz/$fmt.dict")
    log="$LOGS/fuzz-$fmt.log"
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
      failed+=("$fmt")
    fi
  done
fi

echo
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: FAILED: ${failed[*]} (inputs saved under tests/fuzz/regressions/; logs in $LOGS)"
  exit 1
fi
echo "fuzz: all clean"
