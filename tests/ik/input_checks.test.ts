// Careless input to the rig API gets an Error that names the bad entry instead of a silent wrong
// answer: a NaN angle is not "clamped" to NaN, and a fractional or NaN effector is not truncated
// to some bone. The rig is unchanged after a refused call.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { loadRig } from '../../web/src/rig/load_rig.js';
import { testCharacterGlb } from '../../scripts/rig_files/gltf_character.js';

let ik: IkCoreModule;
let rig: IkRig;

beforeAll(async () => {
  ik = await loadIkNode();
  rig = new IkRig(ik, (await loadRig(await testCharacterGlb(), 'test-character.glb')).spec);
});

afterAll(() => rig?.dispose());

describe('the rig API refuses careless numbers', () => {
  it('project: a non-finite angle is an error naming it, not a NaN pose', () => {
    for (const bad of [NaN, Infinity, -Infinity]) {
      const angles = new Float64Array(rig.numAngles);
      angles[4] = bad;
      expect(() => rig.project(angles)).toThrow(`angles[4] is ${String(bad)}, not a finite number`);
    }
    expect(rig.project(new Float64Array(rig.numAngles)).every(Number.isFinite)).toBe(true);
  });

  it('setEffectors: fractions, NaN and out-of-range indices are errors; the old list stays', () => {
    const before = Array.from(rig.effectors());
    for (const bad of [[NaN], [3.7], [-1], [rig.numBones], [0, 1e10], [2 ** 32 + 1]]) {
      expect(() => rig.setEffectors(bad), JSON.stringify(bad)).toThrow(
        /not an integer index|is not a bone|listed twice/,
      );
      expect(Array.from(rig.effectors())).toEqual(before);
    }
    rig.setEffectors([0, 1]);
    expect(Array.from(rig.effectors())).toEqual([0, 1]);
    rig.setEffectors(before);
  });
});
