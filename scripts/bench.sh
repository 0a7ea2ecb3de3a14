#!/usr/bin/env bash
# npm run bench -- [options]: install what is missing, build the WebAssembly (and the native
# engine when --engine asks for it), then run the benchmark command line (bench-node/cli.ts).
# Setup output goes to stderr, so stdout carries only the tables.
set -euo pipefail
cd "$(dirname "$0")/.."

setup_args=()
previous=""
for arg in "$@"; do
  case "$arg" in
    --engine=*native*) setup_args=(--native) ;;
  esac
  if [ "$previous" = "--engine" ] && [[ "$arg" == *native* ]]; then setup_args=(--native); fi
  previous="$arg"
done

bash scripts/setup.sh "${setup_args[@]}" >&2
exec npx tsx bench-node/cli.ts "$@"
