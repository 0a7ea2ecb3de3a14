// The fuzz run's scratch folder: a sentinel file outside every model folder, and one model
// folder per worker inside it (root/model-<n>/), so "../sentinel.bin" from a model is the sentinel.
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

import { CHARACTER, identityBindBuffer, loadGltfBases } from './gltf_bases.js';

export interface Fixture {
  root: string;
  /** Absolute path of the sentinel: the test character's buffer with identity bind matrices. */
  sentinel: string;
}

/** Makes the scratch folder and the sentinel. */
export async function createFixture(): Promise<Fixture> {
  const root = mkdtempSync(join(tmpdir(), 'ik-fuzz-'));
  const sentinel = join(root, 'sentinel.bin');
  const character = (await loadGltfBases()).find((b) => b.name === CHARACTER)!;
  writeFileSync(sentinel, identityBindBuffer(character));
  return { root, sentinel };
}

/** The model folder of worker `worker`. */
export function modelFolder(fixture: Fixture, worker: number): string {
  return join(fixture.root, `model-${worker}`);
}

/** Deletes the scratch folder. */
export function removeFixture(fixture: Fixture): void {
  rmSync(fixture.root, { recursive: true, force: true });
}
