// Test humanoids: one body (meters, T-pose, Y up, facing +Z) whose bones each naming convention
// names and arranges its own way (Biped hangs the thighs off the spine, Rigify puts a bone
// between neck and head...), plus the helper bones real files carry (finger, end, twist and IK
// bones), so that recognition has to pick the right ones.
import type { HumanoidRole } from '../../web/src/rig/humanoid/humanoid_roles.js';
import { type Vec3, add, mirrorX } from '../../scripts/models/vec.js';
import type { SkeletonJoint } from './skeleton_glb.js';

interface BodyJoint {
  parent?: HumanoidRole;
  head: Vec3;
}

/** The joints of one side's limbs, mirrored for the right side. */
function limbs(side: 'left' | 'right'): [HumanoidRole, BodyJoint][] {
  const at = (p: Vec3): Vec3 => (side === 'left' ? p : mirrorX(p));
  const r = (part: string): HumanoidRole => `${side}${part}` as HumanoidRole;
  return [
    [r('Shoulder'), { parent: 'upperChest', head: at([0.04, 1.44, 0]) }],
    [r('UpperArm'), { parent: r('Shoulder'), head: at([0.16, 1.44, 0]) }],
    [r('LowerArm'), { parent: r('UpperArm'), head: at([0.44, 1.44, -0.01]) }],
    [r('Hand'), { parent: r('LowerArm'), head: at([0.7, 1.44, 0]) }],
    [r('UpperLeg'), { parent: 'hips', head: at([0.1, 0.95, 0]) }],
    [r('LowerLeg'), { parent: r('UpperLeg'), head: at([0.1, 0.52, 0.01]) }],
    [r('Foot'), { parent: r('LowerLeg'), head: at([0.1, 0.08, 0]) }],
    [r('Toes'), { parent: r('Foot'), head: at([0.1, 0, 0.12]) }],
  ];
}

/** Each role's joint: its parent role in the usual hierarchy and its position. */
export const BODY = Object.fromEntries([
  ['hips', { head: [0, 1, 0] }],
  ['spine', { parent: 'hips', head: [0, 1.1, 0] }],
  ['chest', { parent: 'spine', head: [0, 1.22, 0] }],
  ['upperChest', { parent: 'chest', head: [0, 1.34, 0] }],
  ['neck', { parent: 'upperChest', head: [0, 1.48, 0] }],
  ['head', { parent: 'neck', head: [0, 1.58, 0] }],
  ...limbs('left'),
  ...limbs('right'),
]) as Record<HumanoidRole, BodyJoint>;

export interface HumanoidNaming {
  /** The bone name of each role the skeleton has (a role left out has no bone). */
  roles: Partial<Record<HumanoidRole, string>>;
  /** A parent other than the usual one: a role, or the name of a root or extra bone. */
  parents?: Partial<Record<HumanoidRole, string>>;
  /** A bone above the hips (at the origin). */
  root?: string;
  /** More bones: a parent (role or bone name) and the offset from the parent's joint. */
  extra?: { name: string; parent: string; offset: Vec3 }[];
}

/** The joints of the test humanoid named by `naming`, for skeletonGlb. */
export function humanoidJoints(naming: HumanoidNaming): SkeletonJoint[] {
  const nameOf = (ref: string): string => naming.roles[ref as HumanoidRole] ?? ref;
  // The usual parent, or the nearest named bone above it, or the root.
  const usualParent = (role: HumanoidRole): string | undefined => {
    for (let p = BODY[role].parent; p !== undefined; p = BODY[p].parent)
      if (naming.roles[p] !== undefined) return naming.roles[p];
    return naming.root;
  };
  const joints: SkeletonJoint[] = naming.root === undefined ? [] : [{ name: naming.root, head: [0, 0, 0] }];
  for (const [role, name] of Object.entries(naming.roles) as [HumanoidRole, string][]) {
    const override = naming.parents?.[role];
    joints.push({ name, parent: override === undefined ? usualParent(role) : nameOf(override), head: BODY[role].head });
  }
  for (const e of naming.extra ?? []) {
    const parent = joints.find((j) => j.name === nameOf(e.parent));
    if (!parent) throw new Error(`extra bone ${e.name}: its parent ${e.parent} comes later or does not exist`);
    joints.push({ name: e.name, parent: parent.name, head: add(parent.head, e.offset) });
  }
  return joints;
}
