#!/usr/bin/env bash
# Builds trailray for the browser with Emscripten (Debian's emscripten 3.1.6) into build-web/:
# the GL-free core and its tests (run under node by `ctest --test-dir build-web`), and the web
# app that `trailray serve` serves. Run scripts/setup.sh first (it installs Emscripten and
# unpacks the source packages the build compiles).
set -euo pipefail
cd "$(dirname "$0")/.."

# emcc 3.1.6 finds its JavaScript tools (acorn, terser) only through NODE_PATH.
export NODE_PATH=/usr/share/nodejs
source scripts/compiler_cache.sh
# The tests run under node; emcmake's default emulator passes a flag Node 20 rejects, and Node
# 20's own fetch() stands in the way of emscripten's file loading (--no-experimental-fetch).
# TRAILRAY_WEB_TESTS=OFF: the web app only (scripts/serve.sh), not the tests.
emcmake cmake -S . -B build-web -G Ninja -DCMAKE_BUILD_TYPE=Release "-DTRAILRAY_TESTS=${TRAILRAY_WEB_TESTS:-ON}" -DTRAILRAY_WERROR=ON \
  "-DCMAKE_CROSSCOMPILING_EMULATOR=$(command -v node);--no-experimental-fetch" "${launcher[@]}" >/dev/null
cmake --build build-web
