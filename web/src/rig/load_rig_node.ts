// Node-only helper over loadRig: reads the file (and a .gltf's side buffers, confined to its
// folder: side_files.ts) from disk. Kept apart from load_rig.ts so the browser bundle never
// imports node:fs.
import { dirname } from 'node:path';

import { loadRig, RigFormatError, type LoadedRig, type LoadRigOptions } from './load_rig.js';
import { readRegularFile, sideFileReader } from './side_files.js';

/**
 * Loads the rig at `path` (.json, .glb, .gltf or .urdf; a regular file of at most MAX_RIG_FILE_BYTES);
 * `options` as loadRig takes them. Throws RigFormatError naming the file.
 */
export async function loadRigFromPath(path: string, options: LoadRigOptions = {}): Promise<LoadedRig> {
  let bytes: Uint8Array;
  try {
    bytes = await readRegularFile(path);
  } catch (e) {
    throw new RigFormatError(`${path}: cannot read the file: ${(e as Error).message}`);
  }
  return loadRig(bytes, path, sideFileReader(dirname(path)), options);
}
