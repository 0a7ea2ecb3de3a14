#!/usr/bin/env bash
# The native GoogleTest suites in a Debug build with AddressSanitizer and UndefinedBehaviorSanitizer
# (build/native-asan): -O1, Eigen's and libstdc++'s asserts on, every warning an error, any
# sanitizer finding a failed test. npm test runs it (scripts/test.sh); alone: npm run test:sanitize.
# About 7 minutes of two cores from a clean clone (the build about 12 CPU minutes, the suites 8).
# The tests that need the report's A7 rigs skip without them (and fail under CI): it says how many.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --native

if [ ! -f build/native-asan/build.ninja ]; then
  cmake -S wasm -B build/native-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DIK_SANITIZE=ON -DIK_WERROR=ON >/dev/null
fi
cmake --build build/native-asan --target ik_tests
echo "sanitizer build of the suites: $((SECONDS / 60)) min $((SECONDS % 60)) s"
npx tsx scripts/write-test-rigs.ts >/dev/null  # the project's rigs in A7 format, for the native tests
ctest --test-dir build/native-asan --output-on-failure -j 2 | tee build/native-asan/ctest.log
source scripts/a7_dir.sh
if [ ! -d "$a7_dir" ]; then
  echo "A7 rigs not found at $a7_dir: $(grep -c '\*\*\*Skipped' build/native-asan/ctest.log) native A7 tests skipped"
fi
