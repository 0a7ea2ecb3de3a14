// Which end effectors a drag or reach path can move while the others stay pinned, and the chains
// that carry them. Bones are indices into the spec; effectors are indices into spec.effectors.
import type { RigSpec } from '../web/src/ik/rig_spec.js';

/** Bones from `bone` up to its root, inclusive. */
function chainOf(spec: RigSpec, bone: number): number[] {
  const chain: number[] = [];
  for (let b = bone; b !== -1; b = spec.parents[b]) chain.push(b);
  return chain;
}

/**
 * Per end effector (index into spec.effectors), the movable angles that move it and no other
 * effector: angles of bones on its chain that are on no other effector's chain, and not fixed.
 */
export function exclusiveAngles(spec: RigSpec): number[][] {
  const chains = Array.from(spec.effectors, (b) => new Set(chainOf(spec, b)));
  return chains.map((chain, e) => {
    const angles: number[] = [];
    for (const bone of [...chain].sort((x, y) => x - y)) {
      if (chains.some((other, f) => f !== e && other.has(bone))) continue;
      for (let k = 3 * bone; k < 3 * bone + 3; k++) if (spec.lower[k] < spec.upper[k]) angles.push(k);
    }
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
