// Which end effectors a drag or reach path can move while the others stay pinned, and the chains
// that carry them. Bones are indices into the spec; effectors are indices into spec.effectors.
import type { RigSpec } from '#ik/rig_arrays.js';

/** Per bone, the end effectors on it or below it (an effector listed twice counts twice). */
function effectorsBelow(spec: RigSpec): Int32Array {
  const n = spec.parents.length;
  const below = new Int32Array(n);
  for (const b of spec.effectors) below[b]++;
  for (const b of childrenFirst(spec.parents)) if (spec.parents[b] !== -1) below[spec.parents[b]] += below[b];
  return below;
}

/** Every bone reachable from a root, each after all of its children (a reversed breadth-first walk). */
function childrenFirst(parents: Int32Array): number[] {
  const children: number[][] = Array.from(parents, () => []);
  const order: number[] = [];
  parents.forEach((p, b) => (p === -1 ? order.push(b) : children[p].push(b)));
  for (let k = 0; k < order.length; k++) for (const c of children[order[k]]) order.push(c);
  return order.reverse();
}

/**
 * Per end effector (index into spec.effectors), the movable angles that move it and no other
 * effector: angles of bones on its chain that are on no other effector's chain, and not fixed.
 * Those bones are the ones from the effector's bone up while a single effector lies below, so
 * the whole takes time linear in the bones and effectors.
 */
export function exclusiveAngles(spec: RigSpec): number[][] {
  const below = effectorsBelow(spec);
  return Array.from(spec.effectors, (effectorBone) => {
    const bones: number[] = [];
    for (let b = effectorBone; b !== -1 && below[b] === 1; b = spec.parents[b]) bones.push(b);
    const angles: number[] = [];
    for (const bone of bones.sort((x, y) => x - y))
      for (let k = 3 * bone; k < 3 * bone + 3; k++) if (spec.lower[k] < spec.upper[k]) angles.push(k);
    return angles;
  });
}

/** Effectors a drag path can move with the others pinned (non-empty exclusive angle sets). */
export function draggableEffectors(spec: RigSpec): number[] {
  return exclusiveAngles(spec)
    .map((angles, e) => (angles.length > 0 ? e : -1))
    .filter((e) => e >= 0);
}

/**
 * The top bone of the unbranched chain ending at `bone`: walks up from `bone` while the parent has
 * exactly one child. The result is `bone` itself when its parent branches, or a root.
 */
export function chainRootBone(spec: RigSpec, bone: number): number {
  const children = new Int32Array(spec.parents.length);
  for (const p of spec.parents) if (p !== -1) children[p]++;
  let b = bone;
  while (spec.parents[b] !== -1 && children[spec.parents[b]] === 1) b = spec.parents[b];
  return b;
}
