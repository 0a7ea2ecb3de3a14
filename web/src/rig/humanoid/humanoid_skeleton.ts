// A humanoid assembled from the bones one naming convention names, kept consistent with the tree
// (docs/gltf-ik-extras.md, "Humanoid recognition"): each limb runs down the tree (a lower leg
// below its upper leg, a foot below that; the legs below the hips); among several bones named for
// one role the one nearest the root that fits wins. The spine, chest and upper chest are not read
// from names: they are the bones between the hips and the neck, in order. Control bones
// (control_bones.ts) take no role; where one is named as a side's foot (or hand) and the leg (arm)
// has no foot (hand) below its lower leg (arm), the lower bone's child is the foot (hand): the
// limb's own end stands in for the control.
import type { Side } from '../bone_names.js';
import { limbRoles, type ControlBone, type EndStandIn } from './control_bones.js';
import {
  MIDLINE_PARTS,
  namedPart,
  nameTable,
  type BodyPart,
  type BoneName,
  type Convention,
} from './humanoid_names.js';
import type { HumanoidRole } from './humanoid_roles.js';
import type { BoneTree } from './humanoid_tree.js';

/** Role -> bone index, for the roles found. */
export type RoleBones = Partial<Record<HumanoidRole, number>>;

const LEG: readonly BodyPart[] = ['upperLeg', 'lowerLeg', 'foot', 'toes'];
const ARM: readonly BodyPart[] = ['shoulder', 'upperArm', 'lowerArm', 'hand'];
const NECK_HEAD: readonly BodyPart[] = ['neck', 'head'];

/** The role of a part on a side: ('left', 'upperArm') -> leftUpperArm, ('none', 'head') -> head. */
function roleOf(side: Side, part: BodyPart): HumanoidRole {
  return (side === 'none' ? part : `${side}${part[0].toUpperCase()}${part.slice(1)}`) as HumanoidRole;
}

interface Candidate {
  bone: number;
  /** 0 for a convention's own names, 1 for its fallbacks. */
  rank: number;
}

/** The roles a convention finds, and the limb ends that stand in for control bones among them. */
export interface AssembledHumanoid {
  bones: RoleBones;
  /** Hands and feet that are the lower bone's child in place of a control bone named as them. */
  standIns: EndStandIn[];
}

/**
 * The roles `convention` finds in a rig: `names` holds each bone's read name (null for a helper
 * or unnamed bone), `tree` the rig's bone tree, `controls` its control bones. Time O(n log n) in
 * the bones.
 */
export function assembleHumanoid(
  names: readonly (BoneName | null)[],
  tree: BoneTree,
  convention: Convention,
  controls: readonly ControlBone[] = [],
): AssembledHumanoid {
  const table = nameTable(convention);
  const isControl = new Set(controls.map((c) => c.bone));
  const candidates = new Map<HumanoidRole, Candidate[]>();
  names.forEach((name, bone) => {
    if (name === null || isControl.has(bone)) return;
    const hit = namedPart(name, table, convention.numbered);
    // Head, neck and hips have no side; a limb part must have one.
    if (!hit || MIDLINE_PARTS.includes(hit.part) !== (name.side === 'none')) return;
    const role = roleOf(name.side, hit.part);
    const list = candidates.get(role);
    if (list) list.push({ bone, rank: hit.rank });
    else candidates.set(role, [{ bone, rank: hit.rank }]);
  });
  for (const list of candidates.values())
    list.sort((a, b) => a.rank - b.rank || tree.depth[a.bone] - tree.depth[b.bone] || a.bone - b.bone);
  const of = (role: HumanoidRole): Candidate[] => candidates.get(role) ?? [];

  const bones: RoleBones = {};
  // The hips: the first candidate with an upper leg below it, else the first.
  const hasLegBelow = tree.markedBelow([...of('leftUpperLeg'), ...of('rightUpperLeg')].map((c) => c.bone));
  const hips = of('hips').find((c) => hasLegBelow(c.bone)) ?? of('hips')[0];
  if (hips) bones.hips = hips.bone;

  // A chain of parts, each the first candidate below the previous part found (or below `anchor`).
  const chain = (side: Side, parts: readonly BodyPart[], anchor: number | undefined): void => {
    for (const part of parts) {
      const role = roleOf(side, part);
      const hit = of(role).find((c) => anchor === undefined || tree.below(c.bone, anchor));
      if (!hit) continue;
      bones[role] = hit.bone;
      anchor = hit.bone;
    }
  };
  for (const side of ['left', 'right'] as const) {
    chain(side, LEG, bones.hips);
    chain(side, ARM, undefined);
  }
  chain('none', NECK_HEAD, undefined);

  // A hand or foot named only by a control bone: the lower arm's or leg's child, when it has one
  // that is neither a control, a helper nor mapped already (the child with the biggest subtree).
  const standIns: EndStandIn[] = [];
  for (const c of controls) {
    if (c.kind !== 'limbEnd' || c.side === 'none' || !c.limb) continue;
    const { lower, end } = limbRoles(c.limb, c.side);
    const low = bones[lower];
    if (bones[end] !== undefined || low === undefined) continue;
    const used = new Set(Object.values(bones));
    let child: number | undefined;
    for (const k of tree.children(low))
      if (
        !isControl.has(k) &&
        names[k] !== null &&
        !used.has(k) &&
        (child === undefined || tree.descendants(k) > tree.descendants(child))
      )
        child = k;
    if (child === undefined) continue;
    bones[end] = child;
    standIns.push({ control: c.bone, end: child });
  }

  const top = bones.neck ?? bones.head;
  if (bones.hips !== undefined && top !== undefined) {
    const used = new Set(Object.values(bones));
    const torso = (tree.between(bones.hips, top) ?? []).filter((b) => !used.has(b));
    if (torso.length >= 1) bones.spine = torso[0];
    if (torso.length >= 2) bones.chest = torso[1];
    if (torso.length >= 3) bones.upperChest = torso[torso.length - 1];
  }
  return { bones, standIns };
}
