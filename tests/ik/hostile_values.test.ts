// Finite but hostile values through the TypeScript API: sizes, coordinates, tolerances, difference
// steps and soft weights the core refuses with an Error naming the field (wasm/src/size_limits.h),
// integer arguments checked as integers, relative goal weights, results that obey the documented
// rules, and a solver disposed while its input is read reporting just that.
import { beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import type { Goals } from '../../web/src/ik/goals.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { IkSolver, type SolverResult } from '../../web/src/ik/solver.js';
import { loadTestRig, testRigs } from '../helpers/a7.js';
import { disposeAfterAll } from '../helpers/owned.js';
import { straightLimb } from '../../scripts/rig_files/rig_builder.js';

let ik: IkCoreModule;
const keep = disposeAfterAll();

beforeAll(async () => {
  ik = await loadIkNode();
});

/** The rules of SolverResult: no NaN anywhere, converged_E exactly when reached. */
function expectClean(r: SolverResult, what: string): void {
  for (const key of ['E', 'initialE', 'gradNorm', 'tipDistance'] as const)
    expect(Number.isNaN(r[key]), `${what}: ${key}`).toBe(false);
  expect(r.angles.every(Number.isFinite), `${what}: angles`).toBe(true);
  expect(r.reached, `${what}: ${r.stopReason} ${r.message}`).toBe(r.stopReason === 'converged_E');
}

/** The limb's tip goal at (0.5, 1.2, 0.3), reachable, of weight `weight`. */
function limbGoals(weight = 1): Goals {
  return { effectors: [{ bone: 1, position: [0.5, 1.2, 0.3], weight }] };
}

describe('hostile values are refused naming the field', () => {
  it('rig sizes past 1e9 rig units, naming the bone', () => {
    const spec = straightLimb();
    expect(() => new IkRig(ik, { ...spec, lengths: Float64Array.of(1, 1e200) })).toThrow(
      'bone 1: length is 1e+200, more than 1e9 rig units (the largest size the core takes)',
    );
    const rest = Float64Array.from(spec.rest);
    rest[16 + 7] = -2e9; // bone 1's y translation
    expect(() => new IkRig(ik, { ...spec, rest })).toThrow(
      /bone 1: rest_T translation\[1\] is -2e\+09, past \+-1e9 rig units/,
    );
    const big = keep(
      new IkRig(ik, {
        ...spec,
        lengths: Float64Array.of(1e9, 1e9),
        rest: Float64Array.from(spec.rest, (x, i) => (i === 19 ? 1e9 : x)),
      }),
    );
    const g = big.gradient(new Float64Array(6).fill(10), [0, 1e9, 0]);
    expect(g.every(Number.isFinite)).toBe(true);
  });

  it('tolerances that can never be met, steps that read no slope, soft weights past 1000', () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    const cases: [object, RegExp][] = [
      [{ errorTolerance: 0 }, /solver option errorTolerance must be a number > 0 \(0 can never be met/],
      [
        { paperMode: true, fdStepDeg: 1e-300 },
        /solver option fdStepDeg must be in 1e-09\.\.1 \(degrees: smaller steps are lost to rounding/,
      ],
      [{ paperMode: true, fdStepDeg: 1e308 }, /solver option fdStepDeg must be in 1e-09\.\.1/],
      [{ restWeight: 1e80 }, /solver option restWeight must be in 0\.\.1000/],
    ];
    for (const [options, message] of cases) {
      const solver = keep(new IkSolver(rig, 'lm', options));
      expect(() => solver.solve(new Float64Array(6), [1, 1, 0]), JSON.stringify(options)).toThrow(message);
    }
  });

  it('targets, poles and stiffness past their caps', () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    const solver = keep(new IkSolver(rig, 'lm'));
    const zero = new Float64Array(6);
    expect(() => solver.solve(zero, [1e150, 0, 0])).toThrow('target[0] is 1e+150, past +-1e9 rig units');
    expect(() => solver.solve(zero, { ...limbGoals(), poles: [{ bone: 1, point: [1e308, 1e308, 1e308] }] })).toThrow(
      /the point of pole 0 has a coordinate past \+-1e9 rig units/,
    );
    expect(() => solver.solve(zero, { ...limbGoals(), poles: [{ bone: 1, point: [0, 1, 0], weight: 1e100 }] })).toThrow(
      /the weight of pole 0 must be a number in 0\.\.1000/,
    );
    solver.setOptions({ restWeight: 0.05 });
    expect(() => solver.solve(zero, { ...limbGoals(), stiffness: { 'bone 1': 1e308 } })).toThrow(
      /the stiffness of bone 1 must be a number in 0\.\.1000/,
    );
  });

  it('restartStart takes integers in range only, naming the argument', () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    for (const k of [2 ** 31, 2 ** 32 + 1, '3', 1.5, 0, NaN])
      expect(() => rig.restartStart(k as number), String(k)).toThrow(
        /restartStart: the restart index k must be an integer in 1\.\.2147483647/,
      );
    for (const seed of [2 ** 32, -1, '1', 0.5])
      expect(() => rig.restartStart(1, seed as number), String(seed)).toThrow(
        /restartStart: the seed must be an integer in 0\.\.4294967295/,
      );
    expect(rig.restartStart(2 ** 31 - 1, 2 ** 32 - 1).every(Number.isFinite)).toBe(true);
  });
});

