// Unit quaternions [x, y, z, w] as plain arrays, for code without three.js (the avatar's feet, the
// model generator's clips, the glTF rest and posed-file writer): the product, the inverse, the turn
// of a vector, and a rotation matrix's quaternion.
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
