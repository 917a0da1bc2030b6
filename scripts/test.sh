#!/usr/bin/env bash
# Quick start, second command (and CI): set up, build and run every test: the Release build
# with warnings as errors, the same suite under AddressSanitizer + UndefinedBehaviorSanitizer
# (one clang tree that also builds the fuzzers), the WebAssembly build with the page in
# Chromium, and each fuzzer's regression inputs and a short fuzzing run. Real data is read from
# ../shared/data when present. Each stage's time is printed at the end.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)

stage_times=()
stage_start=$SECONDS
# stage NAME: starts timing a stage (and ends the one before).
stage() {
  end_stage
  stage_name=$1
  stage_start=$SECONDS
  echo "== $1"
}
end_stage() {
  if [ -n "${stage_name:-}" ]; then stage_times+=("$(printf '%5d s  %s' $((SECONDS - stage_start)) "$stage_name")"); fi
}
print_stage_times() {
  end_stage
  stage_name=""
  echo
  echo "== time per stage"
  printf '%s\n' "${stage_times[@]}"
  printf '%5d s  total\n' "$SECONDS"
}
trap print_stage_times EXIT

stage "setup"
scripts/setup.sh
source scripts/compiler_cache.sh
source scripts/sanitizer_tree.sh

stage "Release build"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DTRAILRAY_TESTS=ON -DTRAILRAY_BENCH=ON -DTRAILRAY_WERROR=ON "${launcher[@]}" >/dev/null
cmake --build build
stage "Release tests"
ctest --test-dir build --no-tests=error --output-on-failure -j "$jobs"

stage "AddressSanitizer + UndefinedBehaviorSanitizer build (clang; the fuzzers too)"
configure_sanitizer_tree
cmake --build "$sanitizer_tree"
stage "AddressSanitizer + UndefinedBehaviorSanitizer tests"
# LeakSanitizer runs at every test's exit (and every `trailray` the app tests start).
# intercept_tls_get_addr=0: ASan's record of dynamically loaded modules' TLS blocks goes wrong
# with Mesa's driver loaded (a block at 0x3040 of 96 GiB on the main thread), and LeakSanitizer's
# tracer then dies reading it (signal 11, "LeakSanitizer has encountered a fatal error") after
# every test passed. Without the interception those blocks (only the GL driver has any) are not
# scanned; our own thread_local data is static TLS and still is.
env ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:intercept_tls_get_addr=0 \
    LSAN_OPTIONS=suppressions="$PWD/tests/lsan.supp":print_suppressions=0 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir "$sanitizer_tree" --no-tests=error --output-on-failure -j "$jobs"

stage "WebAssembly build (Emscripten)"
scripts/web.sh
# puppeteer-core, exactly as the lockfile says (it drives Debian's Chromium; it downloads no browser).
npm ci --prefix tests/web --no-audit --no-fund --loglevel=error
stage "WebAssembly tests: the core's under node, the page in headless Chromium"
ctest --test-dir build-web --no-tests=error --output-on-failure -j "$jobs"

stage "Fuzzers: regression inputs, then a short run of each"
# Inputs up to 64 KiB: many more executions per second than the 1 MiB default.
FUZZ_MAX_LEN="${FUZZ_MAX_LEN:-65536}" scripts/fuzz.sh "${TRAILRAY_FUZZ_SECONDS:-30}"
