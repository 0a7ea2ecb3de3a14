// The anatomical limits through the solver, as the page drags (lm, no restarts, the rig's drag
// tolerances, one solve per step of the drag from the pose before): lifting a foot in front of a
// character standing on straight legs bends the knee forward in the leg's own plane, reaching a
// hand across the chest bends the elbow towards the chest, and every iterate of every solve stays
// inside the limits (each gesture's, and solves to random targets). Directions are the
// character's own, as built (not as detected).
import { beforeAll, describe, expect, it } from 'vitest';

import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { IkSolver } from '../../web/src/ik/solver.js';
import { humanoidLimits } from '../../web/src/rig/humanoid/humanoid_limits.js';
import { dragTolerances, rigSize } from '../../web/src/rig/tolerances.js';
import { randomAngles, seeded } from '../helpers/a7.js';
import { blenderHumanoid, mixamoHumanoid, type TestHumanoid } from '../helpers/limits_characters.js';
import { disposeAfterAll } from '../helpers/owned.js';

type V = [number, number, number];
const sub = (a: V, b: V): V => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: V, b: V): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: V, b: V): V => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const len = (a: V): number => Math.hypot(...a);
const unit = (a: V): V => a.map((c) => c / len(a)) as V;
const at = (a: ArrayLike<number>, i: number): V => [a[3 * i], a[3 * i + 1], a[3 * i + 2]];
const degrees = (a: V, b: V): number => (Math.acos(Math.min(1, Math.max(-1, dot(unit(a), unit(b))))) * 180) / Math.PI;
const DRAG_STEPS = 30;
/** Steps of a drag that may catch up at bounded joint speed (solver option maxJointMove) instead of being on target. */
const MAX_CATCHING_UP = 3;

let ik: IkCoreModule;
const keep = disposeAfterAll();
beforeAll(async () => {
  ik = await loadIkNode();
});

const characters: [string, () => Promise<TestHumanoid>][] = [
  ['Mixamo, facing +Z', () => mixamoHumanoid()],
  [
    'Mixamo, facing -Z, Mixamo joint frames (hinges on local X)',
    () => mixamoHumanoid({ yawDeg: 180, hingeOnLocalX: true }),
  ],
  ['Mixamo, facing +X', () => mixamoHumanoid({ yawDeg: 90 })],
  ['Blender names, bent limbs, turned 30 degrees, tilted 10', () => blenderHumanoid()],
];

