#!/usr/bin/env bash
# npm run build: the whole site as static files in dist/site/, for any static file server:
#   index.html (the page), embed-example.html, ik-widget.js (the widget, WebAssembly inside),
#   models/ (the project's rigs), assets/ (the page's scripts and its .wasm);
# and the three.js package in dist/lib/ (vite.lib.config.ts), ready for npm pack or npm publish.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
npx vite build --config vite.config.ts --logLevel warn
npx vite build --config vite.widget.config.ts --logLevel warn
cp dist/widget/ik-widget.js dist/site/ik-widget.js
cp web/embed-example.html dist/site/embed-example.html
npx vite build --config vite.lib.config.ts --logLevel warn
echo "build: dist/site/ ($(du -sh dist/site | cut -f1)): serve it with any static file server, e.g. npx vite preview"
echo "build: dist/lib/ ($(du -sh dist/lib | cut -f1)): the ik-web-avatar package, e.g. npm pack dist/lib"
