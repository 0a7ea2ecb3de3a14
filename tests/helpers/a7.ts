// Test helpers: the report's rigs read from the read-only ../shared folder, seeded random
// numbers, and the reference composition of PROTOCOL.md in plain 4x4 matrices.
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';

import type { RigSpec } from '../../web/src/ik/rig_spec.js';
import { parseA7Rig } from '../../web/src/rig/a7_rig.js';

export const a7Dir = process.env.IK_A7_DIR ?? resolve(import.meta.dirname, '../../../shared/rigs/a7');
export const a7Names = ['ikea-lamp', 'robot-arm', 'knight', 'chimpanzee-hand', 'beast'] as const;

export function a7Path(name: string): string {
  return resolve(a7Dir, `${name}.json`);
}

export function loadA7(name: string): RigSpec {
  const path = a7Path(name);
  return parseA7Rig(readFileSync(path, 'utf8'), path);
}

/** A small seeded generator (mulberry32) returning numbers in [0, 1). */
export function seeded(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let t = s;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** Angles uniform in [-360, 360] degrees, clamped into the spec's limits. */
export function randomAngles(spec: RigSpec, rand: () => number): Float64Array {
  const a = new Float64Array(spec.lower.length);
  for (let i = 0; i < a.length; i++) a[i] = Math.min(spec.upper[i], Math.max(spec.lower[i], 360 * (2 * rand() - 1)));
  return a;
}

type M4 = number[]; // row-major 4x4

function mul(a: M4, b: M4): M4 {
  const out = new Array<number>(16).fill(0);
  for (let r = 0; r < 4; r++) for (let c = 0; c < 4; c++) for (let k = 0; k < 4; k++) out[4 * r + c] += a[4 * r + k] * b[4 * k + c];
  return out;
}

function rotX(deg: number): M4 {
  const t = (deg * Math.PI) / 180, c = Math.cos(t), s = Math.sin(t);
  return [1, 0, 0, 0, 0, c, -s, 0, 0, s, c, 0, 0, 0, 0, 1];
}

function rotZ(deg: number): M4 {
  const t = (deg * Math.PI) / 180, c = Math.cos(t), s = Math.sin(t);
  return [c, -s, 0, 0, s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
}

function rigidInverse(m: M4): M4 {
  const out = [m[0], m[4], m[8], 0, m[1], m[5], m[9], 0, m[2], m[6], m[10], 0, 0, 0, 0, 1];
  for (let r = 0; r < 3; r++) out[4 * r + 3] = -(out[4 * r] * m[3] + out[4 * r + 1] * m[7] + out[4 * r + 2] * m[11]);
  return out;
}

/** Tips by T_i = T_parent * rest_i * Rx Rz Rx * rest_i^-1, tip = T_i * rest_i * (length,0,0). */
export function referenceTips(spec: RigSpec, anglesDeg: ArrayLike<number>): Float64Array {
  const n = spec.parents.length;
  const T: (M4 | undefined)[] = new Array(n);
  const pose = (i: number): M4 => {
    const cached = T[i];
    if (cached) return cached;
    const rest = Array.from(spec.rest.subarray(16 * i, 16 * i + 16));
    const rot = mul(mul(rotX(anglesDeg[3 * i]), rotZ(anglesDeg[3 * i + 1])), rotX(anglesDeg[3 * i + 2]));
    const parent = spec.parents[i] === -1 ? rotX(0) : pose(spec.parents[i]);
    return (T[i] = mul(mul(mul(parent, rest), rot), rigidInverse(rest)));
  };
  const tips = new Float64Array(3 * spec.effectors.length);
  spec.effectors.forEach((b, k) => {
    const m = mul(pose(b), Array.from(spec.rest.subarray(16 * b, 16 * b + 16)));
    const l = spec.lengths[b];
    for (let r = 0; r < 3; r++) tips[3 * k + r] = m[4 * r] * l + m[4 * r + 3];
  });
  return tips;
}

export function maxAbs(a: ArrayLike<number>): number {
  let m = 0;
  for (let i = 0; i < a.length; i++) m = Math.max(m, Math.abs(a[i]));
  return m;
}

export function maxAbsDiff(a: ArrayLike<number>, b: ArrayLike<number>): number {
  if (a.length !== b.length) throw new Error(`length ${a.length} != ${b.length}`);
  let m = 0;
  for (let i = 0; i < a.length; i++) m = Math.max(m, Math.abs(a[i] - b[i]));
  return m;
}
