// Writes the project's own rigs in A7 format to build/test-rigs/NAME.json, and the list of their
// names to build/test-rigs/names.txt, for the native tests (which cannot read .glb) and the
// TypeScript tests that run on both rig sets: each web/public/models/NAME.glb read by
// loadRigFromPath and written by web/src/rig/a7/a7_writer.ts. A build product, never committed:
// `npm test` writes them before the native tests, and vitest's global setup before its suites, so
// they always follow the current models and importer.
//   npx tsx scripts/write-test-rigs.ts
import { mkdirSync, writeFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

import { writeA7Rig } from '#rig/a7/a7_writer.js';
import { loadRigFromPath } from '#rig/load_rig_node.js';
import { projectRigNames } from '../bench-node/rigs.js';

const root = resolve(fileURLToPath(new URL('.', import.meta.url)), '..');

/** Where the A7 files go. */
export const testRigsDir = resolve(root, 'build/test-rigs');

/**
 * Writes every project model as A7 JSON into testRigsDir, then the list of their base names
 * (projectRigNames, one a line) to testRigsDir/names.txt, which the native tests read; returns the
 * rig files' paths.
 */
export async function writeTestRigs(): Promise<string[]> {
  mkdirSync(testRigsDir, { recursive: true });
  const paths: string[] = [];
  for (const name of projectRigNames) {
    const { spec } = await loadRigFromPath(resolve(root, `web/public/models/${name}.glb`));
    const path = resolve(testRigsDir, `${name}.json`);
    writeFileSync(path, `${writeA7Rig(spec)}\n`);
    paths.push(path);
  }
  writeFileSync(resolve(testRigsDir, 'names.txt'), projectRigNames.map((name) => `${name}\n`).join(''));
  return paths;
}

if (process.argv[1] && import.meta.url === pathToFileURL(resolve(process.argv[1])).href) {
  for (const path of await writeTestRigs()) console.log(path);
}
