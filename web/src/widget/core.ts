// The WebAssembly core for widgets: the .wasm bytes are inlined in the script (vite ?inline), so
// the host page needs no second file and no server configuration. One instance serves every
// widget on the page.
import wasmDataUrl from '../ik/generated/ik_core.wasm?url&inline';
import { loadIk, type IkCoreModule } from '../ik/module.js';

let shared: Promise<IkCoreModule> | null = null;

function decodeDataUrl(url: string): Uint8Array {
  const comma = url.indexOf(',');
  const binary = atob(url.slice(comma + 1));
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

/** The shared core; a failed load is retried by the next caller. */
export function widgetCore(): Promise<IkCoreModule> {
  if (!shared) {
    shared = (async () => {
      if (typeof WebAssembly !== 'object') throw new Error('this browser has no WebAssembly');
      return loadIk({ wasmBinary: decodeDataUrl(wasmDataUrl), locateFile: (path) => path });
    })();
    shared.catch(() => (shared = null));
  }
  return shared;
}
