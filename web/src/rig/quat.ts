// Unit quaternions [x, y, z, w] as plain arrays, for code without three.js (the avatar's feet and
// posture, the model generator's clips, the glTF rest and posed-file writer): the product, the
// inverse, the turn of a vector, a rotation matrix's quaternion, and a turn about the vertical.
import type { Vec3 } from './anatomy/anatomy_vec.js';

/** A unit quaternion [x, y, z, w]. */
export type Quat = [number, number, number, number];

/** The product a b (b applied first). */
export function mul(a: ArrayLike<number>, b: ArrayLike<number>): Quat {
  const x1 = a[0],
    y1 = a[1],
    z1 = a[2],
    w1 = a[3],
    x2 = b[0],
    y2 = b[1],
    z2 = b[2],
    w2 = b[3];
  return [
    w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
    w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2,
    w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
    w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2,
  ];
}

/** The inverse of a unit quaternion (its conjugate). */
export function inverse(q: ArrayLike<number>): Quat {
  return [-q[0], -q[1], -q[2], q[3]];
}

/** `v` turned by `q`. */
export function rotate(q: ArrayLike<number>, v: ArrayLike<number>): Vec3 {
  const p = mul(mul(q, [v[0], v[1], v[2], 0]), inverse(q));
  return [p[0], p[1], p[2]];
}

/**
 * `v` turned by the unit quaternion `q`, written into `out` and returned (v + 2w (u x v) +
 * 2 u x (u x v), u = q's vector part): rotate() without allocating, for per-frame code.
 */
export function rotateInto(q: ArrayLike<number>, v: ArrayLike<number>, out: Float64Array): Float64Array {
  const x = q[0],
    y = q[1],
    z = q[2],
    w = q[3];
  const cx = y * v[2] - z * v[1],
    cy = z * v[0] - x * v[2],
    cz = x * v[1] - y * v[0];
  out[0] = v[0] + 2 * (w * cx + y * cz - z * cy);
  out[1] = v[1] + 2 * (w * cy + z * cx - x * cz);
  out[2] = v[2] + 2 * (w * cz + x * cy - y * cx);
  return out;
}

/** The unit quaternion of a proper rotation given as 9 row-major numbers (Shepperd's method: the largest of w, x, y, z first). */
export function fromRotation(r: ArrayLike<number>): Quat {
  const [m00, m01, m02, m10, m11, m12, m20, m21, m22] = Array.from(r);
  const trace = m00 + m11 + m22;
  let x, y, z, w;
  if (trace > 0) {
    const s = 0.5 / Math.sqrt(trace + 1);
    [w, x, y, z] = [0.25 / s, (m21 - m12) * s, (m02 - m20) * s, (m10 - m01) * s];
  } else if (m00 > m11 && m00 > m22) {
    const s = 2 * Math.sqrt(1 + m00 - m11 - m22);
    [w, x, y, z] = [(m21 - m12) / s, 0.25 * s, (m01 + m10) / s, (m02 + m20) / s];
  } else if (m11 > m22) {
    const s = 2 * Math.sqrt(1 + m11 - m00 - m22);
    [w, x, y, z] = [(m02 - m20) / s, (m01 + m10) / s, 0.25 * s, (m12 + m21) / s];
  } else {
    const s = 2 * Math.sqrt(1 + m22 - m00 - m11);
    [w, x, y, z] = [(m10 - m01) / s, (m02 + m20) / s, (m12 + m21) / s, 0.25 * s];
  }
  const n = Math.hypot(x, y, z, w);
  return [x / n, y / n, z / n, w / n];
}

/**
 * The turn about the vertical (y; radians, counter-clockwise seen from above) of the rotation that
 * takes frame `rest` to frame `q`: where it turns the forward axis (z), projected on the floor.
 * The quaternions are read at offsets `at` of `q` and `restAt` of `rest` (4 numbers each), so that
 * packed arrays need no copy. Scalar arithmetic: called every frame.
 */
export function yawFrom(q: ArrayLike<number>, rest: ArrayLike<number>, at = 0, restAt = 0): number {
  // r = q rest^-1 (rest a unit quaternion: its inverse is its conjugate).
  const x1 = q[at],
    y1 = q[at + 1],
    z1 = q[at + 2],
    w1 = q[at + 3],
    x2 = -rest[restAt],
    y2 = -rest[restAt + 1],
    z2 = -rest[restAt + 2],
    w2 = rest[restAt + 3];
  const x = w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2,
    y = w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2;
  const z = w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2,
    w = w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2;
  // r's turn of (0, 0, 1): its x and z.
  return Math.atan2(2 * (x * z + w * y), 1 - 2 * (x * x + y * y));
}