describe('accepted values at the edges still obey the rules', () => {
  it('goal weights are relative: 1e10 on every goal reaches like 1 (every method)', () => {
    const spec = loadTestRig(testRigs.find((r) => r.name === 'character')!);
    const rig = keep(new IkRig(ik, spec));
    const tips = rig.tips(new Float64Array(rig.numAngles).fill(10));
    const goals = (weight: number): Goals => ({
      effectors: Array.from(rig.effectors(), (bone, e) => ({
        bone,
        position: tips.subarray(3 * e, 3 * e + 3),
        weight,
      })),
    });
    for (const method of IkSolver.methods(ik)) {
      const solver = keep(new IkSolver(rig, method, { timeBudgetSeconds: 0, maxIterations: 5000 }));
      const plain = solver.solve(new Float64Array(rig.numAngles), tips);
      for (const weight of [1e10, 1e-10]) {
        const r = solver.solve(new Float64Array(rig.numAngles), goals(weight));
        expectClean(r, `${method} weight ${weight}`);
        expect(r.reached, `${method} weight ${weight}: ${r.stopReason}`).toBe(true);
        expect(r.restarts).toBe(plain.restarts);
      }
    }
  });

  it('soft weights at their cap never cost a reachable goal (every method)', () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    const start = new Float64Array(6).fill(10);
    for (const method of IkSolver.methods(ik)) {
      const solver = keep(new IkSolver(rig, method, { timeBudgetSeconds: 0, restWeight: 1000 }));
      const cases: [string, Goals][] = [
        ['rest weight and stiffness 1000', { ...limbGoals(), stiffness: { 'bone 0': 1000, 'bone 1': 1000 } }],
        [
          'a pole of weight 1000 at 1e9',
          { ...limbGoals(), poles: [{ bone: 1, point: [1e9, 1e9, 1e9], weight: 1000 }] },
        ],
      ];
      for (const [what, goals] of cases) {
        const r = solver.solve(start, goals);
        expectClean(r, `${method}, ${what}`);
        expect(r.reached, `${method}, ${what}: ${r.stopReason} ${r.message}`).toBe(true);
      }
    }
  });

  it('a target at the coordinate cap ends near the closest point, not in a numerical failure', () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    for (const method of IkSolver.methods(ik)) {
      const r = keep(new IkSolver(rig, method, { timeBudgetSeconds: 0 })).solve(
        new Float64Array(6).fill(10),
        [0, 1e9, 0],
      );
      expectClean(r, method);
      expect(['converged_grad', 'zero_step'], method).toContain(r.stopReason);
      expect(r.tipDistance - (1e9 - 2), method).toBeLessThan(0.1);
    }
  });
});

describe('a solver disposed while its input is read', () => {
  /** A target array whose reading disposes `solver` (a Proxy's get trap). */
  function disposingTarget(solver: IkSolver): number[] {
    return new Proxy([1, 1, 0], {
      get(t, key, receiver) {
        if (key === '0') solver.dispose();
        return Reflect.get(t, key, receiver) as unknown;
      },
    });
  }

  it("says it was disposed, not embind's BindingError", () => {
    const rig = keep(new IkRig(ik, straightLimb()));
    const zero = new Float64Array(6);
    // Goals handed over before: a plain target then clears them, after reading it.
    const a = new IkSolver(rig, 'lm');
    a.solve(zero, limbGoals());
    expect(() => a.solve(zero, disposingTarget(a))).toThrow('this solver was disposed');
    const b = new IkSolver(rig, 'lm');
    b.solve(zero, limbGoals());
    expect(() => b.start(zero, disposingTarget(b))).toThrow('this solver was disposed');
    // Goals whose reading disposes it: handed over after.
    const c = new IkSolver(rig, 'lm');
    const goals = {
      effectors: [
        {
          bone: 1,
          get position() {
            c.dispose();
            return [1, 1, 0];
          },
        },
      ],
    };
    expect(() => c.solve(zero, goals)).toThrow('this solver was disposed');
    // Checked first: a disposed solver says so before looking at its arguments.
    expect(() => c.start('not angles' as unknown as number[], [1, 1, 0])).toThrow('this solver was disposed');
    expect(() => c.setOptions({ errorTolerance: -1 })).toThrow('this solver was disposed');
  });

  it('and a rig disposed likewise says so', () => {
    const rig = new IkRig(ik, straightLimb());
    const angles = new Proxy([0, 0, 0, 0, 0, 0], {
      get(t, key, receiver) {
        if (key === '0') rig.dispose();
        return Reflect.get(t, key, receiver) as unknown;
      },
    });
    expect(() => rig.tips(angles)).toThrow('this rig was disposed');
    expect(() => rig.project('not angles' as unknown as number[])).toThrow('this rig was disposed');
    expect(() => rig.restartStart(1)).toThrow('this rig was disposed');
  });
});
