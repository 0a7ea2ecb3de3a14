// Defaults for a glTF rig without IK metadata (docs/gltf-ik-extras.md, "Defaults"): end
// effectors are a humanoid's hands, feet and head, else the bones that look like them by name (or
// end an arm), else every leaf; limits are +-180 degrees per XZX angle.
import { isSideToken, nameSide, nameTokens, type Side } from './bone_names.js';
import type { HumanoidMap, HumanoidRole } from './humanoid_roles.js';
import { maxEffectors } from './rig_limits.js';

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
  'thumb', 'index', 'middle', 'ring', 'pinky', 'little', 'finger', 'fingers', 'toe', 'toes', 'ball', 'heel',
  'ik', 'fk', 'target', 'pole', 'ctrl', 'control', 'twist', 'roll', 'mch',
]);

/** The roles whose bones are a humanoid's default end effectors. */
const HUMANOID_EFFECTOR_ROLES: readonly HumanoidRole[] = ['head', 'leftHand', 'rightHand', 'leftFoot', 'rightFoot'];

/** Bone indices (ascending) of a humanoid's head, hands and feet, those it maps. */
function humanoidEffectors(map: HumanoidMap): number[] {
  const bones = HUMANOID_EFFECTOR_ROLES.flatMap((r) => (map.bones[r] === undefined ? [] : [map.bones[r]]));
  return [...new Set(bones)].sort((a, b) => a - b);
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
 * Linear time.
 */
export function effectorsByName(names: readonly string[], parents: ArrayLike<number>): number[] {
  const depth = depths(parents);
  const tokens = names.map(nameTokens);
  const isArm = tokens.map((t) => t.some((w) => ARM_WORDS.has(w)));
  const armBelow = new Array<boolean>(names.length).fill(false);
  for (let b = names.length - 1; b >= 0; b--) if (parents[b] >= 0 && (isArm[b] || armBelow[b])) armBelow[parents[b]] = true;

  // Per role and side, the best bone: lowest [tier, other words, depth] (tier 1: an arm's end).
  const best = new Map<string, { bone: number; score: number[] }>();
  const offer = (key: string, bone: number, score: number[]): void => {
    const current = best.get(key);
    const k = current ? score.findIndex((v, i) => v !== current.score[i]) : -1;
    if (!current || (k >= 0 && score[k] < current.score[k])) best.set(key, { bone, score });
  };
  tokens.forEach((words, bone) => {
    if (words.some((t) => EXCLUDE.has(t))) return;
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
  return [...new Set([...best.values()].map((b) => b.bone))].sort((a, b) => a - b);
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
 * when they are more than the core takes). Bones in `excluded` (flagged effector: false) are never
 * chosen. `names`, `parents` as for effectorsByName.
 */
export function defaultEffectors(
  names: readonly string[],
  parents: ArrayLike<number>,
  humanoid: HumanoidMap | null,
  excluded: ReadonlySet<number>,
): DefaultEffectors {
  const kept = (bones: number[]): number[] => bones.filter((b) => !excluded.has(b));
  const byRole = humanoid ? kept(humanoidEffectors(humanoid)) : [];
  if (byRole.length) return { effectors: byRole, which: 'the hands, feet and head of the humanoid mapping' };
  const byName = kept(effectorsByName(names, parents));
  if (byName.length) return { effectors: byName, which: 'the hands, feet and head found by name' };
  const leaves = kept(leafBones(parents));
  const effectors = deepestBones(leaves, depths(parents), maxEffectors(parents.length));
  if (effectors.length === leaves.length) return { effectors, which: 'all leaf joints' };
  return { effectors, which: `the ${effectors.length} leaf joints furthest from the root, of ${leaves.length} (the most this rig may have)` };
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
  for (const b of bones)
    if (depth[b] > cut || (depth[b] === cut && room-- > 0)) kept.push(b);
  return kept;
}
