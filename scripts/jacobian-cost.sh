#!/usr/bin/env bash
# Times the analytic Jacobian against the paper's central differences, natively and in
# WebAssembly (Node), with the same C++ program (wasm/tools/jacobian_cost.cpp).
# Usage: npm run bench:jacobian -- [RIG.json]   (default: the report's beast, $IK_A7_DIR/beast.json,
# IK_A7_DIR defaulting to ../shared/rigs/a7; the project's own is build/test-rigs/beast.json,
# written by npx tsx scripts/write-test-rigs.ts)
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/a7_dir.sh
[ $# -gt 0 ] || require_a7 bench:jacobian ", or write the project's rigs and name one: npx tsx scripts/write-test-rigs.ts && npm run bench:jacobian -- build/test-rigs/beast.json"
rig="${1:-$a7_dir/beast.json}"
bash scripts/setup.sh --native >/dev/null
cmake --build build/native --target jacobian_cost >/dev/null
NODE_PATH=/usr/share/nodejs cmake --build build/wasm --target jacobian_cost >/dev/null
echo "== native (g++ -O3)"
build/native/jacobian_cost "$rig"
echo "== WebAssembly (em++ -O3 -msimd128, Node $(node --version))"
node build/wasm/jacobian_cost.cjs "$rig"
