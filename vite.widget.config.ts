import { resolve } from 'node:path';
import { defineConfig, type Plugin } from 'vite';

// The embeddable widget: one ES module script, dist/widget/ik-widget.js, with three.js and the
// WebAssembly (base64, see web/src/widget/core.ts) inside. Build: npx vite build --config vite.widget.config.ts

/** The Emscripten glue names its .wasm with new URL(..., import.meta.url); the widget passes the
 *  bytes itself, so that reference is replaced by the bare name rather than bundled a second time. */
function dropGlueWasmUrl(): Plugin {
  return {
    name: 'ik-drop-glue-wasm-url',
    transform(code, id) {
      if (!id.endsWith('ik_core.mjs')) return null;
      const out = code.replace(
        /new URL\(\s*["']ik_core\.wasm["']\s*,\s*import\.meta\.url\s*\)\.toString\(\)/g,
        '"ik_core.wasm"',
      );
      // A new Emscripten may spell it differently: fail the build rather than ship the .wasm twice.
      if (out === code)
        this.error(
          'ik_core.mjs: the wasm URL expression new URL("ik_core.wasm", import.meta.url).toString() was not found; update dropGlueWasmUrl() for this Emscripten',
        );
      return { code: out, map: null };
    },
  };
}

export default defineConfig({
  publicDir: false,
  plugins: [dropGlueWasmUrl()],
  build: {
    outDir: resolve(import.meta.dirname, 'dist/widget'),
    emptyOutDir: true,
    target: 'es2022',
    assetsInlineLimit: () => true,
    lib: {
      entry: resolve(import.meta.dirname, 'web/src/widget/ik_widget.ts'),
      formats: ['es'],
      fileName: () => 'ik-widget.js',
    },
    rollupOptions: { output: { inlineDynamicImports: true } },
  },
});

/** For `npm start`: serves the widget's source as /ik-widget.js, the path the embed example
 *  (web/embed-example.html) loads the built script from (beside it in dist/site/). */
export function widgetDevServer(): Plugin {
  const source = resolve(import.meta.dirname, 'web/src/widget/ik_widget.ts');
  return {
    name: 'ik-widget-dev-server',
    apply: 'serve',
    resolveId(id) {
      return id.replace(/[?#].*$/, '') === '/ik-widget.js' ? source : null;
    },
  };
}
