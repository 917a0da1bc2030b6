#!/usr/bin/env bash
# The developers' inner loop: one tree (build/, Release with -Werror, the same as test.sh's first
# stage and sharing its files), rebuilt incrementally, and only the tests the change touches.
#
#   scripts/quick-test.sh            the tests of what changed against QUICK_TEST_BASE (default
#                                    HEAD: uncommitted and new files): a changed test file runs its
#                                    suites; a changed file of src/<layer>/ runs every test of
#                                    tests/<layer>/; fuzz/ the regression inputs; src/python/
#                                    the module's pytest suites; anything else
#                                    (CMake, scripts, tests/test_support.hpp) every test
#   scripts/quick-test.sh REGEX      the tests whose names match REGEX (ctest -R)
#   scripts/quick-test.sh --all      every test of the tree
#
# scripts/test.sh stays the whole check (the sanitizers, the browser, the fuzzers) before a push.
set -euo pipefail
cd "$(dirname "$0")/.."

[ -f build/CMakeCache.txt ] || scripts/setup.sh
source scripts/compiler_cache.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DTRAILRAY_TESTS=ON -DTRAILRAY_BENCH=ON -DTRAILRAY_WERROR=ON "${launcher[@]}" >/dev/null
cmake --build build

run() { exec ctest --test-dir build --no-tests=error --output-on-failure -j "$(nproc)" "$@"; }
case "${1:-}" in
  --all) run ;;
  -h|--help) sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
  "") ;;
  *) run -R "$1" ;;
esac

base=${QUICK_TEST_BASE:-HEAD}
mapfile -t changed < <({ git diff --name-only "$base" --; git ls-files --others --exclude-standard; } | sort -u)
if [ ${#changed[@]} -eq 0 ]; then
  echo "quick-test: nothing changed against $base (give a REGEX, --all, or QUICK_TEST_BASE=origin/main)"
  exit 0
fi

test_files=()
fuzz=0
python=0
for f in "${changed[@]}"; do
  case $f in
    tests/fuzz/*|fuzz/*) fuzz=1 ;;
    tests/python/*|src/python/*) python=1 ;;  # the module's pytest suites
    tests/packaging/*|scripts/gpu-bundle.sh) packaging=1 ;;
    tests/web/*|src/web/*|docs/*|*.md|examples/*|bench/*) ;;  # nothing of this tree's ctest
    tests/*_test.cpp) [ -f "$f" ] && test_files+=("$f") ;;
    src/*/*)
      layer=${f#src/}; layer=${layer%%/*}
      [ -d "tests/$layer" ] && mapfile -t -O "${#test_files[@]}" test_files < <(find "tests/$layer" -name '*_test.cpp')
      ;;
    *) echo "quick-test: $f changed: running every test"; run ;;
  esac
done

# Suite names of the test files: TEST(Suite, ...), TEST_F, TEST_P; a test's ctest name is
# Suite.Name, or Instance/Suite.Name/Param for parameterised ones.
suites=()
if [ ${#test_files[@]} -gt 0 ]; then
  mapfile -t suites < <(grep -hoE '^(TEST|TEST_F|TEST_P)\( *[A-Za-z0-9_]+' "${test_files[@]}" | sed -E 's/.*\( *//' | sort -u)
fi
patterns=()
[ ${#suites[@]} -gt 0 ] && patterns+=("(^|/)($(IFS='|'; echo "${suites[*]}"))\\.")
[ $fuzz -eq 1 ] && patterns+=("^fuzz_regression_")
[ $python -eq 1 ] && patterns+=("^python\\.")
[ "${packaging:-0}" -eq 1 ] && patterns+=("^packaging\\.")
if [ ${#patterns[@]} -eq 0 ]; then
  echo "quick-test: no test of this tree covers what changed (${changed[*]})"
  exit 0
fi
echo "quick-test: ${#suites[@]} suites from ${#test_files[@]} test files$([ $fuzz -eq 1 ] && echo ', the fuzzers'\'' regression inputs')$([ $python -eq 1 ] && echo ', the Python module'\''s suites')"
run -R "$(IFS='|'; echo "${patterns[*]}")"
