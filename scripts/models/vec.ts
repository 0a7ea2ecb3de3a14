// 3-vectors as tuples, for the model generator: the importer's helpers plus a few of its own.
import { add, norm, scale, sub, type Vec3 } from '#rig/anatomy/anatomy_vec.js';

export { add, cross, dot, scale, sub, type Vec3 } from '#rig/anatomy/anatomy_vec.js';
export const length = norm;
export const normalize = (a: Vec3): Vec3 => scale(a, 1 / length(a));
/** a + t (b - a) */
export const lerp = (a: Vec3, b: Vec3, t: number): Vec3 => add(a, scale(sub(b, a), t));
/** Mirror through the x = 0 plane (left <-> right). */
export const mirrorX = (a: Vec3): Vec3 => [-a[0], a[1], a[2]];
