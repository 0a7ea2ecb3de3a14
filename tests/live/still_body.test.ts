// A still body on a rig without a humanoid map (web/src/live/still_body.ts), through the
// WebAssembly core in Node. Which bones are free while a paw or the head is dragged (the chain up
// to where another effector's chain joins it), when the rest pull is on, and a paw lift on the
// browser test's quadruped (tests/browser/quadruped_model.ts) solved as the page solves frames:
// one solve per step of 20, then until the budget no longer stops it. With the pull the hips and
// the tail's tip stay within 2% of the height; without it (the test has something to catch) the
// same lift moves them more.
import { afterEach, beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import { solveFrame } from '../../web/src/live/live_solve.js';
import { IkSession } from '../../web/src/live/session.js';
import type { SolveSettings } from '../../web/src/live/method_solver.js';
import { applyStillBody, STILL_BODY_WEIGHT, stillBodyStiffness } from '../../web/src/live/still_body.js';
import { loadRig } from '../../web/src/rig/load_rig.js';
import { dragTolerances, restHeight, rigSize } from '../../web/src/rig/tolerances.js';
import { quadrupedGlb } from '../browser/quadruped_model.js';

let ik: IkCoreModule;
let spec: RigSpec;
beforeAll(async () => {
  ik = await loadIkNode();
  const rig = await loadRig(await quadrupedGlb(), 'quadruped.glb');
  expect(rig.gltf?.humanoid).toBeNull();
  spec = rig.spec;
});
afterEach(() => expect(IkSession.alive.sessions).toBe(0));

const free = (s: Float64Array): string[] => spec.names.filter((_, b) => s[b] === 0);

describe('stillBodyStiffness', () => {
  it('frees the dragged chain up to where another effector chain joins it, and holds every other bone', () => {
    const effectors = Array.from(spec.effectors);
    const names = effectors.map((b) => spec.names[b]);
    expect(names).toEqual(['head', 'fore_paw.L', 'fore_paw.R', 'hind_paw.L', 'hind_paw.R']);
    expect(free(stillBodyStiffness(spec, effectors, 1))).toEqual(['fore1.L', 'fore2.L', 'fore3.L', 'fore_paw.L']);
    expect(free(stillBodyStiffness(spec, effectors, 3))).toEqual(['hind1.L', 'hind2.L', 'hind3.L', 'hind_paw.L']);
    expect(free(stillBodyStiffness(spec, effectors, 0))).toEqual(['neck', 'head']);
    expect(free(stillBodyStiffness(spec, effectors, -1))).toEqual([]);
  });
});

describe('applyStillBody', () => {
  it('turns the pull on only with the setting on, no humanoid map, no paper mode and a target dragged', () => {
    const session = new IkSession(ik, spec);
    try {
      const f: SolveSettings = {
        gradientTolerance: 0,
        tipTolerance: 1e-3,
        maxIterations: 50,
        timeBudgetMs: 3,
        restarts: 0,
        paperMode: false,
      };
      session.yielding = 1;
      applyStillBody(session, true, false, f);
      expect([f.restWeight, f.restFromStart]).toEqual([STILL_BODY_WEIGHT, true]);
      expect(session.goals.stiffness.length).toBe(spec.parents.length);
      expect(session.goals.packed(session.targets, 1).stiffness).toBe(session.goals.stiffness);
      for (const [on, humanoid, paper, dragged] of [
        [false, false, false, 1],
        [true, true, false, 1],
        [true, false, true, 1],
        [true, false, false, -1],
      ] as const) {
        session.yielding = dragged;
        f.paperMode = paper;
        applyStillBody(session, on, humanoid, f);
        expect([f.restWeight, f.restFromStart, session.goals.stiffness.length]).toEqual([0, false, 0]);
      }
    } finally {
      session.dispose();
    }
  });
});

/** Lifts paw `paw` by 15% of the height as the page's drag does; the hips' and tail tip's moves as shares of the height. */
function lift(paw: string, still: boolean): { hips: number; tail: number; off: number; tolerance: number } {
  const s = new IkSession(ik, spec);
  try {
    const tips0 = s.rig.boneTips(s.angles);
    const t = dragTolerances(rigSize(tips0)),
      height = restHeight(tips0);
    const f: SolveSettings = {
      gradientTolerance: t.gradientTolerance,
      tipTolerance: t.tipTolerance,
      maxIterations: 50,
      timeBudgetMs: 3,
      restarts: 0,
      paperMode: false,
      strictPriority: true,
      maxJointMove: t.maxJointMove,
    };
    const k = Array.from(s.effectors()).findIndex((b) => spec.names[b] === paw);
    s.yielding = k;
    const timing = { ms: 0, again: false };
    const solve = (): void => {
      applyStillBody(s, still, false, f);
      solveFrame(s, 'lm', f, timing);
    };
    const y0 = s.targets[3 * k + 1];
    for (let i = 1; i <= 20; i++) {
      s.targets[3 * k + 1] = y0 + (0.15 * height * i) / 20;
      solve();
    }
    for (let n = 0; n < 300 && timing.again; n++) solve();
    expect(timing.again).toBe(false);
    const tips = s.rig.boneTips(s.angles),
      tip = s.tips();
    const moved = (name: string): number => {
      const b = spec.names.indexOf(name);
      return (
        Math.hypot(tips[3 * b] - tips0[3 * b], tips[3 * b + 1] - tips0[3 * b + 1], tips[3 * b + 2] - tips0[3 * b + 2]) /
        height
      );
    };
    const off = Math.hypot(
      tip[3 * k] - s.targets[3 * k],
      tip[3 * k + 1] - s.targets[3 * k + 1],
      tip[3 * k + 2] - s.targets[3 * k + 2],
    );
    return { hips: moved('body'), tail: moved('tail4'), off, tolerance: t.tipTolerance };
  } finally {
    s.dispose();
  }
}

describe('a paw lift on the quadruped', () => {
  it.each(['fore_paw.L', 'hind_paw.L'])(
    '%s: on target with the hips and tail within 2% of the height; without the pull they move more',
    (paw) => {
      const on = lift(paw, true),
        off = lift(paw, false);
      const pct = (x: number): string => `${(100 * x).toFixed(2)}%`;
      console.log(
        `[still body] ${paw} up 15%: on: hips ${pct(on.hips)}, tail tip ${pct(on.tail)}; off: hips ${pct(off.hips)}, tail tip ${pct(off.tail)} of the height`,
      );
      for (const r of [on, off]) expect(r.off).toBeLessThan(r.tolerance);
      expect(on.hips).toBeLessThan(0.02);
      expect(on.tail).toBeLessThan(0.02);
      expect(off.hips).toBeGreaterThan(0.02);
      expect(off.tail).toBeGreaterThan(0.02);
    },
  );
});
