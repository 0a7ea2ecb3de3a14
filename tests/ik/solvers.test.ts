// The solvers through WebAssembly in Node: every method on the report's incremental targets
// (PROTOCOL.md) on the project's rigs and the five A7 rigs, and the contract of the binding
// (options, errors, stepping).
import { beforeAll, describe, expect, it } from 'vitest';

import { generateTargets } from '../../bench-node/targets.js';
import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { IkSolver, type SolverOptions } from '../../web/src/ik/solver.js';
import { defaultTolerances, rigSize } from '../../web/src/rig/tolerances.js';
import { loadTestRig, randomAngles, rigsLike, seeded, testRigs, type TestRig } from '../helpers/a7.js';
import { disposeAfterAll } from '../helpers/owned.js';

let ik: IkCoreModule;
const keep = disposeAfterAll();

beforeAll(async () => {
  ik = await loadIkNode();
});
/** The core's methods (its registry), for the tables of cases below. */
const methods = IkSolver.methods(await loadIkNode());

/** The report's tolerances of `testRig` (web/src/rig/tolerances.ts); no time budget. */
function reportOptions(testRig: TestRig, rig: IkRig): SolverOptions & { errorTolerance: number } {
  const size = rigSize(rig.boneTips(new Float64Array(rig.numAngles)));
  const { gradientTolerance, errorTolerance } = defaultTolerances(testRig.name, testRig.a7, size);
  return { gradientTolerance: gradientTolerance, errorTolerance: errorTolerance, timeBudgetSeconds: 0 };
}

interface TargetCase {
  start: Float64Array;
  target: Float64Array;
}

/** The benchmark's incremental targets of `seed` (bench-node/targets.ts), as (start, target) pairs. */
function incrementalTargets(rig: IkRig, count: number, seed: number): TargetCase[] {
  const set = generateTargets(rig.spec, 'incremental', count, seed, (a) => rig.tips(a));
  const m = set.numAngles,
    r = set.numResiduals;
  return Array.from({ length: set.count }, (_, k) => ({
    start: set.starts.subarray(k * m, (k + 1) * m),
    target: set.targets.subarray(k * r, (k + 1) * r),
  }));
}

function insideLimits(rig: IkRig, a: Float64Array): boolean {
  return a.every((x, i) => x >= rig.lower[i] && x <= rig.upper[i]);
}

// What each method must reach (as the native suite): the share of solves ending with E below
// the tolerance; the others must stop on the gradient test.
const expectations: Record<string, { samples: number; maxIterations: number; minSuccess: number }> = {
  lm: { samples: 30, maxIterations: 200, minSuccess: 1 },
  newton: { samples: 30, maxIterations: 200, minSuccess: 1 },
  gn: { samples: 30, maxIterations: 200, minSuccess: 0.9 },
  bfgs: { samples: 30, maxIterations: 500, minSuccess: 0.95 },
  gd: { samples: 15, maxIterations: 20000, minSuccess: 0.5 },
};

describe('the methods', () => {
  it('are the registered ones, lm first, each with a label and a description', () => {
    expect(IkSolver.methods(ik)).toEqual(['lm', 'gn', 'bfgs', 'newton', 'gd']);
    for (const m of methods) {
      expect(IkSolver.describe(ik, m).length).toBeGreaterThan(10);
      expect(IkSolver.label(ik, m).length).toBeGreaterThan(3);
    }
    expect(IkSolver.label(ik, 'lm')).toBe('Levenberg–Marquardt');
    expect(() => IkSolver.describe(ik, 'simplex')).toThrow(/unknown solver method "simplex"/);
    expect(() => IkSolver.label(ik, 'simplex')).toThrow(/unknown solver method "simplex"/);
  });
});

