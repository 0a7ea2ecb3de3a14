// The gestures experiment: what a user does with a humanoid's hands, feet and head, as scripted
// paths of small target steps from the rest pose P(0), every other effector pinned at its tip at
// P(0). Per side (hands and feet both ways):
//   - a hand across the chest to the other shoulder;
//   - a hand over the head;
//   - a hand behind the back;
//   - a foot lifted forward;
//   - the head target lowered by 30% of the height (a crouch, where the rig can);
//   - a hand pushed past its reach, straight out forward to 1.5 arm lengths from the shoulder.
// A path runs through waypoints placed on the body at P(0) (gesturePaths), each leg split into equal
// steps of at most GESTURE_STEP_SHARE of the height, so every step moves the target less than that.
// The body: its up, forward and left directions from the importer's humanoid frame
// (web/src/rig/anatomy/anatomy_frame.ts), joints at P(0) from forward kinematics; `height` is the extent of
// every bone's head and tip at P(0) along up, an arm's length the distance from the shoulder (the
// upper arm's head) to the hand effector's tip, a leg's from the hip to the foot effector's tip.
// Paths are chained like reach's (each step from the previous step's solution); whether a step can
// be reached at all is reachability.ts's to decide, as for reach.
import type { RigSpec } from '#ik/rig_arrays.js';
import { bodyFrame } from '#rig/anatomy/anatomy_frame.js';
import { add, dot, norm, scale, sub, type Vec3 } from '#rig/anatomy/anatomy_vec.js';
import type { HumanoidMap, HumanoidRole } from '#rig/humanoid/humanoid_roles.js';
import { jointPositions } from './jumps.js';
import type { TargetSet } from './target_set.js';

/** Largest target step of a gesture, as a share of the humanoid's height. */
export const GESTURE_STEP_SHARE = 0.005;
/** How far the crouch lowers the head target, as a share of the height. */
export const CROUCH_SHARE = 0.3;
/** Where the push past reach ends: this many arm lengths in front of the shoulder. */
export const PUSH_REACH = 1.5;

/** Forward kinematics: every bone's pose transform (IkRig.poses, 16 row-major numbers per bone). */
export type PosesFn = (angles: Float64Array) => Float64Array;

/** The humanoid a gestures set is made for: its mapping and its forward kinematics. */
export interface GestureBody {
  humanoid: HumanoidMap;
  poses: PosesFn;
}

export interface GesturePath {
  /** What the gesture is, e.g. "left hand across the chest". */
  name: string;
  /** The dragged effector, an index into spec.effectors. */
  effector: number;
  /** The target's positions after each step (rig units); the path starts at the effector's tip at P(0). */
  steps: Vec3[];
}

type Side = 'left' | 'right';
const SIDES: readonly Side[] = ['left', 'right'];
const other = (side: Side): Side => (side === 'left' ? 'right' : 'left');
const role = (side: Side, part: string): HumanoidRole => `${side}${part}` as HumanoidRole;

/** The effector (index into spec.effectors) on the bone of `r` or the nearest below it; -1 if none. */
function effectorOf(spec: RigSpec, humanoid: HumanoidMap, r: HumanoidRole): number {
  const bone = humanoid.bones[r];
  if (bone === undefined) return -1;
  let best = -1,
    bestDepth = Infinity;
  spec.effectors.forEach((e, k) => {
    let depth = 0;
    for (let b = e; b >= 0; b = spec.parents[b], depth++) {
      if (b !== bone) continue;
      if (depth < bestDepth) [best, bestDepth] = [k, depth];
      break;
    }
  });
  return best;
}

/**
 * The target positions of a walk from `start` through `waypoints`, each leg in equal steps of at
 * most `step` (rig units): the positions after each step, ending at the last waypoint.
 */
export function walk(start: Vec3, waypoints: readonly Vec3[], step: number): Vec3[] {
  const out: Vec3[] = [];
  let from = start;
  for (const to of waypoints) {
    const leg = sub(to, from);
    const n = Math.max(1, Math.ceil(norm(leg) / step));
    for (let i = 1; i <= n; i++) out.push(add(from, scale(leg, i / n)));
    from = to;
  }
  return out;
}

/**
 * The gestures of a humanoid (see the header) in sample order: per side the hand's three gestures
 * and the push, the feet, then the head. `rest`: P(0); `restTips`: the effectors' tips at P(0). A
 * gesture whose role or effector the rig lacks is left out.
 */
