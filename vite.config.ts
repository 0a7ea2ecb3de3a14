import { resolve } from 'node:path';
import { defineConfig } from 'vite';

import { widgetDevServer } from './vite.widget.config.js';

const isolation = { 'Cross-Origin-Opener-Policy': 'same-origin', 'Cross-Origin-Embedder-Policy': 'require-corp' };

// The page lives in web/; `npm start` serves it (and web/embed-example.html with the widget's source).
export default defineConfig({
  root: resolve(import.meta.dirname, 'web'),
  publicDir: resolve(import.meta.dirname, 'web/public'),
  plugins: [widgetDevServer()],
  // Pre-bundle what the page imports. embed-example.html loads the widget script from a path
  // widgetDevServer() serves (no file there), which the dependency scan would report as missing.
  optimizeDeps: { entries: ['index.html'] },
  // Cross-origin isolation gives performance.now() microsecond resolution (100 us without it),
  // so the page's per-solve times are measured, not rounded.
  server: { port: 5173, strictPort: false, headers: isolation },
  preview: { headers: isolation },
  // `npm run build` (scripts/build-site.sh) writes the page here and adds the widget and its example.
  // three.js alone is about 700 kB minified: one chunk is fine for this page.
  // The compare worker (web/src/page/compare_worker.ts) is an ES module: it imports the WebAssembly glue.
  worker: { format: 'es' },
  build: {
    outDir: resolve(import.meta.dirname, 'dist/site'),
    emptyOutDir: true,
    target: 'es2022',
    chunkSizeWarningLimit: 2000,
  },
});
