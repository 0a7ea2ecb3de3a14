// The kinematics checks of the native suite, run again through the WebAssembly module in Node, on
// the project's rigs and the report's A7 rigs (tests/helpers/a7.ts).
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import {
  loadA7,
  loadTestRig,
  maxAbs,
  maxAbsDiff,
  needsA7,
  randomAngles,
  referenceTips,
  rigsLike,
  seeded,
  testRigs,
  type TestRig,
} from '../helpers/a7.js';

let ik: IkCoreModule;
const rigs: IkRig[] = [];

beforeAll(async () => {
  ik = await loadIkNode();
});

afterAll(() => rigs.forEach((r) => r.dispose()));

function rigOf(testRig: TestRig): IkRig {
  const rig = new IkRig(ik, loadTestRig(testRig));
  rigs.push(rig);
  return rig;
}

/** Central differences of rig.tips in JS, step h degrees, no clamping; row-major like jacobian(). */
function centralDifferences(rig: IkRig, a: Float64Array, h: number): Float64Array {
  const rows = 3 * rig.numEffectors,
    cols = rig.numAngles;
  const jac = new Float64Array(rows * cols);
  for (let j = 0; j < cols; j++) {
    const p = a.slice(),
      m = a.slice();
    p[j] += h;
    m[j] -= h;
    const tp = rig.tips(p),
      tm = rig.tips(m);
    for (let r = 0; r < rows; r++) jac[r * cols + j] = (tp[r] - tm[r]) / (2 * h);
  }
  return jac;
}

function expectJacobianMatches(rig: IkRig, a: Float64Array, what: string): void {
  const jac = rig.jacobian(a);
  const fd = centralDifferences(rig, a, 1e-3);
  expect(maxAbsDiff(jac, fd) / maxAbs(fd), what).toBeLessThan(1e-6);
}

describe.each(testRigs)('$label through WebAssembly', (testRig) => {
  it('forward kinematics matches the reference 4x4 composition to 1e-12 relative', () => {
    const rig = rigOf(testRig);
    const rand = seeded(11);
    for (let s = 0; s < 100; s++) {
      const a = randomAngles(rig.spec, rand);
      const ref = referenceTips(rig.spec, a);
      expect(maxAbsDiff(rig.tips(a), ref)).toBeLessThanOrEqual(1e-12 * Math.max(1, maxAbs(ref)));
    }
  });

  it('the analytic Jacobian matches central differences at random poses', () => {
    const rig = rigOf(testRig);
    const rand = seeded(12);
    for (let s = 0; s < 20; s++) expectJacobianMatches(rig, randomAngles(rig.spec, rand), `random ${s}`);
  });

  it('the analytic Jacobian matches central differences on the limits', () => {
    const rig = rigOf(testRig);
    const rand = seeded(13);
    for (let s = 0; s < 10; s++) {
      const a = new Float64Array(rig.numAngles);
      for (let i = 0; i < a.length; i++)
        a[i] = rand() < 0.5 ? Math.max(rig.lower[i], -720) : Math.min(rig.upper[i], 720);
      expectJacobianMatches(rig, a, `limits ${s}`);
    }
  });

  it('the analytic Jacobian matches central differences at middle angle 0 (XZX singular)', () => {
    const rig = rigOf(testRig);
    const rand = seeded(14);
    for (let s = 0; s < 10; s++) {
      const a = randomAngles(rig.spec, rand);
      for (let b = 0; b < rig.numBones; b++) a[3 * b + 1] = 0;
      expectJacobianMatches(rig, a, `middle 0, ${s}`);
    }
  });

  it('the gradient is J^T r and E is half the squared tip error', () => {
    const rig = rigOf(testRig);
    const rand = seeded(15);
    const target = rig.tips(randomAngles(rig.spec, rand));
    const a = randomAngles(rig.spec, rand);
    const r = rig.tips(a).map((x, i) => x - target[i]);
    expect(rig.objective(a, target)).toBeCloseTo(0.5 * r.reduce((s, x) => s + x * x, 0), 12);
    const jac = rig.jacobian(a),
      g = rig.gradient(a, target);
    const cols = rig.numAngles;
    for (let j = 0; j < cols; j++) {
      let gj = 0;
      for (let i = 0; i < r.length; i++) gj += jac[i * cols + j] * r[i];
      expect(g[j]).toBeCloseTo(gj, 12);
    }
  });
});

