#!/usr/bin/env bash
# npm start: install what is missing, build the WebAssembly, serve the page with vite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
exec npx vite --config vite.config.ts "$@"