export function gesturePaths(
  spec: RigSpec,
  body: GestureBody,
  rest: Float64Array,
  restTips: ArrayLike<number>,
): GesturePath[] {
  const { humanoid } = body;
  const frame = bodyFrame(spec, humanoid);
  const joints = jointPositions(spec, body.poses(rest));
  const head = (b: number): Vec3 => [joints[6 * b], joints[6 * b + 1], joints[6 * b + 2]];
  const along = (d: Vec3): number[] =>
    Array.from({ length: 2 * spec.parents.length }, (_, j) =>
      dot(d, [joints[3 * j], joints[3 * j + 1], joints[3 * j + 2]]),
    );
  const heights = along(frame.up);
  const height = Math.max(...heights) - Math.min(...heights);
  const step = GESTURE_STEP_SHARE * height;
  const { up, forward } = frame;
  const sideways = (side: Side): Vec3 => (side === 'left' ? frame.left : scale(frame.left, -1));
  const tipOf = (e: number): Vec3 => [restTips[3 * e], restTips[3 * e + 1], restTips[3 * e + 2]];
  const at = (r: HumanoidRole): Vec3 | null => (humanoid.bones[r] === undefined ? null : head(humanoid.bones[r]!));
  /** A point `base` + sum of (share * length) along each direction. */
  const offset = (base: Vec3, length: number, ...moves: [Vec3, number][]): Vec3 =>
    moves.reduce((p, [d, share]) => add(p, scale(d, share * length)), base);

  const paths: GesturePath[] = [];
  const push = (name: string, effector: number, waypoints: (Vec3 | null)[]): void => {
    if (effector < 0 || waypoints.some((w) => w === null)) return;
    paths.push({ name, effector, steps: walk(tipOf(effector), waypoints as Vec3[], step) });
  };

  const hips = at('hips'),
    headBone = humanoid.bones.head;
  const headTop: Vec3 | null =
    headBone === undefined ? null : [joints[6 * headBone + 3], joints[6 * headBone + 4], joints[6 * headBone + 5]];
  for (const side of SIDES) {
    const hand = effectorOf(spec, humanoid, role(side, 'Hand'));
    const shoulder = at(role(side, 'UpperArm')),
      otherShoulder = at(role(other(side), 'UpperArm'));
    if (hand < 0 || !shoulder || !otherShoulder) continue;
    const arm = norm(sub(tipOf(hand), shoulder));
    const s = sideways(side);
    push(`${side} hand across the chest`, hand, [
      offset(shoulder, arm, [forward, 0.6]),
      offset(otherShoulder, arm, [forward, 0.25]),
    ]);
    push(`${side} hand over the head`, hand, [
      offset(shoulder, arm, [s, 0.5], [up, 0.6]),
      headTop && offset(headTop, arm, [up, 0.1]),
    ]);
    push(`${side} hand behind the back`, hand, [
      offset(shoulder, arm, [s, 0.2], [up, -0.9]),
      offset(shoulder, arm, [s, 0.1], [up, -0.7], [forward, -0.3]),
      hips && offset(hips, height, [up, 0.1], [forward, -0.12]),
    ]);
    push(`${side} hand pushed past its reach`, hand, [
      offset(shoulder, arm, [forward, 0.5]),
      offset(shoulder, arm, [forward, PUSH_REACH]),
    ]);
  }
  for (const side of SIDES) {
    const foot = effectorOf(spec, humanoid, role(side, 'Foot'));
    const hip = at(role(side, 'UpperLeg'));
    if (foot < 0 || !hip) continue;
    const leg = norm(sub(tipOf(foot), hip));
    push(`${side} foot lifted forward`, foot, [offset(tipOf(foot), leg, [forward, 0.35], [up, 0.35])]);
  }
  const headEffector = effectorOf(spec, humanoid, 'head');
  if (headEffector >= 0)
    push('head lowered (crouch)', headEffector, [offset(tipOf(headEffector), height, [up, -CROUCH_SHARE])]);
  return paths;
}

/** Samples in the whole gestures set of `paths`. */
export function gestureSteps(paths: readonly GesturePath[]): number {
  return paths.reduce((n, p) => n + p.steps.length, 0);
}

/**
 * Fills the samples of `set` (set.count <= gestureSteps(paths)) with the paths' steps in order:
 * targets (`restTips` with the dragged effector's target moved), starts (`rest` = P(0), used by each
 * path's first step), chained flags, dragged effector and path index.
 */
export function fillGestures(
  set: TargetSet,
  paths: readonly GesturePath[],
  rest: Float64Array,
  restTips: Float64Array,
): void {
  const m = set.numAngles,
    r = set.numResiduals;
  let k = 0;
  paths.forEach((path, index) => {
    path.steps.forEach((point, t) => {
      if (k >= set.count) return;
      const target = set.targets.subarray(k * r, (k + 1) * r);
      target.set(restTips);
      target.set(point, 3 * path.effector);
      set.starts.set(rest, k * m);
      set.chained[k] = t > 0 ? 1 : 0;
      set.dragged[k] = path.effector;
      set.group[k] = index;
      k++;
    });
  });
}
