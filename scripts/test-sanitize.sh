#!/usr/bin/env bash
# npm run test:sanitize: the native GoogleTest suites in a Debug build with AddressSanitizer and
# UndefinedBehaviorSanitizer (build/native-asan): Eigen's and libstdc++'s asserts on, every warning
# an error, any sanitizer finding a failed test. About 10 minutes of two cores (the build 13 CPU
# minutes, the suites 10), so npm test runs the same suites in the Release build instead.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --native

if [ ! -f build/native-asan/build.ninja ]; then
  cmake -S wasm -B build/native-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DIK_SANITIZE=ON -DIK_WERROR=ON >/dev/null
fi
cmake --build build/native-asan --target ik_tests
npx tsx scripts/write-test-rigs.ts >/dev/null  # the project's rigs in A7 format, for the native tests
ctest --test-dir build/native-asan --output-on-failure -j 2
