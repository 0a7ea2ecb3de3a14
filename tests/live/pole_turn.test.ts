// A pole turns its limb on every project rig with a two-bone limb: with the limb bent (its tip's
// target pulled a fifth of the way towards the limb's root, as a user bends an arm before placing
// its elbow), its pole carried 90 degrees round the root-tip line in 20 steps, each solved as the
// page solves a frame, turns the joint (elbow, knee, thumb) at least half the way after it, while
// every tip stays within the page's δ (0.1% of the rig size) of its target. Limbs whose tips leave
// them no room for that turn (NO_ROOM) must still keep every tip within δ and not turn away.
// Before the fix, the hand's finger poles stood on the palm side, against the way the fingers
// bend, and pulled the fingertips 0.08 (a third of the hand) off their targets.
import { afterEach, beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkSession } from '../../web/src/live/session.js';
import { sub } from '../../web/src/rig/anatomy/anatomy_vec.js';
import {
  limb,
  limbEffector,
  type PoleRig,
  poleRig,
  polePoint,
  settle,
  swivelTo,
  turnedAboutLimb,
  worstTip,
} from './pole_drag.js';

let ik: IkCoreModule;
beforeAll(async () => {
  ik = await loadIkNode();
});
afterEach(() => expect(IkSession.alive.sessions).toBe(0));

/** The rigs with two-bone limbs (pole_limbs.ts finds them) and the turn each pole is given, degrees. */
const RIGS = ['knight', 'character', 'beast', 'hand', 'lamp'];
/**
 * Limbs that the tips leave no room for the turn. Measured (2026-11-26) at the end of this test's
 * drag: of 1500 poses solved on target (lm, no poles) from random angles within the limits, the
 * one whose joint points nearest the turned pole is still this far from it (degrees), against the
 * pole's own result: the character's knees 76 and 75 (the pole: 75, 74; the toes pinned and the
 * ankles' limits), the beast's neck 58 (82: the head on a neck on a stiff chest) and hocks 55 and
 * 53 (56, 48), the hand's middle, ring and little fingers 81, 81, 80 (76, 86, 86: hinged fingers
 * turn only with their base joint's 15 degrees of twist; the index finger's 0.5 came from a pose
 * that points the finger at the pole, where the turn has no meaning), the lamp's arm 83 (83: hinges).
 */
const NO_ROOM: Readonly<Record<string, readonly string[]>> = {
  character: ['mixamorig:LeftLeg', 'mixamorig:RightLeg'],
  beast: ['neck', 'hock.L', 'hock.R'],
  hand: ['index_03', 'middle_03', 'ring_03', 'pinky_03'],
  lamp: ['upper_arm'],
};
const TURN = 90;
const STEPS = 20;

/** Pulls limb j's tip target `share` of the way towards the limb's root in `steps` solved steps. */
function bend(r: PoleRig, j: number, share: number, steps = 10): void {
  const k = limbEffector(r, j);
  const t = r.session.targets.subarray(3 * k, 3 * k + 3);
  const from = Array.from(t),
    root = limb(r, j).root;
  for (let i = 1; i <= steps; i++) {
    for (let a = 0; a < 3; a++) t[a] = from[a] + ((root[a] - from[a]) * share * i) / steps;
    settle(r);
  }
}

describe('a pole turns its limb towards it', () => {
  for (const name of RIGS)
    it(`${name}: each limb with room turns its joint at least half the way to a pole carried ${TURN} degrees round it; the tips stay within δ`, async () => {
      const first = await poleRig(ik, name);
      const count = first.limbs.length;
      first.session.dispose();
      expect(count).toBeGreaterThan(0);
      const failures: string[] = [];
      for (let j = 0; j < count; j++) {
        const r = await poleRig(ik, name);
        try {
          const bone = r.spec.names?.[r.limbs[j].bone] ?? String(r.limbs[j].bone);
          settle(r);
          bend(r, j, 0.2);
          const bent = worstTip(r.session);
          const start = Array.from(polePoint(r, j));
          const target = turnedAboutLimb(r, j, start, TURN);
          const before = swivelTo(r, j, target);
          let worst = 0;
          for (let i = 1; i <= STEPS; i++) {
            polePoint(r, j).set(turnedAboutLimb(r, j, start, (TURN * i) / STEPS));
            settle(r);
            worst = Math.max(worst, worstTip(r.session));
          }
          const after = swivelTo(r, j, target);
          const line = `${name} ${bone}: joint ${before.toFixed(1)} -> ${after.toFixed(1)} deg from the pole, largest tip error ${worst.toExponential(2)} (bent: ${bent.toExponential(2)}, δ ${r.settings.tipTolerance.toExponential(2)})`;
          console.log(line);
          const room = !NO_ROOM[name]?.includes(bone);
          const turned = room ? before > TURN / 2 && after <= before / 2 : after <= before + 1;
          if (!turned || !(worst < r.settings.tipTolerance)) failures.push(line);
        } finally {
          r.session.dispose();
        }
      }
      expect(failures).toEqual([]);
    });
});

// The reach row (pole_residual.h): on the knight at its rest pose, the left elbow's pole dragged
// 0.4 units up, along the hanging arm, changes nothing about the swivel, yet the elbow comes
// nearer the pole as far as the pinned hand lets the arm bend. Measured: 0.021 nearer (without the
// reach row 0.004 farther); of 1500 poses on target from random angles the nearest was 0.067
// nearer, past the hand's, collarbone's and upper arm's limits that the drag ends against.
describe('a pole dragged along a straight limb', () => {
  it('knight: the left elbow comes nearer its pole dragged 0.4 up along the hanging arm; the tips stay within δ', async () => {
    const r = await poleRig(ik, 'knight');
    try {
      const j = r.limbs.findIndex((l) => r.spec.names?.[l.bone] === 'forearm.L');
      settle(r);
      const start = Array.from(polePoint(r, j)),
        elbow = limb(r, j).joint;
      let worst = 0;
      for (let i = 1; i <= STEPS; i++) {
        polePoint(r, j).set([start[0], start[1] + (0.4 * i) / STEPS, start[2]]);
        settle(r);
        worst = Math.max(worst, worstTip(r.session));
      }
      const pole = Array.from(polePoint(r, j)) as [number, number, number];
      const nearer = Math.hypot(...sub(pole, elbow)) - Math.hypot(...sub(pole, limb(r, j).joint));
      console.log(
        `knight forearm.L, pole 0.4 up: the elbow ${nearer.toFixed(4)} nearer, largest tip error ${worst.toExponential(2)}`,
      );
      expect(nearer).toBeGreaterThan(0.01);
      expect(worst).toBeLessThan(r.settings.tipTolerance);
    } finally {
      r.session.dispose();
    }
  });
});
