// The glTF inputs mutations start from: the project's models (web/public/models/*.glb) and the
// Blender-style test character, each as JSON and BIN chunk.
import { readdirSync, readFileSync } from 'node:fs';
import { join, resolve } from 'node:path';

import { unpackGlb, type Json } from '../rig_files/glb.js';
import { testCharacterGlb } from '../rig_files/gltf_character.js';

export interface GltfBase {
  name: string;
  json: Json;
  bin: Uint8Array;
}

const modelsDir = resolve(import.meta.dirname, '../../web/public/models');

/** The name of the test character among the bases (the uri cases use it: the sentinel is its buffer). */
export const CHARACTER = 'test-character.glb';

/** Every base, the test character last. */
export async function loadGltfBases(): Promise<GltfBase[]> {
  const models = readdirSync(modelsDir)
    .filter((f) => f.endsWith('.glb'))
    .sort()
    .map((name) => ({ name, ...unpackGlb(readFileSync(join(modelsDir, name))) }));
  return [...models, { name: CHARACTER, ...unpackGlb(await testCharacterGlb()) }];
}

/**
 * `base`'s buffer with every skin's inverse bind matrices replaced by identities: a valid buffer
 * for its JSON whose bind matrices disagree with the pose, so a rig loaded from it carries a
 * "not in the bind pose" warning. The sentinel outside the model folder holds these bytes.
 */
export function identityBindBuffer(base: GltfBase): Uint8Array {
  const bin = base.bin.slice();
  const view = new DataView(bin.buffer);
  const accessors = base.json.accessors as Record<string, number>[];
  const views = base.json.bufferViews as Record<string, number>[];
  for (const skin of base.json.skins) {
    const accessor = accessors[skin.inverseBindMatrices as number];
    const bufferView = views[accessor.bufferView];
    const start = (bufferView.byteOffset ?? 0) + (accessor.byteOffset ?? 0),
      stride = bufferView.byteStride ?? 64;
    for (let j = 0; j < accessor.count; j++)
      for (let k = 0; k < 16; k++) view.setFloat32(start + stride * j + 4 * k, k % 5 === 0 ? 1 : 0, true);
  }
  return bin;
}
