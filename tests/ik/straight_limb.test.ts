// Through WebAssembly, as the page calls it while a user drags (restarts 0, a tip tolerance):
// a straight two-bone limb whose target moves along it towards its root bends and reaches the
// target; a target past its length ends at the closest point, reported as not reached; and the
// result's stop reason, `reached` and `tipDistance` describe the returned angles.
import { beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import { IkSolver } from '../../web/src/ik/solver.js';
import { disposeAfterAll } from '../helpers/owned.js';

let ik: IkCoreModule;
const keep = disposeAfterAll();

beforeAll(async () => {
  ik = await loadIkNode();
});
const methods = IkSolver.methods(await loadIkNode());

/** Two bones of length 1 along +x from the origin, limits +-180 degrees; effector: the second tip (2, 0, 0). */
function straightLimb(): RigSpec {
  const identity = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
  const shifted = [1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
  return {
    names: ['upper', 'lower'],
    parents: Int32Array.from([-1, 0]),
    rest: Float64Array.from([...identity, ...shifted]),
    lengths: Float64Array.from([1, 1]),
    lower: new Float64Array(6).fill(-180),
    upper: new Float64Array(6).fill(180),
    effectors: Int32Array.from([1]),
  };
}

const TOLERANCE = 1e-4;
const dragOptions = { restarts: 0, tipTolerance: TOLERANCE, gradientTolerance: 1e-12, timeBudgetSeconds: 0 };

function distance(a: ArrayLike<number>, b: ArrayLike<number>): number {
  return Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

describe.each(methods)('%s on a straight limb, restarts off', (method) => {
  it('bends and reaches a target moved along the limb towards its root', () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    const solver = keep(new IkSolver(rig, method, dragOptions));
    for (const along of [0.01, 0.3]) {
      const target = [2 - along, 0, 0];
      const r = solver.solve(new Float64Array(6), target);
      expect(r.stopReason).toBe('converged_E');
      expect(r.reached).toBe(true);
      expect(r.restarts).toBe(0);
      expect(r.escapes).toBeGreaterThanOrEqual(1);
      const tip = rig.tips(r.angles);
      expect(distance(tip, target)).toBeLessThan(TOLERANCE);
      expect(r.tipDistance).toBeCloseTo(distance(tip, target), 12);
    }
  });

  it('stays straight without the escape (the behaviour it replaces)', () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    const solver = keep(new IkSolver(rig, method, { ...dragOptions, escapeSaddles: false, chainRestarts: 0 }));
    const r = solver.solve(new Float64Array(6), [1.8, 0, 0]);
    expect(r.stopReason).toBe('converged_grad');
    expect(r.reached).toBe(false);
    expect(r.iterations).toBe(0);
  });

  it('ends a target past the limb at the closest point, not reached', () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    const solver = keep(new IkSolver(rig, method, { ...dragOptions, gradientTolerance: 1e-9 }));
    const target = [1.5, 2.5, 0];
    const r = solver.solve(new Float64Array(6), target);
    expect(r.reached).toBe(false);
    expect(r.stopReason).not.toBe('converged_E');
    expect(r.tipDistance).toBeCloseTo(Math.hypot(1.5, 2.5) - 2, 3);
  });
});

describe('the result describes the returned point', () => {
  it('reached, tipDistance, E and the stop reason agree with forward kinematics, restarts on', () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    for (const options of [
      { errorTolerance: 1e-6, tipTolerance: 0 },
      { errorTolerance: 1e-6, tipTolerance: 1e-3 },
    ]) {
      const solver = keep(
        new IkSolver(rig, 'lm', { ...options, restarts: 3, stallIterations: 3, timeBudgetSeconds: 0 }),
      );
      for (const target of [
        [0.5, 1, 0.2],
        [1000, 0, 0],
        [0, 0, 2.5],
        [-1.9, 0.1, 0],
      ]) {
        const r = solver.solve(new Float64Array(6), target);
        const tip = rig.tips(r.angles);
        const d = distance(tip, target);
        expect(r.tipDistance).toBeCloseTo(d, 9);
        expect(r.E).toBeCloseTo(rig.objective(r.angles, target), 12);
        const onTarget = options.tipTolerance > 0 ? d < options.tipTolerance : r.E < options.errorTolerance;
        expect(r.reached).toBe(onTarget);
        expect(r.stopReason === 'converged_E').toBe(r.reached);
        if (r.stopReason === 'converged_grad') expect(r.gradNorm).toBeLessThan(1e-4);
      }
    }
  });
});