describe.each(testRigs)('$label: incremental targets through WebAssembly', (testRig) => {
  it.each(methods)('%s solves them to the report tolerances, inside the limits', (method) => {
    const rig = keep(new IkRig(ik, loadTestRig(testRig)));
    const expectation = expectations[method];
    const options = { ...reportOptions(testRig, rig), maxIterations: expectation.maxIterations };
    const solver = keep(new IkSolver(rig, method, options));
    const cases = incrementalTargets(rig, expectation.samples, 41);
    let successes = 0;
    for (const c of cases) {
      const r = solver.solve(c.start, c.target);
      expect(['converged_E', 'converged_grad'], `${method} ${r.stopReason}`).toContain(r.stopReason);
      expect(r.E).toBeLessThanOrEqual(r.initialE);
      expect(insideLimits(rig, r.angles)).toBe(true);
      expect(rig.objective(r.angles, c.target)).toBeCloseTo(r.E, 12);
      if (r.E < options.errorTolerance) successes++;
    }
    expect(successes, `${successes} of ${cases.length}`).toBeGreaterThanOrEqual(expectation.minSuccess * cases.length);
  });
});

describe('the Solver binding', () => {
  it.each(rigsLike('knight'))('fills in defaults and reports the options of the current solve ($label)', (testRig) => {
    const rig = keep(new IkRig(ik, loadTestRig(testRig)));
    const solver = keep(new IkSolver(rig));
    expect(solver.method).toBe('lm');
    const o = solver.options();
    expect(o).toMatchObject({ gradientTolerance: 1e-4, errorTolerance: 2e-4, timeBudgetSeconds: 1, restarts: 1000 });
    solver.setOptions({ maxIterations: 3, restarts: 2 });
    expect(solver.options().maxIterations).toBe(100000); // applies at the next start
    solver.start(new Float64Array(rig.numAngles), rig.tips(new Float64Array(rig.numAngles)));
    expect(solver.options()).toMatchObject({ maxIterations: 3, restarts: 2, gradientTolerance: 1e-4 });
  });

  it.each(rigsLike('beast'))('stepping gives the same solve as solve(), with E per iteration ($label)', (testRig) => {
    const rig = keep(new IkRig(ik, loadTestRig(testRig)));
    // Without restarts (of the whole pose or of a chain), saddle escapes or goals given up (each
    // one more iteration within a step): one iteration per step, and the last iterate is the best point.
    const options = {
      ...reportOptions(testRig, rig),
      restarts: 0,
      chainRestarts: 0,
      escapeSaddles: false,
      strictPriority: false,
    };
    const stepped = keep(new IkSolver(rig, 'gn', options));
    const solved = keep(new IkSolver(rig, 'gn', options));
    const rand = seeded(5);
    for (let s = 0; s < 3; s++) {
      const start = new Float64Array(rig.numAngles);
      const target = rig.tips(randomAngles(rig.spec, rand));
      expect(stepped.start(start, target)).toBe('running');
      let steps = 0;
      while (stepped.step()) {
        expect(stepped.running).toBe(true);
        expect(stepped.errorHistory().length).toBe(++steps + 1);
        rig.tips(rig.upper.map((u, i) => Math.min(u, Math.max(rig.lower[i], 33)))); // pose the rig elsewhere
      }
      const a = stepped.result(),
        b = solved.solve(start, target);
      expect(a).toEqual({ ...b, elapsedSeconds: a.elapsedSeconds });
      expect(stepped.errorHistory()).toEqual(solved.errorHistory());
      expect(solved.errorHistory().length).toBe(b.iterations + 1);
      expect(solved.errorHistory()[0]).toBe(b.initialE);
      expect(stepped.angles()).toEqual(a.angles);
    }
  });

  it.each(rigsLike('ikea-lamp'))('turns bad input into Errors with the message ($label)', (testRig) => {
    const rig = keep(new IkRig(ik, loadTestRig(testRig)));
    const a = new Float64Array(rig.numAngles),
      t = rig.tips(a);
    const m = a.length,
      r = t.length;
    expect(() => new IkSolver(rig, 'simplex')).toThrow(
      /unknown solver method "simplex" \(known: lm, gn, bfgs, newton, gd\)/,
    );
    expect(() => new IkSolver(rig, 'lm', { maxIteration: 3 } as SolverOptions)).toThrow(
      /unknown solver option "maxIteration"/,
    );
    expect(() => new IkSolver(rig, 'lm', { maxIterations: 2.5 })).toThrow(/maxIterations must be an integer/);
    expect(() => new IkSolver(rig, 'lm', { paperMode: 1 } as unknown as SolverOptions)).toThrow(
      /paperMode must be true or false/,
    );
    const solver = keep(new IkSolver(rig, 'bfgs'));
    expect(() => solver.solve(a, t.slice(1))).toThrow(`target has ${r - 1} values, expected ${r}`);
    expect(() => solver.solve(new Float64Array(m + 3), t)).toThrow(`angles has ${m + 3} values, expected ${m}`);
    expect(() =>
      solver.solve(
        a,
        t.map((x, i) => (i === 1 ? NaN : x)),
      ),
    ).toThrow(/target\[1\] is NaN, not a finite number/);
    expect(() =>
      solver.start(
        a.map((x, i) => (i === 2 ? Infinity : x)),
        t,
      ),
    ).toThrow(/angles\[2\] is Infinity, not a finite number/);
    solver.setOptions({ errorTolerance: -1 });
    expect(() => solver.solve(a, t)).toThrow(/solver option errorTolerance must be a number > 0 \(0 can never be met/);
    solver.setOptions({});
    expect(solver.solve(a, t).stopReason).toBe('converged_E');
  });

  it.each(rigsLike('knight'))('follows the rig when its end effectors change ($label)', (testRig) => {
    const rig = keep(new IkRig(ik, loadTestRig(testRig)));
    const solver = keep(new IkSolver(rig, 'lm', reportOptions(testRig, rig)));
    const [c] = incrementalTargets(rig, 1, 7);
    expect(solver.solve(c.start, c.target).stopReason).toBe('converged_E');
    const all = Array.from(rig.effectors());
    rig.setEffectors(all.slice(0, 2));
    expect(() => solver.solve(c.start, c.target)).toThrow(`target has ${c.target.length} values, expected 6`);
    const goal = rig.project(c.start.map((x) => x + 3));
    const r = solver.solve(c.start, rig.tips(goal));
    expect(r.stopReason).toBe('converged_E');
    rig.setEffectors(all);
    expect(solver.solve(c.start, c.target).stopReason).toBe('converged_E');
  });

  it.each(rigsLike('knight'))(
    'lm with restarts solves random targets the plain run gets stuck on ($label)',
    (testRig) => {
      const rig = keep(new IkRig(ik, loadTestRig(testRig)));
      const options = reportOptions(testRig, rig);
      // One run, nothing to leave a stop off target (no restart of any kind, no escape).
      const plain = keep(new IkSolver(rig, 'lm', { ...options, restarts: 0, chainRestarts: 0, escapeSaddles: false }));
      const restarting = keep(new IkSolver(rig, 'lm', { ...options, restarts: 200 }));
      const rand = seeded(9);
      let plainSolved = 0;
      for (let s = 0; s < 20; s++) {
        const start = new Float64Array(rig.numAngles);
        const target = rig.tips(randomAngles(rig.spec, rand));
        if (plain.solve(start, target).E < options.errorTolerance) plainSolved++;
        const r = restarting.solve(start, target);
        expect(r.E, `target ${s}: ${r.stopReason} after ${r.restarts} restarts`).toBeLessThan(options.errorTolerance);
        expect(insideLimits(rig, r.angles)).toBe(true);
      }
      expect(plainSolved).toBeLessThan(20);
    },
  );

  it.each(rigsLike('ikea-lamp'))('refuses use after dispose, and after its rig was disposed ($label)', (testRig) => {
    const rig = new IkRig(ik, loadTestRig(testRig));
    const solver = new IkSolver(rig, 'gd');
    solver.dispose();
    solver.dispose();
    expect(() => solver.step()).toThrow(/this solver was disposed/);
    const orphan = new IkSolver(rig, 'gn');
    rig.dispose();
    expect(() => orphan.step()).toThrow(/this rig was disposed/);
    orphan.dispose();
  });
});
