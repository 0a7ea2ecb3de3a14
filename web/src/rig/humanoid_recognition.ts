// Humanoid recognition (docs/gltf-ik-extras.md, "Humanoid recognition"): which bone of a rig
// plays which VRM humanoid role. A VRM extension is authoritative; otherwise every naming
// convention is tried and the one that maps the most core roles wins (ties: Mixamo, Unreal,
// Rigify, Biped, generic). A rig is a humanoid when the hips and both legs or both arms are found.
import type { JsonObject } from './gltf_json.js';
import { CONVENTIONS, readBoneName } from './humanoid_names.js';
import { CORE_HUMANOID_ROLES, type HumanoidMap, type HumanoidRole, type HumanoidSource } from './humanoid_roles.js';
import { assembleHumanoid, type RoleBones } from './humanoid_skeleton.js';
import { BoneTree } from './humanoid_tree.js';
import { readVrmHumanoid } from './humanoid_vrm.js';

export interface HumanoidRecognition {
  /** The mapping, or null when the rig is not recognised as a humanoid. */
  map: HumanoidMap | null;
  /** Lines for the rig's warnings: what matched, and any problem with a VRM extension. */
  notes: string[];
}

/** Roles that must all be found, besides the hips, for a humanoid: the legs, or the arms. */
const LIMB_SETS: readonly (readonly HumanoidRole[])[] = [
  ['leftUpperLeg', 'leftLowerLeg', 'leftFoot', 'rightUpperLeg', 'rightLowerLeg', 'rightFoot'],
  ['leftUpperArm', 'leftLowerArm', 'leftHand', 'rightUpperArm', 'rightLowerArm', 'rightHand'],
];

/** True when `bones` has the hips and both legs or both arms. */
function isHumanoid(bones: RoleBones): boolean {
  return bones.hips !== undefined && LIMB_SETS.some((set) => set.every((r) => bones[r] !== undefined));
}

const coreCount = (bones: RoleBones): number => CORE_HUMANOID_ROLES.filter((r) => bones[r] !== undefined).length;

/**
 * The humanoid roles found from bone names alone: `names` and `parents` of the rig's bones (parents
 * first, depth-first). The convention mapping the most core roles wins.
 */
export function humanoidByName(names: readonly string[], parents: ArrayLike<number>): { source: HumanoidSource; bones: RoleBones } {
  const read = names.map(readBoneName);
  const tree = new BoneTree(parents);
  let best: { source: HumanoidSource; bones: RoleBones } | undefined;
  for (const c of CONVENTIONS) {
    const bones = assembleHumanoid(read, tree, c);
    if (!best || coreCount(bones) > coreCount(best.bones)) best = { source: c.source, bones };
  }
  return best!;
}

/**
 * Recognises the humanoid of a glTF rig: `json` is the document (for a VRM extension), `names`
 * the bones' node names, `parents` their parents (depth-first), `boneOfNode` the bone of each node
 * (-1 for a node that is no joint). Linear in the file apart from sorting candidates.
 */
export function recognizeHumanoid(json: JsonObject, names: readonly string[], parents: ArrayLike<number>, boneOfNode: Int32Array): HumanoidRecognition {
  const notes: string[] = [];
  const vrm = readVrmHumanoid(json, boneOfNode);
  if (vrm?.problem) notes.push(vrm.bones ? vrm.problem : `${vrm.problem}: bones recognised by name instead`);
  const found = vrm?.bones ? { source: vrm.source, bones: vrm.bones } : humanoidByName(names, parents);
  if (!isHumanoid(found.bones)) return { map: null, notes };

  const missing = CORE_HUMANOID_ROLES.filter((r) => found.bones[r] === undefined);
  const matched = `${CORE_HUMANOID_ROLES.length - missing.length} of ${CORE_HUMANOID_ROLES.length} core roles`;
  notes.unshift(`humanoid (${found.source}): ${matched}${missing.length ? `; missing ${missing.join(', ')}` : ''}`);
  return { map: { source: found.source, bones: found.bones, missing }, notes };
}
