// Joint-limit shorthands (XZX, degrees) and the hinge-axis helper for the model definitions.
import type { Limits } from './model.js';
import { type Vec3, cross, normalize, sub } from './vec.js';

/** No motion: a fixed frame. */
export const fixed: Limits = [
  [0, 0, 0],
  [0, 0, 0],
];

/** A hinge: only the middle angle (about the joint's local Z) moves, in [lo, hi]. */
export function hinge(lo: number, hi: number): Limits {
  return [
    [0, lo, 0],
    [0, hi, 0],
  ];
}

/** A ball joint: twist a0 in [-twist0, twist0], bend a1 in [lo, hi], twist a2 in [-twist2, twist2]. */
export function ball(twist0: number, lo: number, hi: number, twist2: number): Limits {
  return [
    [-twist0, lo, -twist2],
    [twist0, hi, twist2],
  ];
}

/**
 * The hinge hint for a bone from head to tail so that a positive middle angle moves its tip
 * towards `towards` (e.g. flexion): the local Z axis is (bone direction) x towards.
 */
export function flex(head: Vec3, tail: Vec3, towards: Vec3): Vec3 {
  return cross(normalize(sub(tail, head)), towards);
}
