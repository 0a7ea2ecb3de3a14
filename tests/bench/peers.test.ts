// The peers' adapters: the XZX <-> quaternion mapping, the Euler box for CCD, the scene graphs
// reproducing our forward kinematics, and both peers solving easy targets.
import { Quaternion } from 'three';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { ClosedChainIkRunner } from '../../bench-node/peers/closed_chain_ik.js';
import { eulerBox, ThreeCcdRunner, xzxQuaternion } from '../../bench-node/peers/three_ccd.js';
import { xzxWithinLimits } from '../../web/src/rig/xzx_angles.js';
import type { RunSettings } from '../../bench-node/runner.js';
import { generateTargets } from '../../bench-node/targets.js';
import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { defaultTolerances, rigSize } from '../../web/src/rig/tolerances.js';
import { loadTestRig, seeded, testRigs, type TestRig } from '../helpers/a7.js';

let ik: IkCoreModule;
const rigs: IkRig[] = [];
beforeAll(async () => {
  ik = await loadIkNode();
});
afterAll(() => rigs.forEach((r) => r.dispose()));

describe('XZX angles from a rotation', () => {
  it('recovers any rotation, including b = 0 and b = 180, and in-limit angles exactly', () => {
    const rand = seeded(5);
    const out = new Float64Array(3);
    for (let i = 0; i < 2000; i++) {
      const a = [360 * rand() - 180, i % 4 === 0 ? 0 : i % 4 === 1 ? 180 : 360 * rand() - 180, 360 * rand() - 180];
      const q = xzxQuaternion(a[0], a[1], a[2]);
      xzxWithinLimits(q, [-1e10, -1e10, -1e10], [1e10, 1e10, 1e10], out);
      expect(1 - Math.abs(q.dot(xzxQuaternion(out[0], out[1], out[2])))).toBeLessThan(1e-12);
      const lo = a.map((v) => v - 2),
        hi = a.map((v) => v + 2);
      xzxWithinLimits(q, lo, hi, out);
      for (let k = 0; k < 3; k++) {
        expect(out[k]).toBeGreaterThanOrEqual(lo[k]);
        expect(out[k]).toBeLessThanOrEqual(hi[k]);
      }
      expect(1 - Math.abs(q.dot(xzxQuaternion(out[0], out[1], out[2])))).toBeLessThan(1e-12);
    }
  });

  it('clamps a rotation outside the limits into them', () => {
    const out = new Float64Array(3);
    xzxWithinLimits(xzxQuaternion(0, 50, 0), [0, -10, 0], [0, 30, 0], out);
    expect(Array.from(out)).toEqual([0, 30, 0]);
    xzxWithinLimits(xzxQuaternion(0, -170, 0), [0, -100, 0], [0, 10, 0], out); // -170 is nearer -100 than 10 + 360k
    expect(out[1]).toBeCloseTo(-100, 9);
  });
});

describe('Euler XYZ box for CCD', () => {
  const deg = Math.PI / 180;
  it('is exact for joints that turn about one axis', () => {
    const values = (...a: number[]): number[] => a.map((v) => v + 0); // -0 is 0 here
    const z = eulerBox([0, -60, 0], [0, 120, 0]);
    expect(values(z.min.x, z.min.y, z.min.z)).toEqual([0, 0, -60 * deg]);
    expect(values(z.max.x, z.max.y, z.max.z)).toEqual([0, 0, 120 * deg]);
    const x = eulerBox([-90, 0, 0], [90, 0, 0]);
    expect(values(x.min.x, x.max.x, x.min.z, x.max.z)).toEqual([-90 * deg, 90 * deg, 0, 0]);
  });

  it('wraps ranges of a full turn or more to [-pi, pi]', () => {
    const b = eulerBox([0, 0, -1e10], [0, 0, 1e10]);
    expect([b.min.x, b.max.x]).toEqual([-Math.PI, Math.PI]);
  });

  it('bounds the first-order XYZ angles of every XZX rotation inside the limits', () => {
    const lo = [-70, -30, -10],
      hi = [70, 100, 10];
    const box = eulerBox(lo, hi);
    expect(box.min.x).toBeCloseTo(-80 * deg, 12);
    expect(box.max.z).toBeCloseTo(100 * deg, 12);
    expect(box.max.y).toBeCloseTo(100 * deg * Math.sin(10 * deg), 12);
  });
});

/** The benchmark's settings for the random and incremental experiments (bench-node/rigs.ts). */
function settingsFor(testRig: TestRig, rig: IkRig, method: string): RunSettings {
  const size = rigSize(rig.boneTips(new Float64Array(rig.numAngles)));
  const { gradientTolerance, errorTolerance } = defaultTolerances(testRig.name, testRig.a7, size);
  return {
    method,
    gradientTolerance,
    errorTolerance,
    tipTolerance: 0,
    timeBudgetSeconds: 1,
    paper: false,
    rigSize: size,
  };
}

describe.each(testRigs)('peers on $label', (testRig) => {
  it.each(['three-ccd', 'closed-chain-ik'])(
    '%s: a solve from the target pose stops at once; incremental targets converge',
    (method) => {
      const spec = loadTestRig(testRig);
      const rig = new IkRig(ik, spec);
      rigs.push(rig);
      const settings = settingsFor(testRig, rig, method);
      const runner =
        method === 'three-ccd' ? new ThreeCcdRunner(spec, settings) : new ClosedChainIkRunner(spec, settings);
      const set = generateTargets(spec, 'incremental', 20, 3, (a) => rig.tips(a));
      const m = set.numAngles,
        r = set.numResiduals;
      let converged = 0,
        improved = 0;
      for (let k = 0; k < set.count; k++) {
        const target = set.targets.subarray(k * r, (k + 1) * r);
        // Started at the very angles the target was made from, the scene graph's tips are the target.
        const there = runner.solve({ start: set.targetAngles!.slice(k * m, (k + 1) * m), target, dragged: -1 });
        expect(there.iterations).toBe(0);
        expect(there.E).toBeLessThan(1e-9 * settings.rigSize ** 2);
        const result = runner.solve({ start: set.starts.slice(k * m, (k + 1) * m), target, dragged: -1 });
        expect(result.seconds).toBeGreaterThan(0);
        if (result.E < settings.errorTolerance) converged++;
        const E0 = rig.objective(set.starts.subarray(k * m, (k + 1) * m), target);
        if (result.E <= E0 * (1 + 1e-3) + 1e-9 * settings.rigSize ** 2) improved++; // float32 rounding (closed-chain-ik)
      }
      // Quality is the benchmark's business; here only that the adapters work: every solve ends no
      // worse than it started (to rounding), and most converge (CCD with its Euler box fails often on beast).
      expect(improved).toBe(set.count);
      expect(converged).toBeGreaterThanOrEqual(testRig.name === 'beast' && method === 'three-ccd' ? 1 : 12);
      runner.dispose();
    },
  );
});

it('CCD keeps quaternions of joints unit length', () => {
  const q = xzxQuaternion(10, 20, 30);
  expect(q.length()).toBeCloseTo(1, 14);
  expect(q).toBeInstanceOf(Quaternion);
});
