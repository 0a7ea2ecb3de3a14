// The project's rigs in A7 format (wasm/tests/rigs, read by the native tests and by the tests that
// run on every rig) are exactly what scripts/write-test-rigs.ts writes from the current models.
import { readdirSync, readFileSync } from 'node:fs';
import { resolve } from 'node:path';

import { describe, expect, it } from 'vitest';

import { testRigNames, testRigsDir, testRigText } from '../../scripts/write-test-rigs.js';

describe('wasm/tests/rigs', () => {
  it.each(testRigNames)('%s.json is what the script writes from web/public/models', async (name) => {
    const committed = readFileSync(resolve(testRigsDir, `${name}.json`), 'utf8');
    const fresh = await testRigText(name);
    expect(committed === fresh, `${name}.json differs from the model: run npx tsx scripts/write-test-rigs.ts`).toBe(true);
  });

  it('holds no other file', () => {
    expect(readdirSync(testRigsDir).sort()).toEqual(testRigNames.map((n) => `${n}.json`).sort());
  });
});
