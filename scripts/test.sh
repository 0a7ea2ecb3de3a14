#!/usr/bin/env bash
# npm test: install what is missing, build both targets, then run every test: the C++ format
# check, the native GoogleTest suites under AddressSanitizer and UndefinedBehaviorSanitizer
# (scripts/test-sanitize.sh: build/native-asan, Debug with asserts, warnings as errors), the
# TypeScript type check, the layers, ESLint and Prettier, vitest (WebAssembly in Node, then the
# browser). The report's A7 rigs are read from $IK_A7_DIR (default ../shared/rigs/a7); without that
# folder the suites that need them are skipped, each layer printing one line, unless CI is set.
set -euo pipefail
cd "$(dirname "$0")/.."
started=$SECONDS
# A stage's heading, with the minutes and seconds since npm test began (where the suite's time goes).
stage() { printf '== %s (at %d:%02d)\n' "$1" $(((SECONDS - started) / 60)) $(((SECONDS - started) % 60)); }
bash scripts/setup.sh --native --browser

stage "C++ format (clang-format, .clang-format)"
mapfile -t cxx_files < <(find wasm/src wasm/bindings wasm/native wasm/tests wasm/tools -name '*.cpp' -o -name '*.h' | sort)
clang-format --dry-run --Werror "${cxx_files[@]}"

stage "native tests (GoogleTest, with AddressSanitizer and UndefinedBehaviorSanitizer)"
bash scripts/test-sanitize.sh

stage "type check"
npx tsc -p tsconfig.json

stage "layers (dependency-cruiser: no import up the layers, no cycle; .dependency-cruiser.cjs)"
npm run --silent lint:deps

stage "TypeScript lint and format (ESLint, eslint.config.mjs; Prettier, .prettierrc.json: npm run format fixes it)"
npm run --silent lint

stage "vitest"
npx vitest run "$@"

stage "browser tests (headless Chromium: the page and the widget)"
npx vitest run --config vitest.browser.config.ts
stage "done"
