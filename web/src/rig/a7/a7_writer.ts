// Writes a RigSpec as A7-style JSON (the format of PROTOCOL.md), which the native engine parses
// with wasm/native/a7_rig.cpp. Numbers are written with JavaScript's shortest round-trip form, so
// the native side reads bit-identical values. Extra fields (bone names) are allowed by the format.
//
// Unbounded limits: JSON has no infinity. When all three limits of a side are unbounded the key
// is left out (the format's "missing means unbounded"); a mix of bounded and unbounded angles
// writes +-UNBOUNDED_DEG, which no clamp can tell from infinity for angles a solver reaches.
import type { RigSpec } from '../../ik/rig_arrays.js';

export const UNBOUNDED_DEG = 1e300;

interface A7Bone {
  name: string;
  parent_id: number;
  length: number;
  rest_T: number[][];
  xzx_min?: number[];
  xzx_max?: number[];
}

function limits(values: Float64Array, i: number, sign: 1 | -1): number[] | undefined {
  const v = Array.from(values.subarray(3 * i, 3 * i + 3));
  if (v.every((x) => x === sign * Infinity)) return undefined;
  return v.map((x) => (Number.isFinite(x) ? x : Math.sign(x) * UNBOUNDED_DEG));
}

/** The A7 JSON text of `spec`. */
export function writeA7Rig(spec: RigSpec): string {
  const bones: A7Bone[] = Array.from(spec.parents, (parent, i) => {
    const rest = spec.rest.subarray(16 * i, 16 * i + 16);
    const bone: A7Bone = {
      name: spec.names[i] ?? `bone ${i}`,
      parent_id: parent,
      length: spec.lengths[i],
      rest_T: [0, 1, 2, 3].map((r) => Array.from(rest.subarray(4 * r, 4 * r + 4))),
    };
    const lo = limits(spec.lower, i, -1);
    const hi = limits(spec.upper, i, 1);
    if (lo) bone.xzx_min = lo;
    if (hi) bone.xzx_max = hi;
    return bone;
  });
  return JSON.stringify({ bones, ik_constraints: Array.from(spec.effectors) });
}
