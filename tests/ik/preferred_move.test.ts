// IkSolver.setPreferredMove through the WebAssembly: a move the goal leaves room for turns a
// redundant chain while its tip stays on target, the next solve has none, other methods ignore
// it, and a move of the wrong length or with a NaN is refused by name (the native tests,
// wasm/tests/solvers/preferred_move_test.cpp, cover the step itself).
import { beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import { IkSolver, type SolverOptions } from '../../web/src/ik/solver.js';
import { disposeAfterAll } from '../helpers/owned.js';

let ik: IkCoreModule;
const keep = disposeAfterAll();

beforeAll(async () => {
  ik = await loadIkNode();
});

/** A straight chain of 3 unit bones along +x, +-90 degrees per angle, its last tip the effector. */
function chain(): RigSpec {
  const rest = new Float64Array(48);
  for (let i = 0; i < 3; i++) rest.set([1, 0, 0, i, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], 16 * i);
  return {
    names: [],
    parents: Int32Array.from([-1, 0, 1]),
    rest,
    lengths: new Float64Array(3).fill(1),
    lower: new Float64Array(9).fill(-90),
    upper: new Float64Array(9).fill(90),
    effectors: Int32Array.from([2]),
  };
}

/** A tracked frame's solve: no restarts, one iteration at least, tight tolerances. */
const FRAME: SolverOptions = {
  restarts: 0,
  minIterations: 1,
  lmInitialMu: 1e-3,
  tipTolerance: 1e-6,
  gradientTolerance: 1e-14,
  timeBudgetSeconds: 0,
};

describe('a preferred move', () => {
  it('turns a redundant chain where its goal leaves room, for one solve, the tip on target', () => {
    const rig = keep(new IkRig(ik, chain()));
    const start = new Float64Array(9);
    for (let b = 0; b < 3; b++) start[3 * b + 1] = 20;
    const target = rig.tips(start);
    target[1] += 1e-3;
    const lm = keep(new IkSolver(rig, 'lm')),
      plain = keep(new IkSolver(rig, 'lm'));
    lm.setOptions(FRAME);
    plain.setOptions(FRAME);
    const move = new Float64Array(9);
    move[1] = 2;
    lm.setPreferredMove(move);
    const moved = lm.solve(start, target);
    const without = plain.solve(start, target);
    expect(moved.stopReason).toBe('converged_E');
    const tip = rig.tips(moved.angles);
    expect(Math.hypot(tip[0] - target[0], tip[1] - target[1], tip[2] - target[2])).toBeLessThan(1e-6);
    // The first bone turned its way further than without the move (native: 0.18 against 0.065).
    expect(moved.angles[1] - without.angles[1]).toBeGreaterThan(0.05);
    // The next solve has none: the plain solve's angles, bit for bit.
    expect(Array.from(lm.solve(start, target).angles)).toEqual(Array.from(without.angles));
    // gd ignores it.
    const gd = keep(new IkSolver(rig, 'gd')),
      gdPlain = keep(new IkSolver(rig, 'gd'));
    gd.setOptions(FRAME);
    gdPlain.setOptions(FRAME);
    gd.setPreferredMove(move);
    expect(Array.from(gd.solve(start, target).angles)).toEqual(Array.from(gdPlain.solve(start, target).angles));
  });

  it('is refused, by name, with the wrong length or a value that is not finite', () => {
    const rig = keep(new IkRig(ik, chain()));
    const lm = keep(new IkSolver(rig, 'lm'));
    expect(() => lm.setPreferredMove(new Float64Array(8))).toThrow(/preferred move has 8 values, expected 9/);
    const bad = new Float64Array(9);
    bad[4] = NaN;
    expect(() => lm.setPreferredMove(bad)).toThrow(/preferred move .*finite/);
    bad[4] = Infinity;
    expect(() => lm.setPreferredMove(bad)).toThrow(/preferred move .*finite/);
  });
});
