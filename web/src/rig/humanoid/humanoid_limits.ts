// Anatomical joint limits for a recognised humanoid, in the importer's XZX frame (degrees).
//
// A bone turns by Rx(a0) Rz(a1) Rx(a2) in its canonical frame (x along the bone): a0 picks the
// plane the bone bends in, a1 bends it by that much about the turned z, a2 twists it back (the
// bone's twist is a0 + a2). Each joint's range (anatomy_ranges.ts) is a bend about an anatomical
// axis (anatomy_axes.ts), which may lie at any angle phi about the bone from its local z. With
// a0 = phi + b0, a1 = b1, a2 = -phi + b2 the rotation is Rx(phi) Rx(b0) Rz(b1) Rx(b2) Rx(-phi):
// the anatomical (b0, b1, b2) about the turned frame. So the limits are the anatomical ones
// shifted by phi on a0 and -phi on a2, and since b0 and b2 share one half-width, the rest pose
// clamped into them is (c, 0, -c): no turn at all, the model stays as it was loaded.
//
// Cone-like ranges come from the same three numbers: b0 turns the bend plane by up to +-w about
// the main one, b1 bends within it (a negative bend goes the opposite way), b2 twists back by up
// to +-w, so zero twist stays possible in every plane. With w = 90 the planes cover every
// direction (a shoulder's full cone); with small w they fan about the main plane (a hip's).
import type { RigSpec } from '../../ik/rig_arrays.js';
import { bodyFrame, type BodyFrame } from '../anatomy/anatomy_frame.js';
import { bendAxis } from '../anatomy/anatomy_axes.js';
import { JOINT_RANGES, jointOf, type JointRange } from '../anatomy/anatomy_ranges.js';
import { dot, restAxis, type Vec3 } from '../anatomy/anatomy_vec.js';
import { HUMANOID_ROLES, type HumanoidMap, type HumanoidRole } from './humanoid_roles.js';

/** A rig's joint limits: 3 XZX angles per bone, degrees. */
export interface RigLimits {
  lower: Float64Array;
  upper: Float64Array;
}

/** The limits (the spec's own where unchanged) and what was found and done, for the user. */
export interface HumanoidLimits extends RigLimits {
  /** Facing, reverse joints, limits kept from extras.ik (for the user; a bend plane turned from the local z is routine, not noted). */
  notes: string[];
}

/** The angle (degrees, in (-180, 180]) about bone i's x axis from its local z to `axis` taken across x. */
export function planeTurn(spec: RigSpec, i: number, axis: Vec3): number {
  return (Math.atan2(-dot(axis, restAxis(spec, i, 1)), dot(axis, restAxis(spec, i, 2))) * 180) / Math.PI;
}

/**
 * XZX limits (degrees) for `range` about an axis turned by phi degrees about the bone from its
 * local z. A turn past 90 degrees is taken as the opposite axis with the bend's sign flipped, so
 * |phi| <= 90.
 */
export function turnedLimits(phi: number, range: JointRange): { lower: Vec3; upper: Vec3 } {
  let [lo, hi] = range.bend;
  if (Math.abs(phi) > 90) {
    phi -= Math.sign(phi) * 180;
    [lo, hi] = [-hi, -lo];
  }
  const t = range.twist;
  return { lower: [phi - t, lo, -phi - t], upper: [phi + t, hi, -phi + t] };
}

/** The character's forward direction in words: a signed rig axis if within 5 degrees of one, else 3 numbers. */
function describeDirection(v: Vec3): string {
  const k = v.findIndex((c) => Math.abs(c) > Math.cos((5 * Math.PI) / 180));
  return k >= 0 ? `${v[k] > 0 ? '+' : '-'}${'XYZ'[k]}` : `(${v.map((c) => c.toFixed(2)).join(', ')})`;
}

interface BoneLimits {
  /** XZX limits, degrees. */
  lower: Vec3;
  upper: Vec3;
  /** The rest pose bends this knee or elbow the other way than the facing says. */
  reversed: boolean;
}

/** One mapped bone's limits (see BoneLimits); a fixed joint's are all 0. */
function boneLimits(spec: RigSpec, map: HumanoidMap, role: HumanoidRole, bone: number, frame: BodyFrame): BoneLimits {
  const range = JOINT_RANGES[jointOf(role)];
  if (range.twist === 0 && range.bend[0] === 0 && range.bend[1] === 0)
    return { lower: [0, 0, 0], upper: [0, 0, 0], reversed: false };
  const bend = bendAxis(spec, map, role, bone, frame);
  const limits = turnedLimits(planeTurn(spec, bone, bend.axis), range);
  return { ...limits, reversed: bend.reversed };
}

/**
 * Anatomical XZX limits (degrees) for every bone `map` gives a role: knees and elbows bend one way
 * (0 to 150), hips of the legs and shoulders of the arms get cone-like ranges, spine, neck, head,
 * wrists, ankles, clavicles and toes their own (anatomy_ranges.ts); the hips bone is fixed. Bones
 * with no role, or with explicit[i] true (limits from extras.ik), keep the spec's limits. Pure:
 * the spec is not changed.
 */
export function humanoidLimits(spec: RigSpec, map: HumanoidMap, explicit: readonly boolean[]): HumanoidLimits {
  const lower = spec.lower.slice(),
    upper = spec.upper.slice();
  const frame = bodyFrame(spec, map);
  const kept: string[] = [],
    reversed: string[] = [];
  for (const role of HUMANOID_ROLES) {
    const bone = map.bones[role];
    if (bone === undefined) continue;
    const name = spec.names[bone] || `bone ${bone}`;
    if (explicit[bone]) {
      kept.push(name);
      continue;
    }
    const limits = boneLimits(spec, map, role, bone, frame);
    lower.set(limits.lower, 3 * bone);
    upper.set(limits.upper, 3 * bone);
    if (limits.reversed) reversed.push(name);
  }
  const notes = [
    `humanoid limits: the character faces ${describeDirection(frame.forward)} (from the ${frame.facingFrom})`,
  ];
  if (reversed.length) notes.push(`bent the other way in the rest pose, so limited that way: ${reversed.join(', ')}`);
  if (kept.length) notes.push(`extras.ik limits kept: ${kept.join(', ')}`);
  return { lower, upper, notes };
}
