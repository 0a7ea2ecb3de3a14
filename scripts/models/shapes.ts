// Low-poly shapes for the project rigs: frusta (cylinders, cones), blocks and balls, built in
// armature space and skinned to one joint (or blended between two along a frustum).
import type { Shape } from './model.js';
import { type Vec3, add, cross, normalize, scale, sub } from './vec.js';

/** One joint, or [joint, weight] pairs summing to 1. */
export type Skin = string | [string, number][];

const pairs = (s: Skin): [string, number][] => (typeof s === 'string' ? [[s, 1]] : s);

/** Two unit vectors perpendicular to u and to each other, the first close to `side` when given. */
function basis(u: Vec3, side?: Vec3): [Vec3, Vec3] {
  const hint: Vec3 = side ?? (Math.abs(u[1]) < 0.9 ? [0, 1, 0] : [1, 0, 0]);
  const a = normalize(cross(cross(u, hint), u));
  return [a, cross(u, a)];
}

/**
 * A capped frustum from a (radius ra) to b (radius rb) with `sides` sides. The ring at a follows
 * `skinA`, the ring at b `skinB` (default: skinA), so a limb can blend into its parent at the joint.
 */
export function frustum(
  material: string,
  a: Vec3,
  b: Vec3,
  ra: number,
  rb: number,
  sides: number,
  skinA: Skin,
  skinB: Skin = skinA,
  side?: Vec3,
): Shape {
  const u = normalize(sub(b, a));
  const [e1, e2] = basis(u, side);
  const positions: Vec3[] = [];
  const weights: [string, number][][] = [];
  for (const [c, r, s] of [
    [a, ra, skinA],
    [b, rb, skinB],
  ] as const)
    for (let k = 0; k < sides; k++) {
      const t = (2 * Math.PI * (k + 0.5)) / sides;
      positions.push(add(c, add(scale(e1, r * Math.cos(t)), scale(e2, r * Math.sin(t)))));
      weights.push(pairs(s));
    }
  const triangles: [number, number, number][] = [];
  for (let k = 0; k < sides; k++) {
    const k1 = (k + 1) % sides;
    triangles.push([k, k1, sides + k1], [k, sides + k1, sides + k]);
  }
  for (let k = 1; k + 1 < sides; k++) triangles.push([0, k + 1, k], [sides, sides + k, sides + k + 1]);
  return { material, positions, weights, triangles };
}

/**
 * A block from a to b (length along a->b) with the given width (along `side`, orthogonalised)
 * and depth (along the third axis), skinned to one joint.
 */
export function block(
  material: string,
  a: Vec3,
  b: Vec3,
  width: number,
  depth: number,
  skin: Skin,
  side?: Vec3,
): Shape {
  const u = normalize(sub(b, a));
  const [e1, e2] = basis(u, side);
  const positions: Vec3[] = [];
  for (const c of [a, b])
    for (const [s1, s2] of [
      [-1, -1],
      [1, -1],
      [1, 1],
      [-1, 1],
    ])
      positions.push(add(c, add(scale(e1, (s1 * width) / 2), scale(e2, (s2 * depth) / 2))));
  const quads = [
    [0, 3, 2, 1],
    [4, 5, 6, 7],
    [0, 1, 5, 4],
    [1, 2, 6, 5],
    [2, 3, 7, 6],
    [3, 0, 4, 7],
  ];
  const triangles = quads.flatMap(
    ([p, q, r, s]) =>
      [
        [p, q, r],
        [p, r, s],
      ] as [number, number, number][],
  );
  return { material, positions, weights: positions.map(() => pairs(skin)), triangles };
}

/** A low-poly ball (6 segments, 4 bands) of radius r, skinned to one joint. */
export function ball(material: string, center: Vec3, r: number, skin: Skin, stretch: Vec3 = [1, 1, 1]): Shape {
  const seg = 6,
    bands = 4;
  const positions: Vec3[] = [add(center, [0, r * stretch[1], 0])];
  for (let i = 1; i < bands; i++) {
    const phi = (Math.PI * i) / bands;
    for (let k = 0; k < seg; k++) {
      const t = (2 * Math.PI * k) / seg;
      positions.push(
        add(center, [
          r * stretch[0] * Math.sin(phi) * Math.cos(t),
          r * stretch[1] * Math.cos(phi),
          r * stretch[2] * Math.sin(phi) * Math.sin(t),
        ]),
      );
    }
  }
  positions.push(add(center, [0, -r * stretch[1], 0]));
  const last = positions.length - 1;
  const ring = (i: number, k: number): number => 1 + (i - 1) * seg + (k % seg);
  const triangles: [number, number, number][] = [];
  for (let k = 0; k < seg; k++) {
    triangles.push([0, ring(1, k + 1), ring(1, k)]);
    for (let i = 1; i + 1 < bands; i++)
      triangles.push(
        [ring(i, k), ring(i, k + 1), ring(i + 1, k + 1)],
        [ring(i, k), ring(i + 1, k + 1), ring(i + 1, k)],
      );
    triangles.push([last, ring(bands - 1, k), ring(bands - 1, k + 1)]);
  }
  return { material, positions, weights: positions.map(() => pairs(skin)), triangles };
}
