// The rig-space axis a mapped bone's main bend (its flexion) turns about, taken from the skeleton:
// the character's frame (anatomy_frame.ts) says where forward, up and left are; a knee or elbow
// bent in the rest pose says which way it bends; a hand's finger roots say where its palm faces.
import type { RigSpec } from '../../ik/rig_arrays.js';
import type { BodyFrame } from './anatomy_frame.js';
import { JOINT_RANGES, jointOf, type Toward } from './anatomy_ranges.js';
import { cross, dot, norm, reject, restAxis, restOrigin, scale, sub, unit, type Vec3 } from './anatomy_vec.js';
import type { HumanoidMap, HumanoidRole } from '../humanoid/humanoid_roles.js';

/** A bend direction this close to the bone's own (sine of the angle: 30 degrees) is not used when another is listed. */
const MIN_SINE = 0.5;
/** A rest pose bent less than this (sine of 3 degrees) says nothing about which way a knee or elbow bends. */
const MIN_REST_BEND = Math.sin((3 * Math.PI) / 180);

export interface BendAxis {
  /** Unit axis in rig space: a positive bend turns the bone's tip about it, towards the role's main bend. */
  axis: Vec3;
  /** True when the rest pose bends the other way than the character's facing suggests (a reverse joint). */
  reversed: boolean;
}

/** Unit normal of the palm of hand bone `hand` (either side), from its child joints' spread; null without two. */
function palmNormal(spec: RigSpec, hand: number): Vec3 | null {
  const x = restAxis(spec, hand, 0);
  const roots: Vec3[] = [];
  spec.parents.forEach((p, i) => {
    if (p === hand) roots.push(restOrigin(spec, i));
  });
  let spread: Vec3 = [0, 0, 0];
  for (const a of roots)
    for (const b of roots) {
      const d = reject(sub(a, b), x);
      if (norm(d) > norm(spread)) spread = d;
    }
  return norm(spread) > 0.1 * spec.lengths[hand] ? unit(cross(x, spread)) : null;
}

/** The direction `toward` names for bone `bone`, in rig space (null: a palm without fingers). */
function direction(toward: Toward, frame: BodyFrame, spec: RigSpec, bone: number): Vec3 | null {
  switch (toward) {
    case 'forward':
      return frame.forward;
    case 'back':
      return scale(frame.forward, -1);
    case 'up':
      return frame.up;
    case 'down':
      return scale(frame.up, -1);
    case 'palm':
      return palmNormal(spec, bone);
  }
}

/**
 * The thigh or upper arm of a knee or elbow role (the mapped one, else the bone's parent);
 * undefined for other roles or a root.
 */
function upperBone(spec: RigSpec, map: HumanoidMap, role: HumanoidRole, bone: number): number | undefined {
  const joint = jointOf(role);
  if (joint !== 'lowerLeg' && joint !== 'lowerArm') return undefined;
  const mapped = map.bones[role.replace('Lower', 'Upper') as HumanoidRole];
  return mapped ?? (spec.parents[bone] >= 0 ? spec.parents[bone] : undefined);
}

/** The axis of role `role`'s main bend on its bone `bone` (see BendAxis). */
export function bendAxis(
  spec: RigSpec,
  map: HumanoidMap,
  role: HumanoidRole,
  bone: number,
  frame: BodyFrame,
): BendAxis {
  const x = restAxis(spec, bone, 0);
  // The first listed direction far enough off the bone, else the one farthest off.
  let axis: Vec3 = [0, 0, 0];
  for (const toward of JOINT_RANGES[jointOf(role)].toward) {
    const d = direction(toward, frame, spec, bone);
    const k = d ? cross(x, d) : null;
    if (k && norm(k) > norm(axis)) axis = k;
    if (norm(axis) >= MIN_SINE) break;
  }
  axis = unit(axis)!; // every list has two perpendicular directions, so one is off the bone
  // A bent knee or elbow: the way it bends at rest wins over the facing when the two disagree.
  const upper = upperBone(spec, map, role, bone);
  const upperDir = upper === undefined ? null : unit(sub(restOrigin(spec, bone), restOrigin(spec, upper)));
  const bent = upperDir ? cross(upperDir, x) : null;
  if (bent && norm(bent) >= MIN_REST_BEND && dot(unit(bent)!, axis) < -0.5)
    return { axis: scale(axis, -1), reversed: true };
  return { axis, reversed: false };
}
