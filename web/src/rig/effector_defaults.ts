// Defaults for a glTF rig without IK metadata (docs/gltf-ik-extras.md, "Defaults"):
// end effectors are the bones that look like the hands, feet and head by name, else every leaf;
// limits are +-180 degrees per XZX angle.
import { isSideToken, nameSide, nameTokens, type Side } from './bone_names.js';

/** Default XZX limit, degrees: every angle in [-180, 180]. */
export const DEFAULT_LIMIT_DEG = 180;

type Role = 'hand' | 'foot' | 'head';

const ROLE_WORDS: Record<Role, string[]> = {
  hand: ['hand', 'wrist'],
  foot: ['foot', 'ankle'],
  head: ['head'],
};

// A name with one of these words is a part of a hand or foot, not the hand or foot itself.
const EXCLUDE = new Set([
  'thumb', 'index', 'middle', 'ring', 'pinky', 'little', 'finger', 'fingers', 'toe', 'toes', 'ball', 'heel',
  'ik', 'fk', 'target', 'pole', 'ctrl', 'control', 'twist', 'roll', 'mch',
]);

export interface BoneForDefaults {
  name: string;
  /** Depth in the rig (0 for a root). */
  depth: number;
}

/**
 * Bone indices (ascending) of the default end effectors: for each of head, left/right hand,
 * left/right foot (and an unsided hand or foot), the bone whose name names it with the fewest other
 * words (then the shallowest, then the first). Returns an empty array when no name matches.
 */
export function effectorsByName(bones: BoneForDefaults[]): number[] {
  const best = new Map<string, { bone: number; extra: number; depth: number }>();
  bones.forEach((bone, index) => {
    const tokens = nameTokens(bone.name);
    if (tokens.some((t) => EXCLUDE.has(t))) return;
    const side: Side = nameSide(tokens);
    for (const role of Object.keys(ROLE_WORDS) as Role[]) {
      const word = tokens.find((t) => ROLE_WORDS[role].includes(t));
      if (word === undefined || (role === 'head' && side !== 'none')) continue;
      // Words other than the role word, the side and digits: "mixamorig", "top", "end"...
      const extra = tokens.filter((t) => t !== word && !isSideToken(t) && !/^[0-9]+$/.test(t)).length;
      const key = `${role} ${side}`;
      const current = best.get(key);
      if (!current || extra < current.extra || (extra === current.extra && bone.depth < current.depth))
        best.set(key, { bone: index, extra, depth: bone.depth });
    }
  });
  return [...new Set([...best.values()].map((b) => b.bone))].sort((a, b) => a - b);
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
