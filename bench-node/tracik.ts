// --experiment tracik: TRAC-IK's published protocol (its README, v1.4.6; its harness is
// trac_ik_examples/src/ik_tests.cpp), the one behind the table in tracik_table.ts:
//   - N queries (default TRACIK_SAMPLES), seeded: each draws a joint configuration uniformly
//     within the limits (an angle whose limits span a full turn or more, a continuous joint,
//     from the full turn centred on its nominal value: +-180 degrees for a +-180 or unlimited one);
//   - the target is the tip's full pose at that configuration (--goals pose: pose_goals.ts);
//   - every query starts from the nominal ("mid-limit") configuration, (lower + upper) / 2 per
//     angle (an unlimited angle: 0 clamped into its limits);
//   - TRAC-IK's 1e-5 tolerances: every tip within TRACIK_TOLERANCE (rig units; metres for a URDF)
//     of its target and every frame within TRACIK_TOLERANCE radians of its target orientation,
//     judged by the harness from forward kinematics of the returned angles;
//   - 5 ms per query (TRACIK_TIMEOUT_S), restarts allowed within it.
// The rotation test: TRAC-IK (and KDL's NR_JL) test each component of the rotation vector between
// the frames (KDL::diff) against 1e-5 rad; each component is at most the vector's length, which
// is the rotation angle between the frames, so an angle <= 1e-5 implies TRAC-IK's test, and
// TRAC-IK's test implies an angle <= sqrt(3) * 1e-5. The bench tests the angle (the core's
// orientation error): at most as lenient as TRAC-IK's. Likewise the tip distance (Euclidean)
// within 1e-5 implies each of x, y, z within 1e-5.
import { extname } from 'node:path';

import type { RigSpec } from '#ik/rig_arrays.js';
import { BenchError, quote } from './errors.js';
import type { GoalsKind } from './pose_goals.js';
import type { RunSettings } from './runner.js';
import { project, type TargetSet } from './target_set.js';

/** The experiment's name. */
export const TRACIK = 'tracik';
/** Queries when --samples is not given (TRAC-IK's 10,000). */
export const TRACIK_SAMPLES = 10_000;
/** Time per query when --time-budget is not given, seconds (TRAC-IK's 5 ms). */
export const TRACIK_TIMEOUT_S = 0.005;
/** Position (rig units: metres for a URDF) and rotation (radians) tolerance: TRAC-IK's 1e-5. */
export const TRACIK_TOLERANCE = 1e-5;
/** The rotation tolerance as the core takes it: degrees of the angle between the frames. */
export const TRACIK_ROTATION_TOLERANCE_DEG = (TRACIK_TOLERANCE * 180) / Math.PI;
/**
 * Gradient tolerance of our solvers (rig units^2 per degree) when --gradient-tolerance is not given: far below
 * the gradient of a pose 1e-5 off its target (about 1e-7 on a 1 m arm), so that the gradient
 * test (a stationary point: restart) never ends a run that is converging onto the target.
 */
export const TRACIK_GRADIENT_TOLERANCE = 1e-14;

/** The nominal configuration (degrees): mid-limit per angle; an angle with an infinite limit 0, clamped into its limits. */
export function nominalAngles(spec: RigSpec): Float64Array {
  const a = new Float64Array(spec.lower.length);
  for (let i = 0; i < a.length; i++) {
    const mid = (spec.lower[i] + spec.upper[i]) / 2;
    a[i] = Number.isFinite(mid) ? mid : 0;
  }
  return project(spec, a);
}

/**
 * A configuration drawn uniformly within the limits (degrees); `rand` gives numbers in [0, 1),
 * one per angle in order. An angle whose limits span 360 degrees or more draws from the full turn
 * centred on `nominal` (its value there), then clamped into its limits.
 */
export function tracikAngles(spec: RigSpec, nominal: ArrayLike<number>, rand: () => number): Float64Array {
  const a = new Float64Array(spec.lower.length);
  for (let i = 0; i < a.length; i++) {
    const u = rand();
    const lo = spec.lower[i],
      hi = spec.upper[i];
    a[i] = hi - lo >= 360 ? nominal[i] - 180 + 360 * u : lo + (hi - lo) * u;
  }
  return project(spec, a);
}