describe.each(rigsLike('knight'))('the WebAssembly rig API on $label', (testRig) => {
  it('keeps bone poses consistent with tips', () => {
    const rig = rigOf(testRig);
    const a = randomAngles(rig.spec, seeded(16));
    const poses = rig.poses(a),
      boneTips = rig.boneTips(a),
      tips = rig.tips(a);
    rig.spec.effectors.forEach((b, k) => {
      // tip = T_b * rest_b * (length, 0, 0)
      const T = poses.subarray(16 * b, 16 * b + 16),
        R = rig.spec.rest.subarray(16 * b, 16 * b + 16);
      const l = rig.spec.lengths[b];
      for (let r = 0; r < 3; r++) {
        let v = T[4 * r + 3];
        for (let c = 0; c < 3; c++) v += T[4 * r + c] * (R[4 * c] * l + R[4 * c + 3]);
        expect(v).toBeCloseTo(tips[3 * k + r], 12);
        expect(boneTips[3 * b + r]).toBeCloseTo(tips[3 * k + r], 14);
      }
    });
  });

  it('turns bad input into errors that name the problem', () => {
    const rig = rigOf(testRig);
    const m = rig.numAngles,
      r = 3 * rig.numEffectors;
    expect(() => rig.tips(new Float64Array(5))).toThrow(`angles has 5 values, expected ${m}`);
    const a = new Float64Array(m);
    a[4] = NaN;
    expect(() => rig.tips(a)).toThrow('angles[4] is NaN, not a finite number');
    expect(() => rig.objective(new Float64Array(m), new Float64Array(r).fill(Infinity))).toThrow(
      'target[0] is Infinity, not a finite number',
    );
    expect(() => rig.setEffectors([3, 99])).toThrow('end effector 1 is bone 99, which is not a bone');
    expect(Array.from(rig.effectors())).toEqual(Array.from(rig.spec.effectors));
    const spec = loadTestRig(testRig);
    spec.parents[2] = 4;
    spec.parents[4] = 2;
    expect(() => new IkRig(ik, spec)).toThrow('parent chain has a cycle');
    const scaled = loadTestRig(testRig);
    scaled.rest[16 * 2] = 2;
    expect(() => new IkRig(ik, scaled)).toThrow(/bone 2( "[^"]*")?: rest_T is not rigid/); // with its name, if any
    const inverted = loadTestRig(testRig);
    inverted.lower[4] = inverted.upper[4] + 50;
    expect(() => new IkRig(ik, inverted)).toThrow(`has min ${inverted.lower[4]} > max ${inverted.upper[4]}`);
    const short = loadTestRig(testRig);
    short.lengths = new Float64Array(2);
    expect(() => new IkRig(ik, short)).toThrow(`lengths has 2 values, expected ${rig.numBones}`);
  });

  it('changes end effectors and refuses use after dispose', () => {
    const spec = loadTestRig(testRig);
    const rig = new IkRig(ik, spec);
    const m = rig.numAngles;
    rig.setEffectors([spec.effectors[0], spec.effectors[1]]);
    expect(rig.numEffectors).toBe(2);
    expect(rig.tips(new Float64Array(m)).length).toBe(6);
    expect(rig.jacobian(new Float64Array(m)).length).toBe(6 * m);
    rig.dispose();
    rig.dispose();
    expect(() => rig.tips(new Float64Array(m))).toThrow('disposed');
  });
});

describe.each(rigsLike('ikea-lamp'))('limits through WebAssembly on $label', (testRig) => {
  it('clamps with project() and reports limits', () => {
    const rig = rigOf(testRig);
    for (const value of [500, -500]) {
      const p = rig.project(new Float64Array(rig.numAngles).fill(value));
      p.forEach((x, i) => expect(x).toBe(Math.min(rig.spec.upper[i], Math.max(rig.spec.lower[i], value))));
    }
    expect(Array.from(rig.lower)).toEqual(Array.from(rig.spec.lower));
    expect(Array.from(rig.upper)).toEqual(Array.from(rig.spec.upper));
  });

  it('the paper finite-difference Jacobian is clamped at the limits', () => {
    const rig = rigOf(testRig);
    const a = rig.project(rig.upper.map((x) => Math.min(x, 720)));
    const fd = rig.finiteDifferenceJacobian(a, 1e-7, true);
    const jac = rig.jacobian(a);
    const cols = rig.numAngles;
    for (let j = 0; j < cols; j++)
      for (let r = 0; r < 3; r++) {
        if (rig.lower[j] === rig.upper[j]) expect(fd[r * cols + j]).toBe(0);
        else expect(Math.abs(fd[r * cols + j] - jac[r * cols + j])).toBeLessThan(1e-6 * maxAbs(jac));
      }
  });
});

it("clamps the report's lamp at the limits its file gives", needsA7, () => {
  const rig = new IkRig(ik, loadA7('ikea-lamp'));
  rigs.push(rig);
  const p = rig.project(new Float64Array(rig.numAngles).fill(500));
  expect(p[3]).toBe(90);
  expect(p[7]).toBe(120);
  expect(p[0]).toBe(0);
  expect(rig.upper[3]).toBe(90);
});
