// Which child a bone points at when its joint has several child joints (docs/gltf-ik-extras.md,
// "Bone axis and length"): the chain continues through the body's midline first, then through
// the biggest subtree, then through a child whose name says spine/neck/head/middle, then the first.
import { nameSide, nameTokens } from './bone_names.js';

const HINTS = new Set(['spine', 'chest', 'torso', 'neck', 'head', 'middle', 'mid']);

export interface ChildCandidate {
  /** Bone index of the child. */
  bone: number;
  name: string;
  /** Number of bones below the child (its descendants). */
  descendants: number;
}

/**
 * The candidate the chain continues through, by these rules in order:
 * 1. a child whose name has no side (left/right) before a sided one;
 * 2. more descendants;
 * 3. a name with one of the words spine, chest, torso, neck, head, middle, mid;
 * 4. the first in the list (glTF children order).
 * `candidates` must not be empty.
 */
export function chooseChainChild(candidates: ChildCandidate[]): ChildCandidate {
  const key = (c: ChildCandidate): number[] => {
    const tokens = nameTokens(c.name);
    return [nameSide(tokens) === 'none' ? 1 : 0, c.descendants, tokens.some((t) => HINTS.has(t)) ? 1 : 0];
  };
  let best = candidates[0];
  let bestKey = key(best);
  for (const c of candidates.slice(1)) {
    const k = key(c);
    const i = k.findIndex((v, j) => v !== bestKey[j]);
    if (i >= 0 && k[i] > bestKey[i]) {
      best = c;
      bestKey = k;
    }
  }
  return best;
}
