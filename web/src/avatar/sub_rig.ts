// The part of a rig that moves a few bones: those bones and every bone above them, as a rig of its
// own. The avatar solves on it (a character's fingers, toes and eyes are a third to a half of its
// bones, and no tracked point moves with them), then writes its angles back into the whole rig's,
// whose other bones keep theirs. Rest transforms are per bone in world space (rig_arrays.ts), so a
// bone kept has the same rest, limits and length in both.
import type { RigSpec } from '../ik/rig_arrays.js';
import type { HumanoidMap, HumanoidRole } from '../rig/humanoid/humanoid_roles.js';

export interface SubRig {
  /** The part's spec: its bones in the whole rig's order, parents renumbered; effectors as given. */
  spec: RigSpec;
  /** The whole rig's index of each of the part's bones. */
  bones: Int32Array;
}

/**
 * The bones `moved` (whole-rig indices) and their ancestors, in the order of `spec`, as a SubRig;
 * its effectors are `moved`, renumbered. A floating root carries over.
 */
export function subRig(spec: RigSpec, moved: readonly number[]): SubRig {
  const numBones = spec.parents.length;
  const keep = new Uint8Array(numBones);
  for (const bone of moved) for (let b = bone; b >= 0 && !keep[b]; b = spec.parents[b]) keep[b] = 1;
  const bones: number[] = [];
  const index = new Int32Array(numBones).fill(-1);
  for (let b = 0; b < numBones; b++) if (keep[b]) index[b] = bones.push(b) - 1;
  const pick = (values: Float64Array, stride: number): Float64Array => {
    const out = new Float64Array(stride * bones.length);
    bones.forEach((b, i) => out.set(values.subarray(stride * b, stride * b + stride), stride * i));
    return out;
  };
  return {
    bones: Int32Array.from(bones),
    spec: {
      ...spec,
      names: bones.map((b) => spec.names[b]),
      parents: Int32Array.from(bones, (b) => (spec.parents[b] < 0 ? -1 : index[spec.parents[b]])),
      rest: pick(spec.rest, 16),
      lengths: pick(spec.lengths, 1),
      lower: pick(spec.lower, 3),
      upper: pick(spec.upper, 3),
      effectors: Int32Array.from(moved, (b) => index[b]),
    },
  };
}

/** `humanoid` with its roles renumbered into `sub`'s bones (roles on bones left out are dropped). */
export function subHumanoid(sub: SubRig, humanoid: HumanoidMap): HumanoidMap {
  const index = new Map(Array.from(sub.bones, (b, i) => [b, i] as const));
  const bones: Partial<Record<HumanoidRole, number>> = {};
  for (const [role, bone] of Object.entries(humanoid.bones) as Array<[HumanoidRole, number | undefined]>) {
    const i = bone === undefined ? undefined : index.get(bone);
    if (i !== undefined) bones[role] = i;
  }
  return { ...humanoid, bones };
}

/**
 * Writes the part's pose `subAngles` (3 per part bone, degrees, then any floating root's 3
 * translations, rig units) into the whole rig's `angles` (same layout over every bone); the other
 * bones' angles are left as they are.
 */
export function scatterAngles(sub: SubRig, subAngles: Float64Array, angles: Float64Array): void {
  const bones = sub.bones;
  for (let i = 0; i < bones.length; i++) {
    const from = 3 * i,
      to = 3 * bones[i];
    angles[to] = subAngles[from];
    angles[to + 1] = subAngles[from + 1];
    angles[to + 2] = subAngles[from + 2];
  }
  const extra = subAngles.length - 3 * bones.length;
  for (let k = 0; k < extra; k++) angles[angles.length - extra + k] = subAngles[3 * bones.length + k];
}
