// A bone's rest transform (canonical bone -> rest bone, rigid, row-major) from its joint's world
// matrix and the world direction the bone points in (docs/gltf-ik-extras.md, "Bone frame"):
// origin = the joint's world position; x = the bone direction; the rotation is the joint's own
// rotation (scale removed) followed by the shortest arc taking its local +x to the bone direction.
import { polarRotation, type Mat4 } from './mat4.js';

type Vec3 = [number, number, number];

/** Shortest-arc rotation (row-major 3x3) taking +x to the unit vector d. For d = -x: 180 deg about z. */
export function shortestArcFromX(d: Vec3): Float64Array {
  const c = d[0];
  if (1 + c < 1e-12) return Float64Array.of(-1, 0, 0, 0, -1, 0, 0, 0, 1);
  // Rodrigues with k = x cross d = (0, -dz, dy): R = I + [k]x + [k]x^2 / (1 + c)
  const kx = 0,
    ky = -d[2],
    kz = d[1];
  const f = 1 / (1 + c);
  const K = [0, -kz, ky, kz, 0, -kx, -ky, kx, 0];
  const K2 = new Array<number>(9);
  for (let r = 0; r < 3; r++)
    for (let col = 0; col < 3; col++) {
      let s = 0;
      for (let k = 0; k < 3; k++) s += K[3 * r + k] * K[3 * k + col];
      K2[3 * r + col] = s;
    }
  const out = new Float64Array(9);
  for (let k = 0; k < 9; k++) out[k] = (k % 4 === 0 ? 1 : 0) + K[k] + K2[k] * f;
  return out;
}

/**
 * The rigid rest transform of a bone whose joint has world matrix `world` (row-major, may hold
 * scale or a mirror) and which points along the world direction `dir` (any length > 0). Returns 16 numbers.
 * Mirrored joints (negative determinant) get their canonical z flipped so the frame stays proper.
 */
export function boneRestFrame(world: Mat4, dir: Vec3): Float64Array {
  const R = polarRotation(world);
  // The direction in the joint's rigid local frame: R^T dir.
  const local = [0, 1, 2].map((c) => R[c] * dir[0] + R[3 + c] * dir[1] + R[6 + c] * dir[2]) as Vec3;
  const n = Math.hypot(...local);
  const Q = shortestArcFromX([local[0] / n, local[1] / n, local[2] / n]);
  const M = new Float64Array(9);
  for (let r = 0; r < 3; r++)
    for (let c = 0; c < 3; c++) M[3 * r + c] = R[3 * r] * Q[c] + R[3 * r + 1] * Q[3 + c] + R[3 * r + 2] * Q[6 + c];
  const mirrored =
    R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) + R[2] * (R[3] * R[7] - R[4] * R[6]) < 0;
  // Columns: x exactly the bone direction, z orthogonalised, y = z cross x (proper, orthonormal).
  const dn = Math.hypot(...dir);
  const x: Vec3 = [dir[0] / dn, dir[1] / dn, dir[2] / dn];
  let z: Vec3 = [M[2], M[5], M[8]];
  if (mirrored) z = [-z[0], -z[1], -z[2]];
  const dot = z[0] * x[0] + z[1] * x[1] + z[2] * x[2];
  z = [z[0] - dot * x[0], z[1] - dot * x[1], z[2] - dot * x[2]];
  const zn = Math.hypot(...z);
  z = [z[0] / zn, z[1] / zn, z[2] / zn];
  const y: Vec3 = [z[1] * x[2] - z[2] * x[1], z[2] * x[0] - z[0] * x[2], z[0] * x[1] - z[1] * x[0]];
  return Float64Array.of(
    x[0],
    y[0],
    z[0],
    world[3],
    x[1],
    y[1],
    z[1],
    world[7],
    x[2],
    y[2],
    z[2],
    world[11],
    0,
    0,
    0,
    1,
  );
}
