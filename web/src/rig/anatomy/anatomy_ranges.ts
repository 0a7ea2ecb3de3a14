// The anatomical range of each humanoid joint, side-free, in degrees: a bend about the joint's
// anatomical axis (positive = its main bend: flexion), the half-width by which the bend plane may
// turn about the bone, and as much twist back. humanoid_limits.ts turns them into XZX limits.
import type { HumanoidRole } from '../humanoid/humanoid_roles.js';

/** A humanoid role without its side; chest and upperChest count as spine. */
export type Joint =
  | 'hips'
  | 'spine'
  | 'neck'
  | 'head'
  | 'shoulder'
  | 'upperArm'
  | 'lowerArm'
  | 'hand'
  | 'upperLeg'
  | 'lowerLeg'
  | 'foot'
  | 'toes';

/**
 * Where a positive bend moves the bone's tip, in the character's frame. 'palm': across the palm,
 * the plane the fingers' roots span (a hand's flexion).
 */
export type Toward = 'forward' | 'back' | 'up' | 'down' | 'palm';

export interface JointRange {
  /** Where the main bend moves the tip: the first of these the bone does not itself point (nearly) along. */
  toward: Toward[];
  /** Bend about the anatomical axis, degrees: [lowest, highest]; positive = toward. */
  bend: [number, number];
  /** Degrees: the bend plane turns by up to this about the bone (a0), and twists back as much (a2). */
  twist: number;
}

/**
 * The ranges, after the project character's hand-written limits (scripts/models/character.ts),
 * with two changes found by dragging a foot up from straight legs (tests/rig/humanoid_limits_solve):
 * - The hips bone stays fixed: it carries the whole body, and dragging a limb should not swing it.
 * - A leg's hip turns its bend plane and twists by 10 degrees at most. With box limits the twist
 *   freedom is as wide as the plane's (zero twist must stay possible in every plane), and the
 *   solver leaves a straight leg through restarts that sample the whole box: at 40 degrees the
 *   knee ends up turned out with the shin across (a "figure-4"), at 10 it stays within about 15
 *   degrees of straight ahead. Sideways leg lifts are the price.
 * Knees and elbows turn their plane by 3 degrees at most. A shoulder's plane turns freely (90
 * degrees either way with a signed bend: every direction), so an arm can hang, rise or reach.
 */
export const JOINT_RANGES: Readonly<Record<Joint, JointRange>> = {
  hips: { toward: ['forward', 'up'], bend: [0, 0], twist: 0 },
  spine: { toward: ['forward', 'up'], bend: [-15, 25], twist: 15 },
  neck: { toward: ['forward', 'up'], bend: [-30, 30], twist: 25 },
  head: { toward: ['forward', 'up'], bend: [-30, 40], twist: 30 },
  shoulder: { toward: ['up', 'forward'], bend: [-10, 30], twist: 20 },
  upperArm: { toward: ['forward', 'up'], bend: [-45, 130], twist: 90 },
  lowerArm: { toward: ['forward', 'up'], bend: [0, 150], twist: 3 },
  hand: { toward: ['palm', 'down', 'forward'], bend: [-70, 70], twist: 20 },
  upperLeg: { toward: ['forward', 'up'], bend: [-30, 120], twist: 10 },
  lowerLeg: { toward: ['back', 'down'], bend: [0, 150], twist: 3 },
  foot: { toward: ['down', 'back'], bend: [-30, 50], twist: 20 },
  toes: { toward: ['down', 'back'], bend: [-30, 30], twist: 5 },
};

/** The joint a role plays (leftLowerLeg -> lowerLeg). */
export function jointOf(role: HumanoidRole): Joint {
  const bare = role.replace(/^(left|right)/, '');
  const joint = bare.charAt(0).toLowerCase() + bare.slice(1);
  return joint === 'chest' || joint === 'upperChest' ? 'spine' : (joint as Joint);
}
