// Writes the project's own rigs in A7 format to wasm/tests/rigs/NAME.json, for the native tests
// (which cannot read .glb) and the TypeScript tests that run on both rig sets: each
// web/public/models/NAME.glb read by loadRigFromPath and written by bench-node/a7_writer.ts.
// tests/rig/test_rigs.test.ts checks the committed files against what this writes now.
// Re-run after the models (npm run models) or the glTF importer change:
//   npx tsx scripts/write-test-rigs.ts
import { writeFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

import { writeA7Rig } from '../bench-node/a7_writer.js';
import { loadRigFromPath } from '../web/src/rig/load_rig_node.js';

/** The project models written, by base name. */
export const testRigNames = ['knight', 'lamp', 'robot-arm', 'hand', 'beast', 'character'] as const;

const root = resolve(fileURLToPath(new URL('.', import.meta.url)), '..');

/** Where the A7 files go. */
export const testRigsDir = resolve(root, 'wasm/tests/rigs');

/** The A7 text of the project model `name` as it loads today. */
export async function testRigText(name: string): Promise<string> {
  const { spec } = await loadRigFromPath(resolve(root, `web/public/models/${name}.glb`));
  return `${writeA7Rig(spec)}\n`;
}

if (process.argv[1] && import.meta.url === pathToFileURL(resolve(process.argv[1])).href) {
  for (const name of testRigNames) {
    const text = await testRigText(name);
    writeFileSync(resolve(testRigsDir, `${name}.json`), text);
    console.log(`wasm/tests/rigs/${name}.json: ${text.length} bytes`);
  }
}
