// Generates the project's own rigs (web/public/models/*.glb): skinned low-poly meshes with IK
// metadata in extras (docs/gltf-ik-extras.md). Deterministic: the same code gives the same bytes,
// which tests/rig/models.test.ts checks against the committed files.
// Run: npm run models   (npx tsx scripts/generate-models.ts)
import { writeFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

import { WebIO } from '@gltf-transform/core';

import { beast } from './models/beast.js';
import { character } from './models/character.js';
import { hand } from './models/hand.js';
import { knight } from './models/knight.js';
import { lamp } from './models/lamp.js';
import { buildDocument, type ModelDef } from './models/model.js';
import { robotArm } from './models/robot_arm.js';

export const modelDefs: ModelDef[] = [lamp, robotArm, knight, hand, beast, character];

/** Where the generated files go. */
export const modelsDir = resolve(fileURLToPath(new URL('.', import.meta.url)), '../web/public/models');

/** Every model as GLB bytes, keyed by file name ("lamp.glb"). */
export async function buildModels(): Promise<Map<string, Uint8Array>> {
  const io = new WebIO();
  const out = new Map<string, Uint8Array>();
  for (const def of modelDefs) out.set(`${def.name}.glb`, await io.writeBinary(buildDocument(def)));
  return out;
}

if (process.argv[1] && import.meta.url === pathToFileURL(resolve(process.argv[1])).href) {
  for (const [name, bytes] of await buildModels()) {
    writeFileSync(resolve(modelsDir, name), bytes);
    console.log(`${name}: ${bytes.byteLength} bytes`);
  }
}
