// A humanoid whose hips move: the core's floating root (rig.h FloatingRoot)
// under the hips, the hips bone turning and tilting as a pelvis does, and the root's move weighed
// as a body's (the solver option rootUnit). The avatar (avatar_solver.ts) and the page's drag mode
// (live_rig.ts) both take it from here. The A7 rigs and the report's experiments never float.
import type { RigSpec } from '../../ik/rig_arrays.js';
import { bodyFrame } from '../anatomy/anatomy_frame.js';
import { bendAxis } from '../anatomy/anatomy_axes.js';
import { planeTurn } from './humanoid_limits.js';
import type { HumanoidMap } from './humanoid_roles.js';

/**
 * The hips' own rotation: a turn about the hips bone (upright on a humanoid) and a tilt forward or
 * back in the way they face (degrees: [back, forward]), no tilt sideways. A humanoid's limits hold
 * the root still (it carries the whole rig); floating hips turn with the body and tilt as a pelvis
 * does in a crouch or a lean (the avatar's clips tilt them 10-12 degrees: held upright, the crouch's
 * and stress's tilted hips left their frames' poses beyond the avatar, and on turn_in_place the
 * spine alone took every lean: 98.6% of the frames on target, 100% with the tilt).
 */
export const HIPS_TILT: [number, number] = [-10, 20];

/** How far the hips may move from where they stand, as shares of the height: sideways and forward, down, up. */
export const ROOT_REACH = { across: 1, down: 0.6, up: 0.1 };

/**
 * The hips' move, as a share of the height, that a solve's step weighs as one degree of a joint
 * (the solver option rootUnit): the least change that meets the targets then moves the hips only
 * as far as a body does. At the default, one rig unit (a metre on the project's character, 0.53 of
 * its height: the hips' move nearly free), the avatar's crouch slid the hips forward and arched the
 * spine back, into a pose from which the flat feet could not go lower, its arms and spine 3.3% of
 * the height from the clip's; with 6 points stress's sideways lean stuck on 4% of its frames. At
 * 0.2 every frame of the six clips is on target with 3 and with 6 points, the crouch's arms and
 * spine 1.9% from the clip's. Lower is dearer still and better on the crouch (1.0% at 0.1, 0.9% at
 * 0.05) but stiffer elsewhere: stress missed 1% of its frames at 0.1; at 0.05 a hand gizmo dragged
 * across the chest in track mode pulled the head off until a foot stepped, and ten avatars' random
 * upper-body sway (tests/browser/avatars) lost 1.8% of its frames (1.25% at 0.2, none at the
 * default), an arm drifting into its shoulder's and wrist's limits where the hips' move had
 * absorbed it.
 */
export const ROOT_UNIT_SHARE = 0.2;

/**
 * XZX limits (degrees) of the hips bone `bone`: the turn a0 free all round, the tilt a1 within
 * HIPS_TILT about the hips' anatomical bend axis (its forward bend: anatomy_axes.ts), which lies
 * phi degrees about the bone from its local z, and a2 = -phi, so that the tilt stays in the plane
 * the hips face (humanoid_limits.ts explains the frame).
 */
export function hipsRange(spec: RigSpec, humanoid: HumanoidMap, bone: number): { lower: number[]; upper: number[] } {
  const phi = planeTurn(spec, bone, bendAxis(spec, humanoid, 'hips', bone, bodyFrame(spec, humanoid)).axis);
  return { lower: [phi - 180, HIPS_TILT[0], -phi], upper: [phi + 180, HIPS_TILT[1], -phi] };
}

/**
 * `spec` (a humanoid's, its limits in place) with floating hips: the hips bone's limits from
 * hipsRange and a floating root that moves within ROOT_REACH of where it stands, `height` being the
 * rig's height at rest (rig units). The hips are the humanoid map's; the root that floats is the
 * rig's root above them (the hips themselves on most rigs).
 */
export function floatingHipsSpec(spec: RigSpec, humanoid: HumanoidMap, height: number): RigSpec {
  const hipsBone = humanoid.bones.hips;
  if (hipsBone === undefined) throw new Error('floating hips need a humanoid hips bone');
  const lower = Float64Array.from(spec.lower),
    upper = Float64Array.from(spec.upper);
  const range = hipsRange(spec, humanoid, hipsBone);
  lower.set(range.lower, 3 * hipsBone);
  upper.set(range.upper, 3 * hipsBone);
  const h = height;
  const floatingRoot = {
    lower: [-ROOT_REACH.across * h, -ROOT_REACH.down * h, -ROOT_REACH.across * h],
    upper: [ROOT_REACH.across * h, ROOT_REACH.up * h, ROOT_REACH.across * h],
  };
  return { ...spec, lower, upper, floatingRoot };
}

/**
 * floatingHipsSpec() with the hips an end effector too (after the spec's, unless they are one):
 * the rig the page solves a floating humanoid with, its hips target the last effector.
 */
export function floatingHipsWithTarget(spec: RigSpec, humanoid: HumanoidMap, height: number): RigSpec {
  const hips = humanoid.bones.hips;
  const effectors = Array.from(spec.effectors ?? []);
  if (hips !== undefined && !effectors.includes(hips)) effectors.push(hips);
  return { ...floatingHipsSpec(spec, humanoid, height), effectors: Int32Array.from(effectors) };
}

/**
 * A crouch's knees take poles only while one bends less than this (degrees, its a1): the poles show
 * a straight leg the way to bend; a bent knee keeps its way from frame to frame. Placed every
 * frame of the avatar's crouch they cost 76 µs a frame on the crouch clip (their forward
 * kinematics and soft rows), 29 at 20 degrees, the same on target; at 5 degrees a knee of
 * stress's deep crouch went astray. The avatar and the page's hips target use it.
 */
export const KNEES_STRAIGHT_DEG = 20;

/** The solver option rootUnit (rig units) for a floating humanoid `height` rig units tall. */
export function floatingRootUnit(height: number): number {
  return ROOT_UNIT_SHARE * height;
}
