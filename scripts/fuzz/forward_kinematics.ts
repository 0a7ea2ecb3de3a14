// The reference forward kinematics of PROTOCOL.md in plain JavaScript, iterative (a chain of
// 100,000 bones must not overflow the stack) and without allocation per bone:
//   F_i = T_parent * rest_i * Rx(a0) Rz(a1) Rx(a2),  T_i = F_i * rest_i^-1,  tip_i = F_i * (length, 0, 0),
// which is PROTOCOL's tip_i = T_i * rest_i * (length, 0, 0). rest_i^-1 is the inverse of a rigid
// transform (transposed rotation), as the core takes it: rest matrices need only be rigid within
// the core's tolerance, and this is the reading the core promises for them.
import type { RigSpec } from '#ik/rig_arrays.js';

const RAD_PER_DEG = Math.PI / 180;

export interface Pose {
  /** T_i, 16 per bone, row-major. */
  poses: Float64Array;
  /** Every bone's tip, 3 per bone. */
  tips: Float64Array;
}

/** Poses and tips of every bone of `spec` at `angles` (3 per bone, degrees). */
export function forwardKinematics(spec: RigSpec, angles: ArrayLike<number>): Pose {
  const n = spec.parents.length;
  const poses = new Float64Array(16 * n),
    tips = new Float64Array(3 * n);
  const done = new Uint8Array(n);
  const stack: number[] = [];
  for (let start = 0; start < n; start++) {
    for (let at = start; at !== -1 && !done[at]; at = spec.parents[at]) stack.push(at);
    while (stack.length > 0) {
      const i = stack.pop()!;
      pose(spec, i, angles, poses, tips);
      done[i] = 1;
    }
  }
  return { poses, tips };
}

/** Tips of the end effectors `effectors` (3 each) out of every bone's tips. */
export function effectorTips(all: Float64Array, effectors: ArrayLike<number>): Float64Array {
  const out = new Float64Array(3 * effectors.length);
  for (let k = 0; k < effectors.length; k++) out.set(all.subarray(3 * effectors[k], 3 * effectors[k] + 3), 3 * k);
  return out;
}

const IDENTITY = Float64Array.of(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
const joint = new Float64Array(16),
  inverse = new Float64Array(16);

/** out[o..o+16] = a[ao..] * b[bo..] (4x4, row-major). */
function multiply(a: Float64Array, ao: number, b: Float64Array, bo: number, out: Float64Array, o: number): void {
  for (let r = 0; r < 4; r++)
    for (let c = 0; c < 4; c++)
      out[o + 4 * r + c] =
        a[ao + 4 * r] * b[bo + c] +
        a[ao + 4 * r + 1] * b[bo + 4 + c] +
        a[ao + 4 * r + 2] * b[bo + 8 + c] +
        a[ao + 4 * r + 3] * b[bo + 12 + c];
}

/** m <- m * R, R the rotation by `t` radians in the plane of columns (i, j): Rx is (1, 2), Rz is (0, 1). */
function rotateColumns(m: Float64Array, i: number, j: number, t: number): void {
  const c = Math.cos(t),
    s = Math.sin(t);
  for (let r = 0; r < 3; r++) {
    const a = m[4 * r + i],
      b = m[4 * r + j];
    m[4 * r + i] = c * a + s * b;
    m[4 * r + j] = c * b - s * a;
  }
}

/** T_i into out[16 i..] and tip_i into tips[3 i..], from the parent's T already in `out`. */
function pose(spec: RigSpec, i: number, angles: ArrayLike<number>, out: Float64Array, tips: Float64Array): void {
  const rest = spec.rest,
    o = 16 * i,
    p = spec.parents[i];
  if (p === -1) multiply(IDENTITY, 0, rest, o, joint, 0);
  else multiply(out, 16 * p, rest, o, joint, 0);
  rotateColumns(joint, 1, 2, angles[3 * i] * RAD_PER_DEG);
  rotateColumns(joint, 0, 1, angles[3 * i + 1] * RAD_PER_DEG);
  rotateColumns(joint, 1, 2, angles[3 * i + 2] * RAD_PER_DEG);
  const l = spec.lengths[i];
  for (let k = 0; k < 3; k++) tips[3 * i + k] = joint[4 * k] * l + joint[4 * k + 3];
  // rest_i^-1 of a rigid transform: R^T and -R^T t.
  for (let r = 0; r < 3; r++) {
    for (let c = 0; c < 3; c++) inverse[4 * r + c] = rest[o + 4 * c + r];
    inverse[4 * r + 3] = -(rest[o + r] * rest[o + 3] + rest[o + 4 + r] * rest[o + 7] + rest[o + 8 + r] * rest[o + 11]);
  }
  inverse.set([0, 0, 0, 1], 12);
  multiply(joint, 0, inverse, 0, out, o);
}
