// Loads the WebAssembly core the same way in the browser (vite resolves the .wasm next to the
// glue) and in Node (pass the file's bytes as wasmBinary, see node.ts).
import createIkModule, { type IkCoreModule, type IkCoreModuleOptions } from './generated/ik_core.mjs';

export type { IkCoreModule, IkCoreModuleOptions };

/** Instantiates the core. Options go to Emscripten (wasmBinary, instantiateWasm, locateFile). */
export async function loadIk(options: IkCoreModuleOptions = {}): Promise<IkCoreModule> {
  return createIkModule(options);
}
