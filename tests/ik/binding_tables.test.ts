// The names the TypeScript API shares with the bindings, written once on each side and checked
// here: SolverOptions (web/src/ik/solver.ts) has exactly the core's options (solver_options.h),
// and the result numbers solveIo() writes (IoStat) are exactly SolverResult's numeric fields, at
// the offsets the core names: solve() (the shared buffer) agrees with result() (embind's object).
import { beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { IkSolver, type SolverOptions, type SolverResult } from '../../web/src/ik/solver.js';
import { disposeAfterAll } from '../helpers/owned.js';
import { straightLimb } from '../helpers/rig_builder.js';

let ik: IkCoreModule;
const keep = disposeAfterAll();

beforeAll(async () => {
  ik = await loadIkNode();
});

// The type checker holds these to the interfaces: a missing or an extra name fails `npx tsc`.
const optionNames = {
  gradientTolerance: true, errorTolerance: true, tipTolerance: true, maxIterations: true, timeBudgetSeconds: true,
  historyCapacity: true, paperMode: true, fdStepDeg: true, gdInitialStep: true, backtrackFactor: true, armijoC1: true,
  maxBacktracks: true, gnSingularCutoff: true, gnMaxStepDeg: true, newtonMaxStepDeg: true, lmInitialMu: true,
  lmDampingFloor: true, lmMaxRejections: true, restarts: true, stallIterations: true, seed: true, escapeSaddles: true,
  chainRestarts: true,
} satisfies Record<keyof SolverOptions, true>;

type ResultNumber = Exclude<keyof SolverResult, 'angles' | 'stopReason' | 'message'>;
const resultNumbers = {
  E: true, initialE: true, gradNorm: true, tipDistance: true, reached: true, iterations: true, functionEvaluations: true,
  jacobianEvaluations: true, restarts: true, escapes: true, chainRestarts: true, elapsedSeconds: true,
} satisfies Record<ResultNumber, true>;

describe('tables shared with the bindings', () => {
  it("SolverOptions names exactly the core's options", () => {
    expect(Object.keys(ik.Solver.defaultOptions()).sort()).toEqual(Object.keys(optionNames).sort());
  });

  it("the result numbers are SolverResult's, and solve() reads each at the core's offset", () => {
    expect([...ik.Solver.ioStats()].sort()).toEqual(Object.keys(resultNumbers).sort());
    const rig = keep(new IkRig(ik, straightLimb()));
    // A straight limb whose target lies along it: an escape and iterations, so the numbers differ.
    const solver = keep(new IkSolver(rig, 'lm', { restarts: 0, tipTolerance: 1e-6 }));
    const fast = solver.solve(new Float64Array(rig.numAngles), [1.5, 0, 0]);
    const slow = solver.result();
    for (const name of Object.keys(resultNumbers) as ResultNumber[]) expect(fast[name], name).toBe(slow[name]);
    expect(fast.escapes + fast.iterations).toBeGreaterThan(0);
    expect(Array.from(fast.angles)).toEqual(Array.from(slow.angles));
  });
});
