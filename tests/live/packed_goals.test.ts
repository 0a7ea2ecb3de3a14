// The per-frame solve's fast path (EffectorGoals.packed, IkSolver.solvePacked): the session packs
// its goals itself instead of building a Goals object for packGoals to check every frame. The
// packed numbers must be exactly packGoals' for every mix of goals the page makes (orientation
// goals, pinned frames, a yielding effector, position goals off, poles), a solve through them must
// give the same pose to the bit, and what the TypeScript checks no longer catch the core still
// refuses with an error that names it.
import { afterEach, beforeAll, describe, expect, it } from 'vitest';

import { packGoals } from '../../web/src/ik/goals.js';
import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { IkSolver } from '../../web/src/ik/solver.js';
import { IkSession } from '../../web/src/live/session.js';
import { disposeAfterAll } from '../helpers/owned.js';
import { sketchRig } from '../../scripts/rig_files/rig_builder.js';

let ik: IkCoreModule;
const keep = disposeAfterAll();
beforeAll(async () => {
  ik = await loadIkNode();
});
afterEach(() => expect(IkSession.alive.sessions).toBe(0));

/** A trunk with two three-bone arms: effectors at both arms' ends (bones 3 and 6). */
const twoArms = () =>
  sketchRig(
    [
      { parent: -1, at: [0, 0, 0], length: 1 },
      { parent: 0, at: [1, 0, 0], length: 1 },
      { parent: 1, at: [2, 0, 0], length: 1 },
      { parent: 2, at: [3, 0, 0], length: 1 },
      { parent: 0, at: [1, 0, 0], length: 1 },
      { parent: 4, at: [2, 0, 0], length: 1 },
      { parent: 5, at: [3, 0, 0], length: 1 },
    ],
    [3, 6],
  );

describe('the session packs its own goals', () => {
  it('packs what packGoals packs, for every mix of goals the page makes', () => {
    const s = new IkSession(ik, twoArms());
    try {
      s.angles.set([0, 20, 0, 0, -30, 10, 5, 15, 0, 0, 40, -20, 0, 25, 0, 0, 0, 0, 0, 0, 0]);
      s.targets.set([2.5, 0.5, 0.2, 2.4, -0.6, 0.1]);
      const cases: Array<[string, () => void, number]> = [
        ['one yielding', () => {}, 0],
        ['an orientation goal', () => s.setOrientationGoal(1, true, [0, 0, Math.sin(0.3), Math.cos(0.3)]), 0],
        ['pinned frames, the other yielding', () => s.goals.pin(s.tipRotations(), [1, 1]), 1],
        ['a position goal off', () => s.goals.setPosition(0, false), 1],
        ['poles', () => s.goals.setPoles([2, 5], [2, 1, 0, 2, -1, 0.5]), -1],
      ];
      for (const [what, change, yielding] of cases) {
        change();
        const fast = s.goals.packed(s.targets, yielding);
        const checked = packGoals(s.rig, s.goals.goals(s.effectors(), s.targets, yielding));
        expect({
          what,
          packed: Array.from(fast.packed),
          target: Array.from(fast.target),
          poles: Array.from(fast.poles),
        }).toEqual({
          what,
          packed: Array.from(checked.packed),
          target: Array.from(checked.target),
          poles: Array.from(checked.poles),
        });
        expect([fast.lengthScale, fast.stiffness.length]).toEqual([checked.lengthScale, checked.stiffness.length]);
      }
    } finally {
      s.dispose();
    }
  });

  it('solves to the same pose, bit for bit, as solve() with the Goals object', () => {
    const s = new IkSession(ik, twoArms());
    const solver = keep(new IkSolver(s.rig, 'lm'));
    try {
      s.targets.set([2.2, 1.1, 0.3, 2.6, -0.4, -0.2]);
      s.setOrientationGoal(0, true, [0, 0, Math.sin(0.2), Math.cos(0.2)]);
      s.goals.setPoles([2], [2, 1, 1]);
      s.yielding = 1;
      const start = s.angles.slice();
      solver.setOptions({ tipTolerance: 1e-4, maxJointMove: 0.2 });
      const viaGoals = solver.solve(start, s.goals.goals(s.effectors(), s.targets, 1));
      const viaPacked = solver.solvePacked(start, s.goals.packed(s.targets, 1));
      expect(viaPacked.iterations).toBeGreaterThan(0);
      expect(Array.from(viaPacked.angles)).toEqual(Array.from(viaGoals.angles));
      expect([viaPacked.stopReason, viaPacked.E]).toEqual([viaGoals.stopReason, viaGoals.E]);
    } finally {
      s.dispose();
    }
  });

  it('hands the goals to the core again when the effectors changed, even to as many', () => {
    const rig = keep(new IkRig(ik, twoArms()));
    const solver = keep(new IkSolver(rig, 'lm'));
    const fresh = (): IkSolver => keep(new IkSolver(rig, 'lm'));
    const s = new IkSession(ik, twoArms());
    try {
      // Effector 0 turned, effector 1 free: after the swap the turn belongs to the other arm.
      s.setOrientationGoal(0, true, [0, Math.sin(0.4), 0, Math.cos(0.4)]);
      const goals = s.goals.packed(s.targets, -1);
      const start = new Float64Array(rig.numAngles);
      solver.solvePacked(start, goals);
      rig.setEffectors([6, 3]);
      const swapped = solver.solvePacked(start, goals);
      expect(Array.from(swapped.angles)).toEqual(Array.from(fresh().solvePacked(start, goals).angles));
    } finally {
      s.dispose();
    }
  });

  it('leaves the checks of each number to the core, which names what it refuses', () => {
    const s = new IkSession(ik, twoArms());
    const solver = keep(new IkSolver(s.rig, 'lm'));
    try {
      const goals = s.goals.packed(s.targets, 0);
      const bad = s.angles.slice();
      bad[4] = NaN;
      expect(() => solver.solvePacked(bad, goals)).toThrow(/angles\[4\] is NaN, not a finite number/);
      expect(() => solver.solvePacked(s.angles.subarray(1), goals)).toThrow(
        /angles must be a Float64Array of 21 numbers/,
      );
      s.setOrientationGoal(1, true, [0, 0, 0, 0]);
      expect(() => solver.solvePacked(s.angles, s.goals.packed(s.targets, 0))).toThrow(/orientation.*not a rotation/);
      s.setOrientationGoal(1, false);
      const nanTarget = s.goals.packed(s.targets, 0);
      nanTarget.target[2] = Infinity;
      expect(() => solver.solvePacked(s.angles, nanTarget)).toThrow(
        /position target of the goal of end effector 0 is not finite/,
      );
    } finally {
      s.dispose();
    }
  });
});
