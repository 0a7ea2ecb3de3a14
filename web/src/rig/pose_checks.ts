// The checks a pose file's values must pass, shared by the writer and the reader of pose files
// (pose_json.ts) so that nothing is written that would not be read back. Each returns what is
// wrong as a phrase naming the field, or undefined when the value passes.
import { effectorCountProblem, MAX_COORDINATE } from './rig_limits.js';

/** Largest deviation of an orientation quaternion's length from 1. */
export const UNIT_TOLERANCE = 1e-6;

/** A short description of any JSON value for messages: 3.5, "abc", null, an array, an object. */
export function shown(v: unknown): string {
  if (typeof v === 'number' || typeof v === 'boolean' || v === null) return String(v);
  if (typeof v === 'string') return JSON.stringify(v.length > 40 ? `${v.slice(0, 40)}...` : v);
  return Array.isArray(v) ? 'an array' : typeof v;
}

/** Why `v` (field `field`, holding `what`) is not an array of `n` finite numbers. */
export function numbersProblem(v: unknown, n: number, field: string, what: string): string | undefined {
  if (!Array.isArray(v)) return `${field} is ${shown(v)}, not an array of ${n} numbers (${what})`;
  if (v.length !== n) return `${field} has ${v.length} values, expected ${n} (${what})`;
  const k = v.findIndex((x) => typeof x !== 'number' || !Number.isFinite(x));
  return k < 0 ? undefined : `${field}[${k}] is ${shown(v[k])}, not a finite number`;
}

/** Why `v` is not a target: 3 finite numbers within +-MAX_COORDINATE rig units. */
export function targetProblem(v: unknown, field: string): string | undefined {
  const bad = numbersProblem(v, 3, field, 'a position in rig units');
  if (bad) return bad;
  const k = (v as number[]).findIndex((x) => Math.abs(x) > MAX_COORDINATE);
  return k < 0 ? undefined : `${field}[${k}] = ${(v as number[])[k]} lies beyond +-${MAX_COORDINATE} rig units`;
}

/** Why `v` is not an orientation: a unit quaternion (x, y, z, w) to UNIT_TOLERANCE. */
export function orientationProblem(v: unknown, field: string): string | undefined {
  const bad = numbersProblem(v, 4, field, 'a unit quaternion x, y, z, w');
  if (bad) return bad;
  const length = Math.hypot(...(v as number[]));
  return Math.abs(length - 1) > UNIT_TOLERANCE ? `${field} has length ${length}, not a unit quaternion` : undefined;
}

/** Why `count` end effectors are too many for a rig of `bones` bones (the core's caps). */
export function effectorsProblem(count: number, bones: number): string | undefined {
  const problem = effectorCountProblem(count, bones);
  return problem && `"effectors": ${problem}`;
}
