// Defaults for a glTF rig without IK metadata (docs/gltf-ik-extras.md, "Defaults"): end
// effectors are a humanoid's hands, feet and head, else the bones that look like them by name (or
// end an arm), else every leaf; limits are +-180 degrees per XZX angle. Control bones
// (control_bones.ts: IK targets and poles off the root, a foot off the root beside the legs) are
// never chosen: where one is named as a hand or foot, the limb's own end is taken in its place.
import { isSideToken, nameSide, nameTokens, type Side } from '../bone_names.js';
import {
  controlBones,
  limbChainEnd,
  limbRoles,
  lowerLimbStandIns,
  type ControlBone,
  type EndStandIn,
} from '../humanoid/control_bones.js';
import { listed } from './gltf_json.js';
import type { HumanoidMap, HumanoidRole } from '../humanoid/humanoid_roles.js';
import { maxEffectors } from '../rig_limits.js';

/** Default XZX limit, degrees: every angle in [-180, 180]. */
export const DEFAULT_LIMIT_DEG = 180;

type Role = 'hand' | 'foot' | 'head';

const ROLE_WORDS: Record<Role, string[]> = {
  hand: ['hand', 'wrist', 'palm', 'gripper', 'claw', 'pincer'],
  foot: ['foot', 'ankle'],
  head: ['head'],
};

// A bone below one of these ends an arm; the first bone past the arm without them is its hand.
const ARM_WORDS = new Set(['arm', 'upperarm', 'lowerarm', 'forearm', 'elbow']);

// A name with one of these words is a part of a hand or foot, not the hand or foot itself.
const EXCLUDE = new Set([
  'thumb',
  'index',
  'middle',
  'ring',
  'pinky',
  'little',
  'finger',
  'fingers',
  'toe',
  'toes',
  'ball',
  'heel',
  'ik',
  'fk',
  'target',
  'pole',
  'ctrl',
  'control',
  'twist',
  'roll',
  'mch',
]);

/** The roles whose bones are a humanoid's default end effectors. */
const HUMANOID_EFFECTOR_ROLES: readonly HumanoidRole[] = ['head', 'leftHand', 'rightHand', 'leftFoot', 'rightFoot'];

/**
 * Bone indices (ascending) of a humanoid's head, hands and feet, those it maps, and a lower arm
 * or leg with no hand or foot mapped below it where a control bone is named as that hand or foot.
 * A limb the mapping leaves out (RobotExpressive's legs hang off the body beside its hips) whose
 * end a control bone names gets the end of its chain by name (limbChainEnd) all the same.
 */
function humanoidEffectors(
  map: HumanoidMap,
  controls: readonly ControlBone[],
  names: readonly string[],
  parents: ArrayLike<number>,
): { effectors: number[]; standIns: EndStandIn[] } {
  const bones = HUMANOID_EFFECTOR_ROLES.flatMap((r) => (map.bones[r] === undefined ? [] : [map.bones[r]]));
  const standIns = lowerLimbStandIns(map.bones, controls);
  const isControl = new Set(controls.map((c) => c.bone));
  for (const c of controls) {
    if (c.kind !== 'limbEnd' || !c.limb || c.side === 'none') continue;
    const { lower, end: endRole } = limbRoles(c.limb, c.side);
    if (map.bones[lower] !== undefined || map.bones[endRole] !== undefined) continue;
    const end = limbChainEnd(names, parents, c.limb, c.side, isControl);
    if (end !== undefined && !standIns.some((s) => s.end === end)) standIns.push({ control: c.bone, end });
  }
  return { effectors: [...new Set([...bones, ...standIns.map((s) => s.end)])].sort((a, b) => a - b), standIns };
}

/** Depth of each bone in a parents-first parent array (0 for a root). */
function depths(parents: ArrayLike<number>): Int32Array {
  const depth = new Int32Array(parents.length);
  for (let b = 0; b < parents.length; b++) if (parents[b] >= 0) depth[b] = depth[parents[b]] + 1;
  return depth;
}

