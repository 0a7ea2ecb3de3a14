// loadRig / loadRigFromPath on A7 files (the project's rigs and the report's): same tips as
// PROTOCOL.md's composition.
import { readFileSync } from 'node:fs';

import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { loadRig, rigBaseName } from '../../web/src/rig/load_rig.js';
import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';
import { loadTestRig, maxAbs, maxAbsDiff, randomAngles, referenceTips, seeded, testRigs } from '../helpers/a7.js';

let ik: IkCoreModule;
const rigs: IkRig[] = [];
beforeAll(async () => {
  ik = await loadIkNode();
});
afterAll(() => rigs.forEach((r) => r.dispose()));

describe.each(testRigs)('loadRig on the A7 file of $label', (testRig) => {
  it('gives the parseA7Rig spec and the reference tips', async () => {
    const { name, path } = testRig;
    const loaded = await loadRig(new Uint8Array(readFileSync(path)), `some/dir/${name}.JSON`);
    expect(loaded.format).toBe('a7');
    expect(loaded.name).toBe(name);
    expect(loaded.gltf).toBeUndefined();
    expect(loaded.spec).toEqual({ ...loadTestRig(testRig), names: loaded.spec.names });
    const rig = new IkRig(ik, loaded.spec);
    rigs.push(rig);
    const rand = seeded(21);
    for (let s = 0; s < 50; s++) {
      const a = randomAngles(loaded.spec, rand);
      const ref = referenceTips(loaded.spec, a);
      expect(maxAbsDiff(rig.tips(a), ref)).toBeLessThanOrEqual(1e-12 * Math.max(1, maxAbs(ref)));
    }
    expect((await loadRigFromPath(path)).spec).toEqual(loaded.spec);
  });
});

describe('rig file names', () => {
  it('takes the base name without directory and extension', () => {
    expect(rigBaseName('web/public/models/robot-arm.glb')).toBe('robot-arm');
    expect(rigBaseName('C:\\rigs\\knight.json')).toBe('knight');
    expect(rigBaseName('.hidden')).toBe('.hidden');
  });
});
