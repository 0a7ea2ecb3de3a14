// Small 3-vector helpers for the anatomical limits (plain tuples, allocation is fine: they run
// once per import), and the rest-frame columns of a RigSpec bone.
import type { RigSpec } from '../../ik/rig_arrays.js';

export type Vec3 = [number, number, number];

export const add = (a: Vec3, b: Vec3): Vec3 => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
export const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
export const scale = (a: Vec3, s: number): Vec3 => [a[0] * s, a[1] * s, a[2] * s];
export const dot = (a: Vec3, b: Vec3): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
export const cross = (a: Vec3, b: Vec3): Vec3 => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
export const norm = (a: Vec3): number => Math.hypot(a[0], a[1], a[2]);

/** a scaled to length 1, or null when it is (nearly) zero. */
export function unit(a: Vec3): Vec3 | null {
  const n = norm(a);
  return n > 1e-12 ? scale(a, 1 / n) : null;
}

/** The part of a perpendicular to the unit vector u. */
export function reject(a: Vec3, u: Vec3): Vec3 {
  return sub(a, scale(u, dot(a, u)));
}

/** Column c (0: x, the bone direction; 1: y; 2: z) of bone i's rest rotation, in rig space. */
export function restAxis(spec: RigSpec, i: number, c: 0 | 1 | 2): Vec3 {
  const m = spec.rest,
    o = 16 * i + c;
  return [m[o], m[o + 4], m[o + 8]];
}

/** Bone i's joint position at rest, in rig space. */
export function restOrigin(spec: RigSpec, i: number): Vec3 {
  const m = spec.rest,
    o = 16 * i;
  return [m[o + 3], m[o + 7], m[o + 11]];
}
