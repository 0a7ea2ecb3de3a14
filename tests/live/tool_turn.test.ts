// A robot's tool turned where its arm must change branch. The test arm (tests/helpers/
// test_arm_urdf.ts) holds its tool 0.15 m below where it stood, and the tool is turned 30 degrees
// about the vertical in 8 frames, as the page's rotate gizmo turns it: on the arm's current branch
// of solutions the turn ends 1 degree short, and the answer lies on another one, which only a
// chain restart's run reaches. Each frame here gets a few iterations (a slow machine, or the
// page's 3 ms on a busy one): a run cut by the frame's budget must go on in the next frame, not be
// thrown away for the next chain restart. Before it did, 5 iterations a frame drew all 64 chain
// restarts and stopped 1 degree short saying "orientation out of reach", and 1 to 3 crawled
// for 400 frames. The tool must reach its target, and no frame may move it farther than the
// joints' speed bound lets it.
import { afterEach, beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { budgetStop, FRAME_STEPS_BEFORE_BUDGET } from '../../web/src/live/live_solve.js';
import type { SolveSettings } from '../../web/src/live/method_solver.js';
import { IkSession } from '../../web/src/live/session.js';
import { applyStillBody } from '../../web/src/live/still_body.js';
import { dragTolerances, rigSize } from '../../web/src/rig/tolerances.js';
import { readRig } from '../../web/src/view/rig_source.js';
import { armUrdf } from '../helpers/test_arm_urdf.js';

let ik: IkCoreModule;
beforeAll(async () => {
  ik = await loadIkNode();
});
afterEach(() => expect(IkSession.alive.sessions).toBe(0));

/** Frames after the turn within which the tool must be on target. */
const SETTLE_FRAMES = 400;

interface Turned {
  reached: boolean;
  stopReason: string;
  orientationErrorDeg: number;
  /** Frames after the turn until the solve stopped. */
  frames: number;
  /** The most the tool tip moved in one frame, and the joints' bound per frame (rig units). */
  largestTipStep: number;
  maxJointMove: number;
}

/** The drag and the turn with `iterations` per frame (an untimed budget: the same on every machine). */
async function dragAndTurn(iterations: number): Promise<Turned> {
  const source = await readRig(new TextEncoder().encode(armUrdf()), 'test_arm.urdf');
  const session = new IkSession(ik, source.spec);
  try {
    const tol = dragTolerances(rigSize(session.rig.boneTips(new Float64Array(session.rig.numAngles))));
    const settings: SolveSettings = {
      ...tol,
      maxIterations: iterations,
      timeBudgetMs: 10_000,
      restarts: 0,
      paperMode: false,
      strictPriority: true,
      stepsBeforeBudget: FRAME_STEPS_BEFORE_BUDGET,
    };
    session.yielding = 0; // the tool's target is the one selected
    let tip = Array.from(session.tips()),
      largestTipStep = 0;
    const frame = () => {
      applyStillBody(session, true, false, settings);
      const outcome = session.solve('lm', settings);
      const now = session.tips();
      largestTipStep = Math.max(largestTipStep, Math.hypot(now[0] - tip[0], now[1] - tip[1], now[2] - tip[2]));
      tip = Array.from(now);
      return outcome;
    };
    const y0 = session.targets[1];
    for (let i = 1; i <= 20; i++) {
      session.targets[1] = y0 - (0.15 * i) / 20;
      frame();
    }
    for (let f = 0; f < SETTLE_FRAMES && budgetStop(frame().stopReason); f++);
    expect(session.orientationErrorDeg()).toBeNaN(); // no orientation goal yet
    // The orientation goal on at the tool's frame (O), then turned about the vertical (+y).
    session.setOrientationGoal(0, true);
    const q = Array.from(session.tipRotations().subarray(0, 4));
    const half = ((30 / 8) * Math.PI) / 360,
      c = Math.cos(half),
      s = Math.sin(half);
    largestTipStep = 0;
    let outcome = frame();
    for (let i = 0; i < 8; i++) {
      const [x, y, z, w] = q; // q = (0, s, 0, c) * q
      q[0] = c * x + s * z;
      q[1] = c * y + s * w;
      q[2] = c * z - s * x;
      q[3] = c * w - s * y;
      session.setOrientationGoal(0, true, q);
      outcome = frame();
    }
    let frames = 0;
    while (budgetStop(outcome.stopReason) && frames < SETTLE_FRAMES) {
      outcome = frame();
      frames++;
    }
    return {
      reached: outcome.reached,
      stopReason: outcome.stopReason,
      orientationErrorDeg: session.orientationErrorDeg(),
      frames,
      largestTipStep,
      maxJointMove: tol.maxJointMove,
    };
  } finally {
    session.dispose();
  }
}

describe("a robot's tool turned onto another branch of solutions", () => {
  for (const iterations of [1, 3, 5, 50])
    it(`reaches its target with ${iterations} iteration${iterations > 1 ? 's' : ''} a frame, moving no faster than the joints' bound`, async () => {
      const r = await dragAndTurn(iterations);
      console.log(
        `[tool turn] ${iterations} it/frame: ${r.stopReason} after ${r.frames} frames, orientation error ${r.orientationErrorDeg.toExponential(2)}°, largest tip step ${r.largestTipStep.toFixed(4)} (joint bound ${r.maxJointMove.toFixed(4)})`,
      );
      expect(r.stopReason).toBe('converged_E');
      expect(r.reached).toBe(true);
      expect(r.orientationErrorDeg).toBeLessThan(0.5);
      expect(r.largestTipStep).toBeLessThan(2 * r.maxJointMove);
    });
});
