#!/usr/bin/env bash
# npm test: install what is missing, build both targets, then run every test: the C++ format
# check, native GoogleTest (build/native, Release, warnings as errors), the TypeScript type check,
# the layers, ESLint and Prettier, vitest (WebAssembly in Node, then the browser). The same
# GoogleTest suites under AddressSanitizer and UndefinedBehaviorSanitizer: npm run test:sanitize (scripts/test-sanitize.sh).
# The report's A7 rigs are read from $IK_A7_DIR (default ../shared/rigs/a7); without that folder
# the suites that need them are skipped, each layer printing one line, unless CI is set.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --native --browser

echo "== C++ format (clang-format, .clang-format)"
mapfile -t cxx_files < <(find wasm/src wasm/bindings wasm/native wasm/tests wasm/tools -name '*.cpp' -o -name '*.h' | sort)
clang-format --dry-run --Werror "${cxx_files[@]}"

echo "== native tests (GoogleTest)"
npx tsx scripts/write-test-rigs.ts >/dev/null  # the project's rigs in A7 format, for the native tests
ctest --test-dir build/native --output-on-failure -j 2 | tee build/native/ctest.log
# The tests that need the report's A7 rigs skip without them (and fail under CI): say so.
source scripts/a7_dir.sh
if [ ! -d "$a7_dir" ]; then
  echo "A7 rigs not found at $a7_dir: $(grep -c '\*\*\*Skipped' build/native/ctest.log) native A7 tests skipped"
fi

echo "== type check"
npx tsc -p tsconfig.json

echo "== layers (dependency-cruiser: no import up the layers, no cycle; .dependency-cruiser.cjs)"
npm run --silent lint:deps

echo "== TypeScript lint and format (ESLint, eslint.config.mjs; Prettier, .prettierrc.json: npm run format fixes it)"
npm run --silent lint

echo "== vitest"
npx vitest run "$@"

echo "== browser tests (headless Chromium: the page and the widget)"
npx vitest run --config vitest.browser.config.ts
