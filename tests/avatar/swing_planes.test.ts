// An upper arm's swing plane where its swing is 0 (web/src/avatar/swing_planes.ts), on the
// project's character in its T-pose: the rotation stays, and the plane chosen is the one in which
// a swing brings the hand fastest towards its target (checked against every whole degree of the
// plane by finite differences); a target at the hand, or a swung arm, are left as they are. While
// the arm leaves the rest pose, a small swing in another plane is turned to the target's, its size
// kept; past SEAT_SWING_DEG, or once the arm has left, it is not.
import { resolve } from 'node:path';

import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { SEAT_SWING_DEG, seatSwingPlane } from '../../web/src/avatar/swing_planes.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { loadRigFromPath } from '../../web/src/rig/load_rig_node.js';

let rig: IkRig;
let arm: number;
beforeAll(async () => {
  const ik = await loadIkNode();
  const character = await loadRigFromPath(resolve(import.meta.dirname, '../../web/public/models/character.glb'));
  const humanoid = character.gltf!.humanoid!;
  arm = humanoid.bones.leftUpperArm!;
  rig = new IkRig(ik, { ...character.spec, effectors: Int32Array.of(humanoid.bones.leftHand!) });
});
afterAll(() => rig.dispose());

/** The hand's tip at `angles` (rig units). */
const hand = (angles: Float64Array): number[] => Array.from(rig.tips(angles));

/** How fast (rig units per degree) a swing of the arm in plane a0 brings the hand towards `target` from `angles`. */
function approach(angles: Float64Array, a0: number, target: number[]): number {
  const twist = angles[3 * arm] + angles[3 * arm + 2],
    at = hand(angles),
    swing = 1e-4;
  const swung = angles.slice();
  swung.set([a0, swing, twist - a0], 3 * arm);
  const gap = (p: number[]) => Math.hypot(...p.map((x, i) => x - target[i]));
  return (gap(at) - gap(hand(swung))) / swing;
}

describe("an upper arm's swing plane at the T-pose", () => {
  it('turns to the plane in which the hand falls fastest towards a target below it, keeping the pose', () => {
    const rest = rig.project(new Float64Array(rig.numAngles));
    expect(rest[3 * arm + 1]).toBe(0); // the T-pose: no swing
    const start = hand(rest);
    const target = [start[0], start[1] - 0.01, start[2] + 0.002]; // down and a little forward
    const angles = rest.slice();
    seatSwingPlane(rig, angles, arm, 0, target);
    expect(angles[3 * arm]).not.toBe(rest[3 * arm]);
    expect(angles[3 * arm] + angles[3 * arm + 2]).toBeCloseTo(rest[3 * arm] + rest[3 * arm + 2], 12);
    const tips = rig.boneTips(angles),
      restTips = rig.boneTips(rest);
    tips.forEach((x, i) => expect(x).toBeCloseTo(restTips[i], 12));
    // No whole degree of the plane within the limits does better.
    const chosen = approach(rest, angles[3 * arm], target);
    for (let a0 = rig.lower[3 * arm]; a0 <= rig.upper[3 * arm]; a0++)
      expect(approach(rest, a0, target)).toBeLessThanOrEqual(chosen + 1e-6);
    expect(chosen).toBeGreaterThan(0);
  });

  it('leaves the arm as it is when its hand is at the target, or when it is already swung', () => {
    const rest = rig.project(new Float64Array(rig.numAngles));
    const angles = rest.slice();
    seatSwingPlane(rig, angles, arm, 0, hand(rest));
    expect(Array.from(angles)).toEqual(Array.from(rest));
    angles[3 * arm + 1] = 5;
    const swung = angles.slice();
    const start = hand(swung);
    seatSwingPlane(rig, angles, arm, 0, [start[0], start[1] - 0.01, start[2]]);
    expect(Array.from(angles)).toEqual(Array.from(swung));
  });

  it('turns a small swing towards the target while the arm leaves the rest pose, keeping its size', () => {
    const rest = rig.project(new Float64Array(rig.numAngles));
    const start = hand(rest);
    const target = [start[0], start[1] - 0.02, start[2] + 0.01]; // down and forward, 2.2 cm
    // A 1-degree swing in the plane the target chooses least: the hand moves away from it.
    const scores: Array<[number, number]> = [];
    for (let a0 = rig.lower[3 * arm]; a0 <= rig.upper[3 * arm]; a0++) scores.push([a0, approach(rest, a0, target)]);
    const worst = scores.reduce((w, s) => (s[1] < w[1] ? s : w))[0];
    const twist = rest[3 * arm] + rest[3 * arm + 2];
    const swung = rest.slice();
    swung.set([worst, 1, twist - worst], 3 * arm);
    const gap = (a: Float64Array) => Math.hypot(...hand(a).map((x, i) => x - target[i]));
    const before = gap(swung);
    const angles = swung.slice();
    seatSwingPlane(rig, angles, arm, 0, target, true);
    expect(Math.abs(angles[3 * arm + 1])).toBe(1);
    expect(angles[3 * arm] + angles[3 * arm + 2]).toBeCloseTo(twist, 12);
    expect(gap(angles)).toBeLessThan(before - 0.01); // the hand now swings towards the target
    // Its plane is within 1% of the best whole degree's rate from the zero swing.
    const best = Math.max(...scores.map((s) => s[1]));
    expect(approach(rest, angles[3 * arm], target)).toBeGreaterThan(0.99 * best);
    // Not leaving, or past SEAT_SWING_DEG: left as it is.
    const kept = swung.slice();
    seatSwingPlane(rig, kept, arm, 0, target, false);
    expect(Array.from(kept)).toEqual(Array.from(swung));
    const far = rest.slice();
    far.set([worst, SEAT_SWING_DEG + 0.5, twist - worst], 3 * arm);
    const farKept = far.slice();
    seatSwingPlane(rig, farKept, arm, 0, target, true);
    expect(Array.from(farKept)).toEqual(Array.from(far));
  });
});
