// Which limbs get a pole handle (a bend hint: PoleGoal in web/src/ik/goals.ts), and which way each
// one bends. A limb is named by its lower bone (forearm, shin); its upper bone is that bone's
// parent. The rule, for each end effector in effector order (a limb reached from two effectors,
// such as two fingers of one hand, counts once):
// - a recognised humanoid: the nearest bone at or above the effector that plays a lower-arm or
//   lower-leg role; an effector with none above it (the head, a spine bone) gets no pole;
// - any other rig: the effector bone's parent, when that parent has a parent itself; else none.
// A limb whose upper or lower part has no length at rest has no bend to hint at and is skipped.
import type { RigSpec } from '../ik/rig_arrays.js';
import { bendAxis } from '../rig/anatomy/anatomy_axes.js';
import { bodyFrame } from '../rig/anatomy/anatomy_frame.js';
import { cross, norm, restAxis, restOrigin, scale, sub, unit, type Vec3 } from '../rig/anatomy/anatomy_vec.js';
import type { HumanoidMap, HumanoidRole } from '../rig/humanoid/humanoid_roles.js';

/** One limb that takes a pole. */
export interface PoleLimb {
  /** The lower bone (forearm, shin): the pole goal's bone. */
  bone: number;
  /**
   * Unit direction, rig coordinates at the rest pose, in which the joint (elbow, knee) leaves the
   * line from the limb's root to its tip when the limb bends: for a humanoid the way its knees
   * (forward) and elbows (back) bend, from anatomy_axes.ts (a rest pose bent the other way wins);
   * otherwise the way the lower bone's limits let it bend (limitsBend), else the rig's facing,
   * glTF's +Z (pole_placement.ts takes it across the limb).
   */
  restBend: Vec3;
}

const LOWER_ROLES: readonly HumanoidRole[] = ['leftLowerArm', 'rightLowerArm', 'leftLowerLeg', 'rightLowerLeg'];

/** The rigs' facing where no humanoid says otherwise (glTF's forward). */
const FACING: Vec3 = [0, 0, 1];

/**
 * The way limb `bone` bends by its own limits, for a rig without a humanoid map: its bend angle
 * (the middle one, about the bone's local Z: rig_arrays.ts's XZX angles) reaching further one way
 * than the other turns the tip that way about Z, towards Z x bone for a positive bend, and the
 * joint leaves the root-tip line the other way: bone x Z. Null when the range is even (a robot's
 * hinge) or the bone cannot bend.
 */
function limitsBend(spec: RigSpec, bone: number): Vec3 | null {
  const lo = spec.lower[3 * bone + 1],
    hi = spec.upper[3 * bone + 1];
  const lean = hi + lo; // > 0: more room for a positive bend than a negative one
  if (!(Math.abs(lean) > 1e-6 * Math.max(1, hi - lo)) || !(hi > lo)) return null;
  const bent = unit(cross(restAxis(spec, bone, 0), restAxis(spec, bone, 2)));
  return bent && lean < 0 ? scale(bent, -1) : bent;
}

/** Whether bone `bone` of `spec` and its parent both have length at rest (so the limb can bend). */
function bendable(spec: RigSpec, bone: number): boolean {
  const parent = spec.parents[bone];
  return parent >= 0 && spec.lengths[bone] > 0 && norm(sub(restOrigin(spec, bone), restOrigin(spec, parent))) > 0;
}

/** The lower bone of effector bone `e`'s limb by the rule above, or -1. */
function lowerBone(spec: RigSpec, e: number, lowerRoles: Map<number, HumanoidRole> | null): number {
  if (lowerRoles) {
    for (let b = e; b >= 0; b = spec.parents[b]) if (lowerRoles.has(b)) return b;
    return -1;
  }
  const parent = spec.parents[e];
  return parent >= 0 && spec.parents[parent] >= 0 ? parent : -1;
}

/**
 * The limbs of `spec` that take a pole for end effectors `effectors` (bone indices), by the rule
 * above; `humanoid`: the rig's humanoid map, if it was recognised as one. Runs once per rig or
 * effector change (it allocates).
 */
export function poleLimbs(spec: RigSpec, effectors: ArrayLike<number>, humanoid?: HumanoidMap | null): PoleLimb[] {
  const lowerRoles = humanoid ? new Map<number, HumanoidRole>() : null;
  if (humanoid && lowerRoles)
    for (const role of LOWER_ROLES) {
      const b = humanoid.bones[role];
      if (b !== undefined) lowerRoles.set(b, role);
    }
  const frame = humanoid ? bodyFrame(spec, humanoid) : null;
  const limbs: PoleLimb[] = [];
  for (let k = 0; k < effectors.length; k++) {
    const bone = lowerBone(spec, effectors[k], lowerRoles);
    if (bone < 0 || limbs.some((l) => l.bone === bone) || !bendable(spec, bone)) continue;
    const role = lowerRoles?.get(bone);
    let restBend: Vec3 = FACING;
    if (humanoid && frame && role) {
      // A positive bend turns the lower bone's tip about `axis`, towards axis x bone; the joint
      // then leaves the root-tip line the other way: bone x axis.
      const bent = unit(cross(restAxis(spec, bone, 0), bendAxis(spec, humanoid, role, bone, frame).axis));
      if (bent) restBend = bent;
    } else if (!humanoid) restBend = limitsBend(spec, bone) ?? FACING;
    limbs.push({ bone, restBend });
  }
  return limbs;
}