describe.each(characters)('%s', (_, make) => {
  let h: TestHumanoid;
  let rig: IkRig;
  let solver: IkSolver;
  let rest: Float64Array;
  let left: V;
  /** Effectors in this order: left hand, right hand, left foot, right foot, head. */
  const LEFT_HAND = 0,
    LEFT_FOOT = 2;

  beforeAll(async () => {
    h = await make();
    const { lower, upper } = humanoidLimits(h.spec, h.map, new Array<boolean>(h.spec.parents.length).fill(false));
    rig = keep(new IkRig(ik, { ...h.spec, lower, upper }));
    const m = h.map.bones;
    rig.setEffectors([m.leftHand!, m.rightHand!, m.leftFoot!, m.rightFoot!, m.head!]);
    const tol = dragTolerances(rigSize(rig.boneTips(new Float64Array(rig.numAngles))));
    solver = keep(new IkSolver(rig, 'lm', { restarts: 0, ...tol, maxIterations: 1000, timeBudgetSeconds: 0 }));
    rest = rig.project(new Float64Array(rig.numAngles));
    left = cross(h.up, h.forward);
  });

  interface Solved {
    angles: Float64Array;
    reached: boolean;
    /** The stop reason (drag(): of the last step). */
    stop: string;
    /** The farthest any iterate went outside the limits, degrees (0: never). */
    excess: number;
  }

  /** Solves with start()/step(), checking every iterate against the limits. */
  function solveStepping(start: Float64Array, target: Float64Array): Solved {
    let excess = 0;
    solver.start(start, target);
    do {
      const a = solver.angles();
      for (let k = 0; k < a.length; k++) excess = Math.max(excess, rig.lower[k] - a[k], a[k] - rig.upper[k]);
    } while (solver.step());
    const r = solver.result();
    return { angles: r.angles, reached: r.reached, stop: r.stopReason, excess };
  }

  /**
   * Drags effector k's target from its rest tip to `goal` in DRAG_STEPS solves; the others stay.
   * `reached`: every step on target, but for at most MAX_CATCHING_UP steps where a change of
   * branch (the first bend of a straight knee whose ankle is on its limit) moved the joints at the
   * page's bounded speed (stop reason joint_speed), and the last step on target.
   */
  function drag(k: number, goal: V): Solved {
    const target = rig.tips(rest);
    const from = at(target, k);
    let pose: Solved = { angles: rest, reached: true, stop: 'converged_E', excess: 0 };
    let reached = true,
      excess = 0,
      catching = 0;
    for (let s = 1; s <= DRAG_STEPS; s++) {
      for (let c = 0; c < 3; c++) target[3 * k + c] = from[c] + ((goal[c] - from[c]) * s) / DRAG_STEPS;
      pose = solveStepping(pose.angles, target);
      if (pose.stop === 'joint_speed') catching++;
      else reached &&= pose.reached;
      excess = Math.max(excess, pose.excess);
    }
    return {
      angles: pose.angles,
      reached: reached && pose.reached && catching <= MAX_CATCHING_UP,
      stop: pose.stop,
      excess,
    };
  }

  it.each([
    ['knee high', 0.3, 0.5],
    ['thigh level', 0.5, 0.6],
  ])("lifting a foot %s in front bends the knee forward, in the leg's plane (no figure-4)", (_, ahead, up) => {
    const m = h.map.bones;
    const tips = rig.boneTips(rest);
    const hip = at(tips, h.spec.parents[m.leftUpperLeg!]),
      knee0 = at(tips, m.leftUpperLeg!),
      ankle0 = at(tips, m.leftLowerLeg!);
    const leg = len(sub(knee0, hip)) + len(sub(ankle0, knee0));
    const foot0 = at(rig.tips(rest), LEFT_FOOT);
    const goal = [0, 1, 2].map((c) => foot0[c] + leg * (ahead * h.forward[c] + up * h.up[c])) as V;
    const { angles, reached, excess } = drag(LEFT_FOOT, goal);
    expect(reached).toBe(true);
    expect(excess, 'every iterate inside the limits').toBe(0);

    const posed = rig.boneTips(angles);
    const knee = at(posed, m.leftUpperLeg!),
      ankle = at(posed, m.leftLowerLeg!);
    const thigh = sub(knee, hip),
      shin = sub(ankle, knee);
    expect(dot(sub(knee, knee0), h.forward) / leg, 'the knee moves forward').toBeGreaterThan(0.3);
    expect(Math.abs(dot(sub(knee, knee0), left)) / leg, 'the knee stays in line').toBeLessThan(0.12);
    expect(degrees(thigh, shin), 'the knee bends').toBeGreaterThan(30);
    // The shin swings back about the character's left axis, not out to a side (a figure-4 is 60
    // degrees or more off, and the hips' narrow twist keeps it under 30: anatomy_ranges.ts).
    expect(degrees(cross(thigh, shin), left), "bend axis vs the character's left").toBeLessThan(35);
    expect(Math.abs(dot(unit(shin), left)), 'the shin points down/back, not across').toBeLessThan(0.35);
  });

  it('reaching a hand across the chest bends the elbow towards the chest', () => {
    const m = h.map.bones;
    const tips = rig.boneTips(rest);
    const shoulder = at(tips, h.map.bones.leftShoulder!),
      elbow0 = at(tips, m.leftUpperArm!),
      wrist0 = at(tips, m.leftLowerArm!);
    const arm = len(sub(elbow0, shoulder)) + len(sub(wrist0, elbow0));
    // In front of the other shoulder.
    const other = at(tips, h.map.bones.rightShoulder!);
    const goal = [0, 1, 2].map((c) => other[c] + 0.6 * arm * h.forward[c]) as V;
    const { angles, reached, excess } = drag(LEFT_HAND, goal);
    expect(reached).toBe(true);
    expect(excess, 'every iterate inside the limits').toBe(0);

    const posed = rig.boneTips(angles);
    const elbow = at(posed, m.leftUpperArm!),
      wrist = at(posed, m.leftLowerArm!);
    const upper = sub(elbow, shoulder),
      fore = sub(wrist, elbow);
    expect(degrees(upper, fore), 'the elbow bends').toBeGreaterThan(30);
    expect(dot(unit(fore), left), 'the forearm points across the body').toBeLessThan(-0.3);
    // The elbow flexes about the axis it had at rest (forearm x forward), carried along by the upper arm.
    const flexAtRest = cross(unit(sub(wrist0, elbow0)), h.forward);
    const T = rig.poses(angles),
      u = 16 * m.leftUpperArm!;
    const carried = [0, 1, 2].map((r) => dot([T[u + 4 * r], T[u + 4 * r + 1], T[u + 4 * r + 2]], flexAtRest)) as V;
    expect(degrees(cross(upper, fore), carried), 'flexion axis vs the anatomical one').toBeLessThan(30);
  });

  it('every iterate of 20 solves to random reachable targets stays inside the limits', () => {
    const rand = seeded(15);
    for (let s = 0; s < 20; s++) expect(solveStepping(rest, rig.tips(randomAngles(rig.spec, rand))).excess).toBe(0);
  });
});
