// Node entry: reads the .wasm from disk, since Emscripten 3.1.6's own Node path fails for ES modules.
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

import { loadIk, type IkCoreModule, type IkCoreModuleOptions } from './module.js';

/** Path of the built .wasm file. */
export const wasmPath = fileURLToPath(new URL('./generated/ik_core.wasm', import.meta.url));

/** Instantiates the core in Node from the .wasm next to the generated glue. */
export async function loadIkNode(options: IkCoreModuleOptions = {}): Promise<IkCoreModule> {
  return loadIk({ wasmBinary: readFileSync(wasmPath), ...options });
}
