// Unit quaternions [x, y, z, w] as plain arrays, for code without three.js (the avatar's feet, the
// model generator's clips): the product, the inverse and the turn of a vector.
import type { Vec3 } from './anatomy_vec.js';

/** A unit quaternion [x, y, z, w]. */
export type Quat = [number, number, number, number];

/** The product a b (b applied first). */
export function mul(a: ArrayLike<number>, b: ArrayLike<number>): Quat {
  const x1 = a[0], y1 = a[1], z1 = a[2], w1 = a[3], x2 = b[0], y2 = b[1], z2 = b[2], w2 = b[3];
  return [w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2, w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2, w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2, w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2];
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
