// Checks of what the API returned: each returns undefined for a clean value or one line saying
// what is wrong (a silent wrong result).
import type { RigSpec } from '#ik/rig_arrays.js';
import type { SolverResult } from '#ik/solver.js';
import { effectorTips, forwardKinematics } from './forward_kinematics.js';

/** Relative tolerance of a tip against the reference forward kinematics. */
const FK_RELATIVE_TOLERANCE = 1e-9;

/** Angles beyond this (degrees) are compared for finiteness only: sin/cos of huge numbers may differ by an ulp of the argument. */
const FK_COMPARABLE_DEG = 1e6;

/** The length scale of `spec` tolerances are relative to: the sum of every bone's offset and length (at least 1). */
export function rigScale(spec: RigSpec): number {
  let s = 1;
  for (let i = 0; i < spec.lengths.length; i++)
    s += Math.hypot(spec.rest[16 * i + 3], spec.rest[16 * i + 7], spec.rest[16 * i + 11]) + Math.abs(spec.lengths[i]);
  return s;
}

/** `values` is an array-like of `length` finite numbers (a typed array when `typed`). */
export function numbersProblem(name: string, values: unknown, length: number, typed = true): string | undefined {
  if (typed && !(values instanceof Float64Array))
    return `${name} is ${values === null || typeof values !== 'object' ? String(values) : `a ${values.constructor?.name ?? 'object'}`}, not a Float64Array`;
  const v = values as ArrayLike<number>;
  if (v === null || typeof v !== 'object' || typeof v.length !== 'number') return `${name} is not an array`;
  if (v.length !== length) return `${name} has ${v.length} numbers, expected ${length}`;
  for (let i = 0; i < v.length; i++) if (!Number.isFinite(v[i])) return `${name}[${i}] is ${v[i]}`;
  return undefined;
}

/** Every angle inside [lower, upper]. */
export function limitsProblem(name: string, angles: ArrayLike<number>, spec: RigSpec): string | undefined {
  for (let i = 0; i < angles.length; i++)
    if (!(angles[i] >= spec.lower[i] && angles[i] <= spec.upper[i]))
      return `${name}[${i}] = ${angles[i]} is outside the limits [${spec.lower[i]}, ${spec.upper[i]}]`;
  return undefined;
}

/** Are `angles` plain finite numbers small enough to compare against the reference kinematics? */
export function comparable(angles: ArrayLike<number>): boolean {
  for (let i = 0; i < angles.length; i++) if (!(Math.abs(angles[i]) <= FK_COMPARABLE_DEG)) return false;
  return true;
}

/** `got` equals `expected` within the relative tolerance of a rig of size `scale`. */
export function closeProblem(
  name: string,
  got: ArrayLike<number>,
  expected: ArrayLike<number>,
  scale: number,
): string | undefined {
  const tol = FK_RELATIVE_TOLERANCE * scale;
  for (let i = 0; i < expected.length; i++)
    if (!(Math.abs(got[i] - expected[i]) <= tol))
      return `${name}[${i}] = ${got[i]}, the reference forward kinematics gives ${expected[i]} (tolerance ${tol.toExponential(1)})`;
  return undefined;
}

/** The end-effector tips of `spec` at `angles`, by the reference kinematics. */
export function referenceTips(spec: RigSpec, angles: ArrayLike<number>): Float64Array {
  return effectorTips(forwardKinematics(spec, angles).tips, spec.effectors);
}

const STOP_REASONS = [
  'converged_E',
  'converged_grad',
  'zero_step',
  'max_iterations',
  'timeout',
  'numerical_failure',
  'joint_speed',
];

/** 1/2 |reference tips at `angles` - target|^2 and the largest tip distance. */
function errorAt(spec: RigSpec, angles: ArrayLike<number>, target: Float64Array): { E: number; far: number } {
  const tips = referenceTips(spec, angles);
  let sum = 0,
    far = 0;
  for (let k = 0; k < tips.length / 3; k++) {
    const d = Math.hypot(
      tips[3 * k] - target[3 * k],
      tips[3 * k + 1] - target[3 * k + 1],
      tips[3 * k + 2] - target[3 * k + 2],
    );
    sum += d * d;
    far = Math.max(far, d);
  }
  return { E: sum / 2, far };
}

/** `angles` clamped into the limits of `spec`. */
export function clampToLimits(spec: RigSpec, angles: ArrayLike<number>): Float64Array {
  return Float64Array.from(angles, (a, k) => Math.min(spec.upper[k], Math.max(spec.lower[k], a)));
}

/**
 * A finished solve: finite numbers, angles inside the limits, `reached` agreeing with the stop
 * reason; when the numbers the solve was given are known, E and tipDistance equal those of the
 * reference tips at the returned angles, and initialE that at the start clamped into the limits.
 * `spec` carries the effectors the solve ran with.
 */
export function solveProblem(
  r: SolverResult,
  spec: RigSpec,
  given?: { start: Float64Array; target: Float64Array },
): string | undefined {
  const n = 3 * spec.parents.length;
  const bad =
    numbersProblem('angles', r.angles, n) ??
    limitsProblem('angles', r.angles, spec) ??
    (STOP_REASONS.includes(r.stopReason) ? undefined : `stopReason is "${r.stopReason}"`) ??
    (r.stopReason === 'numerical_failure'
      ? undefined
      : numbersProblem('result numbers', [r.E, r.initialE, r.gradNorm, r.tipDistance, r.elapsedSeconds], 5, false)) ??
    (r.reached === (r.stopReason === 'converged_E')
      ? undefined
      : `reached is ${r.reached} with stopReason ${r.stopReason}`);
  if (bad || r.stopReason === 'numerical_failure' || !given || !comparable(r.angles) || !comparable(given.start))
    return bad;
  const scale = rigScale(spec) + Math.max(...Array.from(given.target, Math.abs));
  const end = errorAt(spec, r.angles, given.target);
  const start = errorAt(spec, clampToLimits(spec, given.start), given.target);
  return (
    closeProblem('sqrt(2 E)', [Math.sqrt(2 * r.E)], [Math.sqrt(2 * end.E)], scale) ??
    closeProblem('tipDistance', [r.tipDistance], [end.far], scale) ??
    closeProblem('sqrt(2 initialE)', [Math.sqrt(2 * r.initialE)], [Math.sqrt(2 * start.E)], scale)
  );
}
