// Node-only helper over loadRig: reads the file (and a .gltf's side buffers) from disk.
// Kept apart from load_rig.ts so the browser bundle never imports node:fs.
import { readFile } from 'node:fs/promises';
import { dirname, resolve } from 'node:path';

import { loadRig, RigFormatError, type LoadedRig } from './load_rig.js';

/** Loads the rig at `path` (.json, .glb or .gltf). Throws RigFormatError naming the file. */
export async function loadRigFromPath(path: string): Promise<LoadedRig> {
  let bytes: Uint8Array;
  try {
    bytes = await readFile(path);
  } catch (e) {
    throw new RigFormatError(`${path}: cannot read the file: ${(e as Error).message}`);
  }
  const dir = dirname(path);
  return loadRig(bytes, path, async (uri) => new Uint8Array(await readFile(resolve(dir, uri))));
}
