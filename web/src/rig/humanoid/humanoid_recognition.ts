// Humanoid recognition (docs/gltf-ik-extras.md, "Humanoid recognition"): which bone of a rig
// plays which VRM humanoid role. A VRM extension is authoritative; otherwise every naming
// convention is tried and the one that maps the most core roles wins (ties: Mixamo, Unreal,
// Rigify, Biped, generic). A rig is a humanoid when the hips and both legs or both arms are found.
// Control bones (control_bones.ts) take no role, and the notes name them.
import { controlBones, lowerLimbStandIns, type ControlBone, type EndStandIn } from './control_bones.js';
import { listed, type JsonObject } from '../gltf/gltf_json.js';
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
 * first, depth-first), `controls` its control bones (found here when not given). The convention
 * mapping the most core roles wins. `standIns`: the hands and feet that are a limb's own end in
 * place of a control bone named as them.
 */
export function humanoidByName(
  names: readonly string[],
  parents: ArrayLike<number>,
  controls: readonly ControlBone[] = controlBones(names, parents),
): { source: HumanoidSource; bones: RoleBones; standIns: EndStandIn[] } {
  const read = names.map(readBoneName);
  const tree = new BoneTree(parents);
  let best: { source: HumanoidSource; bones: RoleBones; standIns: EndStandIn[] } | undefined;
  for (const c of CONVENTIONS) {
    const { bones, standIns } = assembleHumanoid(read, tree, c, controls);
    if (!best || coreCount(bones) > coreCount(best.bones)) best = { source: c.source, bones, standIns };
  }
  return best!;
}

/** "control bone X" or "3 control bones (X, Y, Z)". */
function counted(noun: string, items: string[]): string {
  return items.length === 1 ? `${noun} ${items[0]}` : `${items.length} ${noun}s (${listed(items)})`;
}

/** The notes on control bones: which were left out, and which limb ends stand in for them. */
function controlNotes(
  names: readonly string[],
  controls: readonly ControlBone[],
  map: HumanoidMap | null,
  standIns: readonly EndStandIn[],
): string[] {
  if (controls.length === 0) return [];
  const notes = [
    `${counted(
      'control bone',
      controls.map((c) => names[c.bone]),
    )} off the root (IK targets, poles, or a hand or foot outside the limbs): ` +
      'not taken as default end effectors nor as humanoid bones',
  ];
  if (!map) return notes;
  const roleOf = new Map(Object.entries(map.bones).map(([role, bone]) => [bone, role]));
  for (const s of standIns)
    notes.push(
      `${roleOf.get(s.end)} is ${names[s.end]}, the end of its limb, in place of the control bone ${names[s.control]}`,
    );
  for (const s of lowerLimbStandIns(map.bones, controls))
    notes.push(
      `${roleOf.get(s.end)} ${names[s.end]} ends its limb: its tip is the end effector in place of the control bone ${names[s.control]}`,
    );
  return notes;
}

/**
 * Recognises the humanoid of a glTF rig: `json` is the document (for a VRM extension), `names`
 * the bones' node names, `parents` their parents (depth-first), `boneOfNode` the bone of each node
 * (-1 for a node that is no joint). Linear in the file apart from sorting candidates.
 */
export function recognizeHumanoid(
  json: JsonObject,
  names: readonly string[],
  parents: ArrayLike<number>,
  boneOfNode: Int32Array,
): HumanoidRecognition {
  const notes: string[] = [];
  const vrm = readVrmHumanoid(json, boneOfNode);
  if (vrm?.problem) notes.push(vrm.bones ? vrm.problem : `${vrm.problem}: bones recognised by name instead`);
  const controls = controlBones(names, parents);
  const found = vrm?.bones
    ? { source: vrm.source, bones: vrm.bones, standIns: [] }
    : humanoidByName(names, parents, controls);
  if (!isHumanoid(found.bones)) return { map: null, notes: [...notes, ...controlNotes(names, controls, null, [])] };

  const missing = CORE_HUMANOID_ROLES.filter((r) => found.bones[r] === undefined);
  const matched = `${CORE_HUMANOID_ROLES.length - missing.length} of ${CORE_HUMANOID_ROLES.length} core roles`;
  notes.unshift(`humanoid (${found.source}): ${matched}${missing.length ? `; missing ${missing.join(', ')}` : ''}`);
  const map: HumanoidMap = { source: found.source, bones: found.bones, missing };
  notes.push(...controlNotes(names, controls, map, found.standIns));
  return { map, notes };
}
