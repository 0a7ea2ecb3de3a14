// loadRig / loadRigFromPath on the report's A7 rigs: same tips as PROTOCOL.md's composition.
import { readFileSync } from 'node:fs';

import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { loadRig, rigBaseName } from '../../web/src/rig/load_rig.js';
import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';
import { a7Names, a7Path, loadA7, maxAbs, maxAbsDiff, randomAngles, referenceTips, seeded } from '../helpers/a7.js';

let ik: IkCoreModule;
const rigs: IkRig[] = [];
beforeAll(async () => {
  ik = await loadIkNode();
});
afterAll(() => rigs.forEach((r) => r.dispose()));

describe.each(a7Names)('loadRig on A7 %s.json', (name) => {
  it('gives the parseA7Rig spec and the reference tips', async () => {
    const loaded = await loadRig(new Uint8Array(readFileSync(a7Path(name))), `some/dir/${name}.JSON`);
    expect(loaded.format).toBe('a7');
    expect(loaded.name).toBe(name);
    expect(loaded.gltf).toBeUndefined();
    expect(loaded.spec).toEqual({ ...loadA7(name), names: loaded.spec.names });
    const rig = new IkRig(ik, loaded.spec);
    rigs.push(rig);
    const rand = seeded(21);
    for (let s = 0; s < 50; s++) {
      const a = randomAngles(loaded.spec, rand);
      const ref = referenceTips(loaded.spec, a);
      expect(maxAbsDiff(rig.tips(a), ref)).toBeLessThanOrEqual(1e-12 * Math.max(1, maxAbs(ref)));
    }
    expect((await loadRigFromPath(a7Path(name))).spec).toEqual(loaded.spec);
  });
});

describe('rig file names', () => {
  it('takes the base name without directory and extension', () => {
    expect(rigBaseName('web/public/models/robot-arm.glb')).toBe('robot-arm');
    expect(rigBaseName('C:\\rigs\\knight.json')).toBe('knight');
    expect(rigBaseName('.hidden')).toBe('.hidden');
  });
});
