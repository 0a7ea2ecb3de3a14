// Test helper: small rigs written by hand. Every bone points along +x at rest (rest rotation the
// identity) from its base `at` (world coordinates), so its tip at rest is at + (length, 0, 0).
import type { RigSpec } from '#ik/rig_arrays.js';

export interface BoneSketch {
  parent: number;
  /** Base (joint) of the bone at rest, rig units. */
  at: [number, number, number];
  length: number;
  /** XZX limits, degrees (default +-180 on every angle). */
  lower?: [number, number, number];
  upper?: [number, number, number];
}

/** A RigSpec from bone sketches; `effectors`: bone indices whose tips are end effectors. */
export function sketchRig(bones: readonly BoneSketch[], effectors: readonly number[]): RigSpec {
  return {
    names: bones.map((_, i) => `bone ${i}`),
    parents: Int32Array.from(bones, (b) => b.parent),
    rest: Float64Array.from(bones.flatMap((b) => [1, 0, 0, b.at[0], 0, 1, 0, b.at[1], 0, 0, 1, b.at[2], 0, 0, 0, 1])),
    lengths: Float64Array.from(bones, (b) => b.length),
    lower: Float64Array.from(bones.flatMap((b) => b.lower ?? [-180, -180, -180])),
    upper: Float64Array.from(bones.flatMap((b) => b.upper ?? [180, 180, 180])),
    effectors: Int32Array.from(effectors),
  };
}

/** Two bones of length 1 along +x from the origin, straight at rest: its tip at (2, 0, 0) is the effector. */
export function straightLimb(): RigSpec {
  return sketchRig(
    [
      { parent: -1, at: [0, 0, 0], length: 1 },
      { parent: 0, at: [1, 0, 0], length: 1 },
    ],
    [1],
  );
}
