# Sourced by test.sh and fuzz.sh: configures build-sanitize, the one clang tree that serves both
# the test suite under AddressSanitizer + UndefinedBehaviorSanitizer and the libFuzzer targets
# (the libraries are compiled once, with the fuzzers' coverage hooks; see fuzz/CMakeLists.txt and
# cmake/Sanitizers.cmake). Both scripts configure it the same way, so neither rebuilds what the
# other built. Needs scripts/compiler_cache.sh sourced first (the `launcher` array).
sanitizer_tree=build-sanitize

configure_sanitizer_tree() {
  if ! command -v clang++ >/dev/null 2>&1; then
    echo "clang++ not found (scripts/setup.sh installs clang and libclang-rt-14-dev)" >&2
    return 2
  fi
  if [ -f "$sanitizer_tree/CMakeCache.txt" ] && ! grep -q '^CMAKE_CXX_COMPILER:.*clang' "$sanitizer_tree/CMakeCache.txt"; then
    echo "$sanitizer_tree was configured with another compiler; reconfiguring from scratch"
    rm -rf "$sanitizer_tree"
  fi
  CC=clang CXX=clang++ cmake -S . -B "$sanitizer_tree" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DTRAILRAY_SANITIZE=ON -DTRAILRAY_PYTHON=OFF \
    -DTRAILRAY_FUZZ=ON -DTRAILRAY_TESTS=ON -DTRAILRAY_WERROR=ON "${launcher[@]}" >/dev/null
}
