#!/usr/bin/env bash
# npm run bench:report [-- --samples N] [--out DIR]: install and build what is missing (native and
# WebAssembly, with the benchmark tools), then run the whole measurement set into docs/benchmarks.md
# (bench-node/report/report.ts). Exits 1 when a target was missed, after writing the document.
# Needs the report's A7 rigs: $IK_A7_DIR (default ../shared/rigs/a7).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/a7_dir.sh
require_a7 bench:report
bash scripts/setup.sh --native
cmake --build build/native --target solver_speed scale_bench ik_bench_native >/dev/null
NODE_PATH=/usr/share/nodejs cmake --build build/wasm --target solver_speed scale_bench >/dev/null
exec npx tsx bench-node/report/report.ts --a7-dir "$a7_dir" "$@"
