// The package's WebAssembly core: ik_core.wasm beside the built module (dist/lib/index.js), loaded
// once and shared by every avatar. A browser fetches it (the glue's own URL, kept beside the module
// by vite.lib.config.ts); Node reads its bytes from disk, since Emscripten 3.1.6's web build cannot
// fetch a file: URL.
import { loadIk, type IkCoreModule } from '../ik/module.js';

let shared: Promise<IkCoreModule> | null = null;

async function load(): Promise<IkCoreModule> {
  const wasm = new URL(/* @vite-ignore */ './ik_core.wasm', import.meta.url);
  if (wasm.protocol !== 'file:') return loadIk();
  const { readFileSync } = process.getBuiltinModule('node:fs');
  return loadIk({ wasmBinary: readFileSync(wasm) });
}

/** The shared core; a failed load (no WebAssembly, the .wasm missing) is retried by the next call. */
export function packageCore(): Promise<IkCoreModule> {
  if (!shared) {
    shared = load();
    shared.catch(() => (shared = null));
  }
  return shared;
}
