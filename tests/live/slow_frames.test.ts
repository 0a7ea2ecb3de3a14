// The page's drag on a machine too slow for its frame budget (a phone, a loaded laptop: in
// Chromium with the CPU throttled 8 times, the character's arm with pole handles took 0 steps a
// frame and then, a step a frame, stayed 0.12 of its height off target for hundreds of frames).
// Here every frame's budget is a microsecond, shorter than any step: with the page's
// stepsBeforeBudget each frame still takes a step, and a frame cut off target lowers the pole's
// pull for the next one, as a run stopped off target does. The left hand, with the pole handles
// and the other effectors' frames pinned, is pulled a fifth of the way to its shoulder in 12
// frames; it must be within δ a few frames after the drag, the elbow bent towards its pole.
import { afterEach, beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { FRAME_STEPS_BEFORE_BUDGET } from '../../web/src/live/live_solve.js';
import { IkSession } from '../../web/src/live/session.js';
import { dragTolerances, rigSize } from '../../web/src/rig/tolerances.js';
import { across, limb, limbEffector, type PoleRig, poleRig, polePoint, worstTip } from './pole_drag.js';

let ik: IkCoreModule;
beforeAll(async () => {
  ik = await loadIkNode();
});
afterEach(() => expect(IkSession.alive.sessions).toBe(0));

const DRAG_FRAMES = 12;
/** Frames after the drag within which the hand must be on target. */
const SETTLE_FRAMES = 10;

/** The left arm's pole, its hand's effector, and a frame settings record whose budget no step fits in. */
function slowDrag(r: PoleRig, stepsBeforeBudget: number) {
  const j = r.limbs.findIndex((l) => /LeftForeArm$/.test(r.spec.names?.[l.bone] ?? ''));
  expect(j).toBeGreaterThanOrEqual(0);
  const k = limbEffector(r, j);
  const size = rigSize(r.session.rig.boneTips(new Float64Array(r.session.rig.numAngles)));
  const settings = {
    ...r.settings,
    timeBudgetMs: 1e-6,
    maxJointMove: dragTolerances(size).maxJointMove,
    strictPriority: true,
    stepsBeforeBudget,
  };
  r.session.yielding = k;
  r.session.pinsFrames = true;
  r.session.pinOrientations(true);
  return { j, k, settings };
}

describe('a drag whose frames are cut by their budget', () => {
  it('the character with pole handles: each frame takes a step, the hand is on target soon after the drag, the elbow towards its pole', async () => {
    const r = await poleRig(ik, 'character');
    try {
      const { j, k, settings } = slowDrag(r, FRAME_STEPS_BEFORE_BUDGET);
      const t = r.session.targets.subarray(3 * k, 3 * k + 3);
      const from = Array.from(t),
        root = limb(r, j).root;
      let fewest = Infinity;
      for (let i = 1; i <= DRAG_FRAMES; i++) {
        for (let a = 0; a < 3; a++) t[a] = from[a] + ((root[a] - from[a]) * 0.2 * i) / DRAG_FRAMES;
        fewest = Math.min(fewest, r.session.solve('lm', settings).iterations);
      }
      expect(fewest).toBeGreaterThanOrEqual(1);
      let frames = 0;
      for (; frames < SETTLE_FRAMES && worstTip(r.session) >= settings.tipTolerance; frames++)
        r.session.solve('lm', settings);
      console.log(
        `[slow frames] hand within δ ${frames} frames after the drag (worst tip ${worstTip(r.session).toExponential(2)}, δ ${settings.tipTolerance.toExponential(2)})`,
      );
      expect(worstTip(r.session)).toBeLessThan(settings.tipTolerance);
      const bend = across(r, j, limb(r, j).joint),
        pole = across(r, j, polePoint(r, j));
      if (!bend || !pole) throw new Error('a straight arm');
      expect(bend[0] * pole[0] + bend[1] * pole[1] + bend[2] * pole[2]).toBeGreaterThan(0.9);
    } finally {
      r.session.dispose();
    }
  });

  it('without steps before the budget, such a frame takes none: the pose does not move', async () => {
    const r = await poleRig(ik, 'character');
    try {
      const { j, k, settings } = slowDrag(r, 0);
      const t = r.session.targets.subarray(3 * k, 3 * k + 3),
        root = limb(r, j).root;
      for (let a = 0; a < 3; a++) t[a] += (root[a] - t[a]) * 0.02;
      const before = r.session.angles.slice();
      const outcome = r.session.solve('lm', settings);
      expect(outcome.iterations).toBe(0);
      expect(outcome.stopReason).toBe('timeout');
      expect(Array.from(r.session.angles)).toEqual(Array.from(before));
    } finally {
      r.session.dispose();
    }
  });
});
