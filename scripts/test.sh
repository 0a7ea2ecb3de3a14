#!/usr/bin/env bash
# npm test: install what is missing, build both targets, then run every test:
# native GoogleTest, the TypeScript type check, vitest (WebAssembly in Node, then the browser).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --native --browser

echo "== native tests (GoogleTest)"
ctest --test-dir build/native --output-on-failure -j 2

echo "== type check"
npx tsc -p tsconfig.json

echo "== vitest"
npx vitest run "$@"

echo "== browser tests (headless Chromium: the page and the widget)"
npx vitest run --config vitest.browser.config.ts
