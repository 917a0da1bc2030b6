#!/usr/bin/env bash
# Quick start, second command (and CI): set up, build and run every test: the Release build
# with warnings as errors, the same suite under AddressSanitizer + UndefinedBehaviorSanitizer,
# and each fuzzer for a bounded time. Real data is read from ../shared/data when present.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)

scripts/setup.sh
source scripts/compiler_cache.sh

echo "== Release build, all tests"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DTRAILRAY_TESTS=ON -DTRAILRAY_BENCH=ON -DTRAILRAY_WERROR=ON "${launcher[@]}" >/dev/null
cmake --build build
ctest --test-dir build --no-tests=error --output-on-failure -j "$jobs"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build, all tests"
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DTRAILRAY_SANITIZE=ON -DTRAILRAY_TESTS=ON -DTRAILRAY_WERROR=ON "${launcher[@]}" >/dev/null
cmake --build build-asan
# LeakSanitizer runs at every test's exit (and every `trailray` the app tests start).
# intercept_tls_get_addr=0: ASan's record of dynamically loaded modules' TLS blocks goes wrong
# with Mesa's driver loaded (a block at 0x3040 of 96 GiB on the main thread), and LeakSanitizer's
# tracer then dies reading it (signal 11, "LeakSanitizer has encountered a fatal error") after
# every test passed. Without the interception those blocks (only the GL driver has any) are not
# scanned; our own thread_local data is static TLS and still is.
env ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:intercept_tls_get_addr=0 \
    LSAN_OPTIONS=suppressions="$PWD/tests/lsan.supp":print_suppressions=0 \
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-asan --no-tests=error --output-on-failure -j "$jobs"

echo "== WebAssembly build (Emscripten): the core's tests under node, the page in headless Chromium"
scripts/web.sh
# puppeteer-core, exactly as the lockfile says (it drives Debian's Chromium; it downloads no browser).
npm ci --prefix tests/web --no-audit --no-fund --loglevel=error
ctest --test-dir build-web --no-tests=error --output-on-failure -j "$jobs"

echo "== Fuzzers (bounded)"
# Inputs up to 64 KiB: many more executions per second than the 1 MiB default.
FUZZ_MAX_LEN="${FUZZ_MAX_LEN:-65536}" scripts/fuzz.sh "${TRAILRAY_FUZZ_SECONDS:-30}"
