// A floating root through the JavaScript API (RigSpec.floatingRoot): the rig gets three more
// unknowns after its angles (the roots' translation, rig units, within the bounds given), every
// method reaches a target beyond the chain by moving the root and stops at its bounds, a rig
// without it keeps 3 unknowns per bone, and bad bounds are refused with an error naming them.
import { beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { IkSolver } from '../../web/src/ik/solver.js';
import { disposeAfterAll } from '../helpers/owned.js';
import { straightLimb } from '../../scripts/rig_files/rig_builder.js';

let ik: IkCoreModule;
const keep = disposeAfterAll();
beforeAll(async () => {
  ik = await loadIkNode();
});
const methods = IkSolver.methods(await loadIkNode());

/** The straight two-bone limb (tip (2, 0, 0) at rest) on a root free within [-1, 1] x [-0.5, 0.5] x [0, 3]. */
const floatingLimb = () => ({ ...straightLimb(), floatingRoot: { lower: [-1, -0.5, 0], upper: [1, 0.5, 3] } });

describe('a floating root', () => {
  it('adds three unknowns after the angles, bounded in rig units; without it, 3 per bone', () => {
    const fixed = keep(new IkRig(ik, straightLimb()));
    const rig = keep(new IkRig(ik, floatingLimb()));
    expect([fixed.numAngles, rig.numAngles]).toEqual([6, 9]);
    expect(Array.from(rig.lower.subarray(6))).toEqual([-1, -0.5, 0]);
    expect(Array.from(rig.upper.subarray(6))).toEqual([1, 0.5, 3]);
    expect(Array.from(rig.tips([0, 0, 0, 0, 0, 0, 0.25, -0.5, 2]))).toEqual([2.25, -0.5, 2]);
  });

  for (const method of methods)
    it(`${method} reaches past the limb by moving the root, and stops at its bounds`, () => {
      const rig = keep(new IkRig(ik, floatingLimb()));
      const solver = keep(new IkSolver(rig, method));
      solver.setOptions({ tipTolerance: 1e-4, timeBudgetSeconds: 2 });
      const start = new Float64Array(9);
      const reached = solver.solve(start, [2, 0.3, 2.5]); // 2.5 along z: the limb alone reaches 2
      expect(reached.reached).toBe(true);
      const tip = rig.tips(reached.angles);
      expect(Math.hypot(tip[0] - 2, tip[1] - 0.3, tip[2] - 2.5)).toBeLessThan(1e-4);
      const beyond = solver.solve(reached.angles, [2, 0.3, 6]); // root at most 3, limb 2: 5 at most
      expect(beyond.reached).toBe(false);
      expect(beyond.angles[8]).toBeLessThanOrEqual(3);
      expect(beyond.angles[8]).toBeGreaterThan(2.9);
    });

  it('refuses bounds that are not three finite numbers with min <= max, by name', () => {
    expect(() => new IkRig(ik, { ...straightLimb(), floatingRoot: { lower: [0, 0], upper: [1, 1, 1] } })).toThrow(
      /floatingRoot.lower \(x, y, z, rig units\) has 2 values, expected 3/,
    );
    expect(() => new IkRig(ik, { ...straightLimb(), floatingRoot: { lower: [0, NaN, 0], upper: [1, 1, 1] } })).toThrow(
      /floatingRoot.lower.*\[1\]/,
    );
    expect(() => new IkRig(ik, { ...straightLimb(), floatingRoot: { lower: [0, 2, 0], upper: [1, 1, 1] } })).toThrow(
      "floating root's y bounds have min > max",
    );
  });
});
