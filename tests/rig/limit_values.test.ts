// Joint limits read from files (limit_degrees.ts, the core's rule): past +-36000 degrees a limit
// means unbounded only in its own direction, so xzx_min = xzx_max = [1e9, 0, 0] (which used to
// become +Infinity and make every solve end in numerical_failure) is refused naming the node and
// the field. The same rule holds for A7 files, which keep -1e10 as written.
import { beforeAll, describe, expect, it } from 'vitest';

import { loadRig } from '../../web/src/rig/load_rig.js';
import { isUnbounded, limitProblem } from '../../web/src/rig/limit_degrees.js';
import { nodeIndex, packGlb, unpackGlb } from '../../scripts/rig_files/glb.js';
import { testCharacterGlb } from '../../scripts/rig_files/gltf_character.js';
import { chainParents, treeA7 } from '../../scripts/rig_files/tree_rigs.js';
import { loadError } from './synthetic_rigs.js';

let glb: Uint8Array;
beforeAll(async () => {
  glb = await testCharacterGlb();
});

/** The test character with `ik` as extras.ik of forearm.L. */
function withIk(ik: unknown): Uint8Array {
  const { json, bin } = unpackGlb(glb);
  json.nodes[nodeIndex(json, 'forearm.L')].extras = { ik };
  return packGlb(json, bin);
}

async function forearmLimits(ik: unknown): Promise<[number[], number[]]> {
  const rig = await loadRig(withIk(ik), 'x.glb');
  const b = rig.spec.names.indexOf('forearm.L');
  return [Array.from(rig.spec.lower.subarray(3 * b, 3 * b + 3)), Array.from(rig.spec.upper.subarray(3 * b, 3 * b + 3))];
}

describe('joint limits in glTF extras.ik', () => {
  it('refuses a lower limit of 1e9 (it would be +Infinity), naming the node and the field', async () => {
    expect(await loadError(withIk({ xzx_min: [1e9, 0, 0], xzx_max: [1e9, 0, 0] }), 'x.glb')).toMatch(
      /^x\.glb: node \d+ "forearm\.L": extras\.ik\.xzx_min\[0\] = 1000000000 degrees leaves no angle within \+-36000 degrees: a lower limit below -36000 means unbounded$/,
    );
    expect(await loadError(withIk({ xzx_max: [0, -36001, 0] }), 'x.glb')).toContain(
      'extras.ik.xzx_max[1] = -36001 degrees leaves no angle within +-36000 degrees: an upper limit above 36000 means unbounded',
    );
  });

  it('reads limits past +-36000 in their own direction, and null, as unbounded', async () => {
    expect(await forearmLimits({ xzx_min: [-1e9, null, -36000], xzx_max: [36001, null, 36000] })).toEqual([
      [-Infinity, -Infinity, -36000],
      [Infinity, Infinity, 36000],
    ]);
  });

  it('states the rule in one place', () => {
    expect(isUnbounded(-36000.5, 'min')).toBe(true);
    expect(isUnbounded(36000, 'max')).toBe(false);
    expect(limitProblem(-1e10, 'min')).toBeUndefined();
    expect(limitProblem(Infinity, 'max')).toBeUndefined();
    expect(limitProblem(36000, 'min')).toBeUndefined();
    expect(limitProblem(36000.5, 'min')).toContain('leaves no angle');
    expect(limitProblem(-Infinity, 'max')).toContain('leaves no angle');
  });
});

describe('joint limits in A7 files', () => {
  const rig = (bone: Record<string, unknown>): string => treeA7(chainParents(2), bone);

  it('keeps 1e10 as written (unbounded) and refuses it as a lower limit', async () => {
    const loaded = await loadRig(
      new TextEncoder().encode(rig({ xzx_min: [-1e10, -90, 0], xzx_max: [1e10, 90, 0] })),
      'a.json',
    );
    expect(Array.from(loaded.spec.lower.subarray(0, 3))).toEqual([-1e10, -90, 0]);
    expect(Array.from(loaded.spec.upper.subarray(0, 3))).toEqual([1e10, 90, 0]);
    expect(await loadError(rig({ xzx_min: [1e10, 0, 0], xzx_max: [1e10, 0, 0] }), 'a.json')).toBe(
      'a.json: bones[0].xzx_min[0] = 10000000000 degrees leaves no angle within +-36000 degrees: a lower limit below -36000 means unbounded',
    );
  });

  it('refuses a lower limit above the upper one, and a limit that is no number', async () => {
    expect(await loadError(rig({ xzx_min: [0, 90, 0], xzx_max: [0, 10, 0] }), 'a.json')).toBe(
      'a.json: bones[0].xzx_min[1] = 90 is above xzx_max[1] = 10',
    );
    expect(await loadError(rig({ xzx_max: [0, '10', 0] }), 'a.json')).toBe(
      'a.json: bones[0].xzx_max[1] is not a number (degrees)',
    );
  });
});
