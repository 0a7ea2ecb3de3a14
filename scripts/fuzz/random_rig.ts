// Valid rigs of every shape the core accepts: chains and trees, random rigid rest frames,
// bounded, one-sided, unbounded and fixed limits, several end effectors.
import type { RigSpec } from '#ik/rig_arrays.js';
import type { Rand } from './random.js';

/** A random rigid 4x4 (row-major): a uniform random rotation and a translation within `reach`. */
function randomRigid(r: Rand, reach: number): number[] {
  let [x, y, z, w] = [r.range(-1, 1), r.range(-1, 1), r.range(-1, 1), r.range(-1, 1)];
  const q = Math.hypot(x, y, z, w) || 1;
  [x, y, z, w] = [x / q, y / q, z / q, w / q];
  return [
    1 - 2 * (y * y + z * z),
    2 * (x * y - z * w),
    2 * (x * z + y * w),
    r.range(-reach, reach),
    2 * (x * y + z * w),
    1 - 2 * (x * x + z * z),
    2 * (y * z - x * w),
    r.range(-reach, reach),
    2 * (x * z - y * w),
    2 * (y * z + x * w),
    1 - 2 * (x * x + y * y),
    r.range(-reach, reach),
    0,
    0,
    0,
    1,
  ];
}

/** Degrees in [lo, hi) to a hundredth (short in a file). */
function degrees(r: Rand, lo: number, hi: number): number {
  return Math.round(r.range(lo, hi) * 100) / 100;
}

function limits(r: Rand): [number, number] {
  return r.weighted<() => [number, number]>([
    [4, () => [-degrees(r, 0, 180), degrees(r, 0, 180)]],
    [1, () => [-Infinity, Infinity]],
    [1, () => [-Infinity, degrees(r, -90, 90)]],
    [1, () => [0, 0]],
    [1, () => [-degrees(r, 0, 720), degrees(r, 0, 720)]],
  ])();
}

/**
 * A random valid rig of `bones` bones (parents before children) with up to `maxEffectors` leaf
 * effectors. `rotated` false: rest frames are translations by whole centimetres only (a much
 * shorter A7 file for the huge rigs).
 */
export function randomRig(r: Rand, bones: number, maxEffectors = 4, rotated = true): RigSpec {
  const chain = r.chance(0.4);
  const parents = Int32Array.from({ length: bones }, (_, i) => (i === 0 ? -1 : chain ? i - 1 : r.int(i)));
  const lower = new Float64Array(3 * bones),
    upper = new Float64Array(3 * bones);
  for (let k = 0; k < 3 * bones; k++) [lower[k], upper[k]] = limits(r);
  const children = new Uint32Array(bones);
  parents.forEach((p) => p >= 0 && children[p]++);
  const leaves = [...parents.keys()].filter((i) => children[i] === 0);
  const effectors = leaves.filter(() => r.chance(0.7)).slice(0, maxEffectors);
  const rest = new Float64Array(16 * bones);
  for (let i = 0; i < bones; i++)
    rest.set(
      rotated
        ? randomRigid(r, 2)
        : [
            1,
            0,
            0,
            r.intIn(-200, 200) / 100,
            0,
            1,
            0,
            r.intIn(-200, 200) / 100,
            0,
            0,
            1,
            r.intIn(-200, 200) / 100,
            0,
            0,
            0,
            1,
          ],
      16 * i,
    );
  return {
    names: Array.from({ length: bones }, (_, i) => `bone ${i}`),
    parents,
    rest,
    lengths: Float64Array.from({ length: bones }, () => (r.chance(0.1) ? 0 : r.range(0.01, 2))),
    lower,
    upper,
    effectors: Int32Array.from(effectors.length ? effectors : [leaves[leaves.length - 1]]),
  };
}

/** Random angles inside the limits of `spec` (unbounded angles within +-360). */
export function randomAngles(r: Rand, spec: RigSpec): Float64Array {
  return Float64Array.from(spec.lower, (lo, k) => Math.min(spec.upper[k], Math.max(lo, r.range(-360, 360))));
}
