// Flips of elbows and knees: a step of a drag, reach or gestures path flips a limb when, at its
// solution, the limb bends against its anatomical direction, or when the limb's bend plane turns
// more than FLIP_TURN_DEG between the step's start pose and its solution.
//
// The limbs are the pole limbs of the page (web/src/live/pole_limbs.ts): for a recognised humanoid
// its lower arms and lower legs, else each end effector bone's parent; a limb is its upper bone's
// head (shoulder, hip), its lower bone's head (elbow, knee) and the lower bone's tip (wrist,
// ankle): pole_placement.ts limbPoints. The bend plane is the plane through the three; its normal
// n = (joint - root) x (tip - joint). A limb counts as bent only when the angle between its two
// parts is more than BENT_DEG (the plane is defined then), at both poses for the turn test.
//
// Anatomical direction (humanoids only; other rigs have no anatomy to hold, only the turn test):
// the importer's bend axis of the role (web/src/rig/anatomy/anatomy_axes.ts, which pole_limbs.ts turns
// into the way the joint leaves the root-tip line: the elbow back so the forearm comes forward,
// the knee forward so the shin goes back). A positive bend turns the lower bone about that axis, so
// a limb bent the anatomical way has n along the axis carried by the upper bone: n . (R_upper a) > 0.
// A limb bent with n . (R_upper a) < 0 bends against it.
import { limbPoints } from '#live/pole_placement.js';
import { poleLimbs } from '#live/pole_limbs.js';
import type { RigSpec } from '#ik/rig_arrays.js';
import { cross, dot, norm, restAxis, sub, unit, type Vec3 } from '#rig/anatomy/anatomy_vec.js';
import type { HumanoidMap } from '#rig/humanoid/humanoid_roles.js';

/** A limb's bend plane turning more than this (degrees) in one step is a flip. */
export const FLIP_TURN_DEG = 90;
/** A limb is bent (its plane defined) when its parts meet at more than this from straight (degrees). */
export const BENT_DEG = 5;

/** One elbow or knee (or the middle joint of a non-humanoid rig's limb). */
export interface FlipLimb {
  /** The lower bone (forearm, shin); its parent is the upper bone. */
  bone: number;
  /**
   * Unit axis, rest (rig) coordinates, about which the anatomical bend turns the lower bone (so
   * the bend plane's normal points along it); null for a limb without anatomy (no humanoid).
   */
  hinge: Vec3 | null;
}

/**
 * The limbs of `spec` whose flips are counted (pole_limbs.ts's rule, for the rig's end effectors),
 * each with its anatomical hinge axis when `humanoid` maps the rig.
 */
export function flipLimbs(spec: RigSpec, humanoid: HumanoidMap | null): FlipLimb[] {
  return poleLimbs(spec, spec.effectors, humanoid).map(({ bone, restBend }) => ({
    bone,
    // restBend = x * a for the lower bone's rest axis x (perpendicular to a), so a = restBend x x.
    hinge: humanoid ? unit(cross(restBend, restAxis(spec, bone, 0))) : null,
  }));
}

/** A limb at one pose: its bend plane's normal (rig units squared) and the angle between its parts (degrees). */
interface Bend {
  normal: Vec3;
  angleDeg: number;
}

function bendOf(spec: RigSpec, poses: ArrayLike<number>, bone: number): Bend {
  const { root, joint, tip } = limbPoints(spec, poses, bone);
  const upper = sub(joint, root),
    lower = sub(tip, joint);
  const normal = cross(upper, lower);
  return { normal, angleDeg: (Math.atan2(norm(normal), dot(upper, lower)) * 180) / Math.PI };
}

/** Direction `d` (rest coordinates) turned with bone `bone` at `poses` (its rotation R_bone). */
function turned(poses: ArrayLike<number>, bone: number, d: Vec3): Vec3 {
  const o = 16 * bone;
  const row = (r: number): number =>
    poses[o + 4 * r] * d[0] + poses[o + 4 * r + 1] * d[1] + poses[o + 4 * r + 2] * d[2];
  return [row(0), row(1), row(2)];
}

/** Whether `limb` at `poses` is bent (more than BENT_DEG) against its anatomical direction. */
export function bentAgainst(spec: RigSpec, limb: FlipLimb, poses: ArrayLike<number>): boolean {
  if (!limb.hinge) return false;
  const { normal, angleDeg } = bendOf(spec, poses, limb.bone);
  return angleDeg > BENT_DEG && dot(normal, turned(poses, spec.parents[limb.bone], limb.hinge)) < 0;
}

/**
 * The angle (degrees) the bend plane of `limb` turns from `from` to `to` (IkRig.poses of the
 * step's start and solution); NaN when the limb is straight (within BENT_DEG) at either pose.
 */
export function planeTurnDeg(spec: RigSpec, limb: FlipLimb, from: ArrayLike<number>, to: ArrayLike<number>): number {
  const a = bendOf(spec, from, limb.bone),
    b = bendOf(spec, to, limb.bone);
  if (!(a.angleDeg > BENT_DEG && b.angleDeg > BENT_DEG)) return NaN;
  return (Math.atan2(norm(cross(a.normal, b.normal)), dot(a.normal, b.normal)) * 180) / Math.PI;
}

/**
 * Whether the step from pose `from` to pose `to` (IkRig.poses) flips one of `limbs`: one bends
 * against its anatomical direction at `to`, or its bend plane turns more than FLIP_TURN_DEG.
 */
export function isFlip(
  spec: RigSpec,
  limbs: readonly FlipLimb[],
  from: ArrayLike<number>,
  to: ArrayLike<number>,
): boolean {
  return limbs.some((limb) => bentAgainst(spec, limb, to) || planeTurnDeg(spec, limb, from, to) > FLIP_TURN_DEG);
}