/**
 * Bone indices (ascending) of the default end effectors by name, for a rig that is no humanoid:
 * for each of head, left/right hand, left/right foot (and an unsided hand or foot), the bone whose
 * name names it with the fewest other words (then the shallowest, then the first). Hand words are
 * hand, wrist, palm, gripper, claw and pincer. A side without a hand word gets the bone that ends
 * an arm instead: the child of a bone named arm/forearm/elbow... with no such bone in its own
 * subtree. A hand ending an arm is sided like its name, else like the arm. `names` are the bones'
 * names, `parents` their parents (parents first). Returns an empty array when nothing matches.
 * Control bones (`controls`, found here when not given) are never taken; a side whose hand or
 * foot only a control bone names gets the end of that arm or leg (limbChainEnd). Linear time.
 */
export function effectorsByName(
  names: readonly string[],
  parents: ArrayLike<number>,
  controls: readonly ControlBone[] = controlBones(names, parents),
): number[] {
  return namedEffectors(names, parents, controls).effectors;
}

/** effectorsByName, and the limb ends taken in place of control bones. */
function namedEffectors(
  names: readonly string[],
  parents: ArrayLike<number>,
  controls: readonly ControlBone[],
): { effectors: number[]; standIns: EndStandIn[] } {
  const isControl = new Set(controls.map((c) => c.bone));
  const depth = depths(parents);
  const tokens = names.map(nameTokens);
  const isArm = tokens.map((t) => t.some((w) => ARM_WORDS.has(w)));
  const armBelow = new Array<boolean>(names.length).fill(false);
  for (let b = names.length - 1; b >= 0; b--)
    if (parents[b] >= 0 && (isArm[b] || armBelow[b])) armBelow[parents[b]] = true;

  // Per role and side, the best bone: lowest [tier, other words, depth] (tier 1: an arm's end).
  const best = new Map<string, { bone: number; score: number[] }>();
  const offer = (key: string, bone: number, score: number[]): void => {
    const current = best.get(key);
    const k = current ? score.findIndex((v, i) => v !== current.score[i]) : -1;
    if (!current || (k >= 0 && score[k] < current.score[k])) best.set(key, { bone, score });
  };
  tokens.forEach((words, bone) => {
    if (isControl.has(bone) || words.some((t) => EXCLUDE.has(t))) return;
    const p = parents[bone];
    const side: Side = nameSide(words);
    const endsArm = p >= 0 && isArm[p] && !isArm[bone] && !armBelow[bone];
    // A hand without a side in its name takes the side of the arm it ends ("claw" below "forearm_r").
    const handSide: Side = side === 'none' && endsArm ? nameSide(tokens[p]) : side;
    let named = false;
    for (const role of Object.keys(ROLE_WORDS) as Role[]) {
      const word = words.find((t) => ROLE_WORDS[role].includes(t));
      if (word === undefined || (role === 'head' && side !== 'none')) continue;
      named = true;
      // Words other than the role word, the side and digits: "mixamorig", "top", "end"...
      const extra = words.filter((t) => t !== word && !isSideToken(t) && !/^[0-9]+$/.test(t)).length;
      offer(`${role} ${role === 'hand' ? handSide : side}`, bone, [0, extra, depth[bone]]);
    }
    if (!named && endsArm) offer(`hand ${handSide}`, bone, [1, 0, depth[bone]]);
  });
  // A hand or foot named only by a control bone: the end of the limb instead (an arm's end found
  // above is kept).
  const standIns: EndStandIn[] = [];
  for (const c of controls) {
    if (c.kind !== 'limbEnd' || !c.limb) continue;
    const key = `${c.limb === 'leg' ? 'foot' : 'hand'} ${c.side}`;
    const current = best.get(key);
    if (current && current.score[0] === 0) continue;
    const end = current?.bone ?? limbChainEnd(names, parents, c.limb, c.side, isControl);
    if (end === undefined) continue;
    best.set(key, { bone: end, score: [1, 0, depth[end]] });
    if (!standIns.some((s) => s.end === end)) standIns.push({ control: c.bone, end });
  }
  return { effectors: [...new Set([...best.values()].map((b) => b.bone))].sort((a, b) => a - b), standIns };
}

/** ", the ends of the limbs (A, B) in place of the control bones off the root (C, D)", or ''. */
function standInText(names: readonly string[], standIns: readonly EndStandIn[]): string {
  if (standIns.length === 0) return '';
  const ends = listed(standIns.map((s) => names[s.end]));
  const controls = listed(standIns.map((s) => names[s.control]));
  return standIns.length === 1
    ? `, the end of a limb (${ends}) in place of the control bone off the root (${controls})`
    : `, the ends of the limbs (${ends}) in place of the control bones off the root (${controls})`;
}