/** Fills the tracik set's target angles and starts (the nominal configuration); `rand`: the experiment's stream. */
export function fillTracik(spec: RigSpec, set: TargetSet, angles: Float64Array, rand: () => number): void {
  const m = set.numAngles;
  const nominal = nominalAngles(spec);
  for (let k = 0; k < set.count; k++) {
    angles.set(tracikAngles(spec, nominal, rand), k * m);
    set.starts.set(nominal, k * m);
  }
}

/** Whether `chain` is BASE:TIP, two non-empty link names. */
export function isChain(chain: string): boolean {
  const parts = chain.split(':');
  return parts.length === 2 && parts.every((p) => p.trim() !== '' && p === p.trim());
}

const usage = (message: string): BenchError => new BenchError(message, 2);

/** What applyTracik reads and sets of the bench's options (BenchOptions, options.ts). */
export interface TracikOptions {
  experiments: readonly string[];
  goals: GoalsKind;
  samples: Record<string, number>;
  timeBudgetSeconds: number;
}

/**
 * The options of a tracik run (`given(name)`: whether the option was on the command line): it
 * runs alone, with pose goals (--goals position is refused), TRAC-IK's tolerances (--error-tolerance
 * is refused; --gradient-tolerance is our solvers' gradient tolerance, default TRACIK_GRADIENT_TOLERANCE),
 * TRACIK_SAMPLES queries and TRACIK_TIMEOUT_S per query unless --samples and --time-budget say otherwise. Throws a usage
 * error (one line); changes nothing for a run without tracik.
 */
export function applyTracik(opts: TracikOptions, given: (option: string) => boolean): void {
  if (!opts.experiments.includes(TRACIK)) return;
  if (opts.experiments.length > 1)
    throw usage(`--experiment: tracik runs alone, not with ${opts.experiments.filter((e) => e !== TRACIK).join(', ')}`);
  if (given('goals') && opts.goals !== 'pose')
    throw usage('--goals: the tracik experiment targets whole poses (--goals pose, its default)');
  if (given('errorTolerance'))
    throw usage(
      "--error-tolerance: the tracik experiment has TRAC-IK's tolerances (1e-5 on positions and on rotations, radians)",
    );
  opts.goals = 'pose';
  if (!given('samples')) for (const method of Object.keys(opts.samples)) opts.samples[method] = TRACIK_SAMPLES;
  if (!given('timeBudget')) opts.timeBudgetSeconds = TRACIK_TIMEOUT_S;
}

/** Checks --chain: BASE:TIP, and every rig a URDF file (the other formats have no chains to choose). */
export function checkChain(chain: string | undefined, rigs: readonly string[]): void {
  if (chain === undefined) return;
  if (!isChain(chain))
    throw usage(
      `--chain: ${quote(chain)} is not BASE:TIP (two link names of the URDF file, the chain's base and its tip)`,
    );
  const other = rigs.find((rig) => extname(rig).toLowerCase() !== '.urdf');
  if (other !== undefined)
    throw usage(`--chain: ${quote(other)} is no URDF file (.urdf): only URDF rigs have chains to choose`);
}

/**
 * The solver settings of the protocol (the rest as every experiment's: bench.ts runSettings):
 * pose goals, on target with every tip within TRACIK_TOLERANCE and every frame within
 * TRACIK_TOLERANCE radians, our solvers' gradient tolerance `gradientTolerance` (--gradient-tolerance; default TRACIK_GRADIENT_TOLERANCE).
 */
export function tracikSettings(
  gradientTolerance: number | undefined,
): Pick<RunSettings, 'gradientTolerance' | 'tipTolerance' | 'orientationToleranceDeg' | 'goals'> {
  return {
    gradientTolerance: gradientTolerance ?? TRACIK_GRADIENT_TOLERANCE,
    tipTolerance: TRACIK_TOLERANCE,
    orientationToleranceDeg: TRACIK_ROTATION_TOLERANCE_DEG,
    goals: 'pose',
  };
}
