// Test helpers: the rigs the tests run on, seeded random numbers and random angles (the
// benchmark's own: bench-node/prng.ts, bench-node/targets.ts), and the reference composition of
// PROTOCOL.md in plain 4x4 matrices.
//
// Two sets of rigs in A7 format: the project's own (build/test-rigs, written from the models by
// scripts/write-test-rigs.ts in vitest's global setup), always there, and the report's five A7 rigs from a7Dir
// (a7_folder.ts), when that folder exists. Tests of a general property run on testRigs; tests
// whose expectations belong to the report's rigs take the options needsA7, which skip them
// without the folder (and fail them under CI).
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';

import { projectRigNames } from '../../bench-node/rigs.js';
import { testRigsDir } from '../../scripts/write-test-rigs.js';
import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import { parseA7Rig } from '../../web/src/rig/a7/a7_rig.js';
import { reportTolerances } from '../../web/src/rig/tolerances.js';
import { A7_TAG, a7Dir, a7Present } from '../../scripts/a7_folder.js';

export { a7Dir };
/** seeded(seed): numbers in [0, 1) from mulberry32; randomAngles(spec, rand): the random experiment's angles. */
export { mulberry32 as seeded } from '../../bench-node/prng.js';
export { randomAngles } from '../../bench-node/targets.js';

/** The report's five rigs, by file base name. */
export const a7Names: readonly string[] = Object.keys(reportTolerances);

/** Test options of a suite or test that reads the A7 rigs: describe(name, needsA7, fn). */
export const needsA7 = { tags: [A7_TAG] };

export function a7Path(name: string): string {
  return resolve(a7Dir, `${name}.json`);
}

export function loadA7(name: string): RigSpec {
  const path = a7Path(name);
  return parseA7Rig(readFileSync(path, 'utf8'), path);
}

/** The report's paper folder (original-measured.csv, results.csv), beside the A7 rigs. */
export const paperDir = resolve(a7Dir, '../../paper');

export interface TestRig {
  /** The file's base name: "knight". */
  name: string;
  /** One of the report's rigs, else the project's own. */
  a7: boolean;
  /** "A7 knight" or "project knight". */
  label: string;
  path: string;
}

/** The project's rigs, then the report's when a7Dir exists. */
export const testRigs: readonly TestRig[] = [
  ...projectRigNames.map((name) => ({
    name,
    a7: false,
    label: `project ${name}`,
    path: resolve(testRigsDir, `${name}.json`),
  })),
  ...(a7Present ? a7Names.map((name) => ({ name, a7: true, label: `A7 ${name}`, path: a7Path(name) })) : []),
];

const projectCounterparts: Record<string, string> = { 'ikea-lamp': 'lamp', 'chimpanzee-hand': 'hand' };

/**
 * The project's counterpart of the report's rig `a7Name` ("ikea-lamp" -> lamp), and that rig too
 * when a7Dir exists: for tests of a general property written for one rig.
 */
export function rigsLike(a7Name: string): TestRig[] {
  if (!a7Names.includes(a7Name))
    throw new Error(`rigsLike: "${a7Name}" is none of the report's rigs (${a7Names.join(', ')})`);
  const project = projectCounterparts[a7Name] ?? a7Name;
  return testRigs.filter((r) => r.name === (r.a7 ? a7Name : project));
}

export function loadTestRig(rig: TestRig): RigSpec {
  return parseA7Rig(readFileSync(rig.path, 'utf8'), rig.path);
}

type M4 = number[]; // row-major 4x4

function mul(a: M4, b: M4): M4 {
  const out = new Array<number>(16).fill(0);
  for (let r = 0; r < 4; r++)
    for (let c = 0; c < 4; c++) for (let k = 0; k < 4; k++) out[4 * r + c] += a[4 * r + k] * b[4 * k + c];
  return out;
}

function rotX(deg: number): M4 {
  const t = (deg * Math.PI) / 180,
    c = Math.cos(t),
    s = Math.sin(t);
  return [1, 0, 0, 0, 0, c, -s, 0, 0, s, c, 0, 0, 0, 0, 1];
}

function rotZ(deg: number): M4 {
  const t = (deg * Math.PI) / 180,
    c = Math.cos(t),
    s = Math.sin(t);
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