/** The default end effectors and how they were chosen (for the warning). */
export interface DefaultEffectors {
  effectors: number[];
  /** "the hands, feet and head of the humanoid mapping", "all leaf joints"... */
  which: string;
}

/**
 * The default end effectors of a rig none of whose joints is flagged one: a humanoid's head,
 * hands and feet, else those found by name (effectorsByName), else the leaves (the deepest ones
 * when they are more than the core takes). Bones in `excluded` (flagged effector: false) and control
 * bones (control_bones.ts) are never chosen. `names`, `parents` as for effectorsByName.
 */
export function defaultEffectors(
  names: readonly string[],
  parents: ArrayLike<number>,
  humanoid: HumanoidMap | null,
  excluded: ReadonlySet<number>,
): DefaultEffectors {
  const controls = controlBones(names, parents);
  const isControl = new Set(controls.map((c) => c.bone));
  const kept = (bones: number[]): number[] => bones.filter((b) => !excluded.has(b) && !isControl.has(b));
  const keptStandIns = (standIns: EndStandIn[]): EndStandIn[] => standIns.filter((s) => !excluded.has(s.end));
  if (humanoid) {
    const byRole = humanoidEffectors(humanoid, controls, names, parents);
    const effectors = kept(byRole.effectors);
    const which = `the hands, feet and head of the humanoid mapping${standInText(names, keptStandIns(byRole.standIns))}`;
    if (effectors.length) return { effectors, which };
  }
  const byName = namedEffectors(names, parents, controls);
  const named = kept(byName.effectors);
  if (named.length)
    return {
      effectors: named,
      which: `the hands, feet and head found by name${standInText(names, keptStandIns(byName.standIns))}`,
    };
  // Leaves, but control bones only when every leaf is one.
  const allLeaves = leafBones(parents).filter((b) => !excluded.has(b));
  const leaves = allLeaves.some((b) => !isControl.has(b)) ? allLeaves.filter((b) => !isControl.has(b)) : allLeaves;
  const effectors = deepestBones(leaves, depths(parents), maxEffectors(parents.length));
  if (effectors.length === leaves.length) return { effectors, which: 'all leaf joints' };
  return {
    effectors,
    which: `the ${effectors.length} leaf joints furthest from the root, of ${leaves.length} (the most this rig may have)`,
  };
}

/**
 * The end effectors (of `effectors`) that only the root moves: a root itself, or a bone whose
 * parent is a root. Dragging one swings the whole rig.
 */
export function rootChainEffectors(effectors: readonly number[], parents: ArrayLike<number>): number[] {
  return effectors.filter((e) => parents[e] < 0 || parents[parents[e]] < 0);
}

/** Bone indices (ascending) of the leaves: bones no other bone has as parent. */
export function leafBones(parents: ArrayLike<number>): number[] {
  const hasChild = new Array<boolean>(parents.length).fill(false);
  for (let i = 0; i < parents.length; i++) if (parents[i] >= 0) hasChild[parents[i]] = true;
  const leaves: number[] = [];
  hasChild.forEach((c, i) => !c && leaves.push(i));
  return leaves;
}

/**
 * The `keep` bones of `bones` (ascending) furthest from the root: greatest `depth`, then lowest
 * index. Returned ascending; all of `bones` when they are no more than `keep`. Linear time.
 */
export function deepestBones(bones: readonly number[], depth: ArrayLike<number>, keep: number): number[] {
  if (bones.length <= keep) return [...bones];
  let deepest = 0;
  for (const b of bones) deepest = Math.max(deepest, depth[b]);
  const atDepth = new Int32Array(deepest + 1);
  for (const b of bones) atDepth[depth[b]]++;
  // The shallowest depth kept, and how many bones of that depth fit after all deeper ones.
  let cut = deepest;
  let room = keep;
  while (room > atDepth[cut]) room -= atDepth[cut--];
  const kept: number[] = [];
  for (const b of bones) if (depth[b] > cut || (depth[b] === cut && room-- > 0)) kept.push(b);
  return kept;
}
