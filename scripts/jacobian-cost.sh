#!/usr/bin/env bash
# Times the analytic Jacobian against the paper's central differences, natively and in
# WebAssembly (Node), with the same C++ program (wasm/tools/jacobian_cost.cpp).
# Usage: npm run bench:jacobian -- [RIG.json]   (default: ../shared/rigs/a7/beast.json)
set -euo pipefail
cd "$(dirname "$0")/.."
rig="${1:-../shared/rigs/a7/beast.json}"
bash scripts/setup.sh --native >/dev/null
cmake --build build/native --target jacobian_cost >/dev/null
NODE_PATH=/usr/share/nodejs cmake --build build/wasm --target jacobian_cost >/dev/null
echo "== native (g++ -O3)"
build/native/jacobian_cost "$rig"
echo "== WebAssembly (em++ -O3 -msimd128, Node $(node --version))"
node build/wasm/jacobian_cost.cjs "$rig"
