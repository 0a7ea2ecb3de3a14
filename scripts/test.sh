#!/usr/bin/env bash
# npm test: install what is missing, build both targets, then run every test: the C++ format
# check, the native GoogleTest suites under AddressSanitizer and UndefinedBehaviorSanitizer
# (scripts/test-sanitize.sh: build/native-asan, Debug with asserts, warnings as errors), the
# TypeScript type check, the layers, ESLint and Prettier, vitest (WebAssembly in Node, then the
# browser). The report's A7 rigs are read from $IK_A7_DIR (default ../shared/rigs/a7); without that
# folder the suites that need them are skipped, each layer printing one line, unless CI is set.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --native --browser

echo "== C++ format (clang-format, .clang-format)"
mapfile -t cxx_files < <(find wasm/src wasm/bindings wasm/native wasm/tests wasm/tools -name '*.cpp' -o -name '*.h' | sort)
clang-format --dry-run --Werror "${cxx_files[@]}"

echo "== native tests (GoogleTest, with AddressSanitizer and UndefinedBehaviorSanitizer)"
bash scripts/test-sanitize.sh

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
