// The target sets of PROTOCOL.md, plus the drag and reach experiments. Generated once per (rig,
// experiment) in the main thread from a seeded stream, before any solve, so every method, engine
// and worker count sees identical starts and targets; a method asked for fewer samples takes a prefix.
//
//   random:      A_k = P(360 * U(-1,1)^(3m)); each solve starts from P(0) (the rest pose).
//   incremental: A_0 = P(0), A_k = P(A_(k-1) + 5 * U(-1,1)^(3m)); solve k starts from A_(k-1).
//   drag:        paths of DRAG_PATH_STEPS steps. Along a path one end effector's exclusive angles
//                (bones that move no other effector) follow a sine from a base pose while every
//                other angle stays at the base, so the other effectors are pinned by construction.
//                The first step of a path starts from the base pose; the others start from the
//                previous step's solution (`chained`), as when a user drags an effector.
//   reach:       straight paths of one effector's target from its rest tip, the others pinned at
//                theirs, from P(0), chained (reach.ts). Not seeded: the set is the same for every seed.
//   tracik:      TRAC-IK's protocol (tracik.ts): A_k uniform within the limits, each solve from the
//                nominal (mid-limit) configuration; run with pose goals.
//   gestures:    a humanoid's scripted gestures (hand across the chest, over the head...) in small
//                steps from P(0), the others pinned at their rest tips, chained (gestures.ts). Not
//                seeded either.
// The targets of random, incremental and drag are x_b = x(A_k): reachable by construction. Reach
// and gestures targets are points, reachable or not: `reachable` says which (reachability.ts
// fills it in).
// Angles are degrees, P clamps to limits. The native tools and tests make random and incremental
// sets with the same streams in C++ (wasm/native/protocol.h); tests/bench/protocol_agreement.test.ts
// checks both give the same sets.
import type { RigSpec } from '#ik/rig_arrays.js';
import { draggableEffectors, exclusiveAngles } from './effectors.js';
import { fillGestures, gesturePaths, gestureSteps, type GestureBody } from './gestures.js';
import { signedUnit, streamFor } from './prng.js';
import { fillReach, REACH_PATH_STEPS, reachPaths } from './reach.js';
import { fillTracik } from './tracik.js';
import { hasReachability, project, type Experiment, type TargetSet, type TipsFn } from './target_set.js';

/** Steps per drag path. */
export const DRAG_PATH_STEPS = 40;
/** Random experiment: each angle is drawn from 360 * U(-1, 1) degrees (then clamped). */
export const RANDOM_RANGE_DEG = 360;
/** Largest random step per angle in the incremental experiment, degrees. */
export const INCREMENTAL_STEP_DEG = 5;
/** Drag: half-range of the base pose around the rest pose, and the sine amplitudes, degrees. */
export const DRAG_BASE_DEG = 20;
export const DRAG_AMPLITUDE_DEG: readonly [number, number] = [10, 30];

/**
 * Angles A = P(360 * U(-1,1)^(3m)) of a random target (degrees); `rand` gives numbers in [0, 1),
 * one per angle in order.
 */
export function randomAngles(spec: RigSpec, rand: () => number): Float64Array {
  const a = new Float64Array(spec.lower.length);
  for (let i = 0; i < a.length; i++) a[i] = RANDOM_RANGE_DEG * signedUnit(rand);
  return project(spec, a);
}

/** Angles P(previous + 5 * U(-1,1)^(3m)) of the next incremental target (degrees); `rand` as for randomAngles. */
export function incrementalAngles(spec: RigSpec, previous: ArrayLike<number>, rand: () => number): Float64Array {
  const a = new Float64Array(previous.length);
  for (let i = 0; i < a.length; i++) a[i] = previous[i] + INCREMENTAL_STEP_DEG * signedUnit(rand);
  return project(spec, a);
}

/**
 * Generates `count` samples of `experiment` for a run seeded with `seed`; reach has at most
 * reachPaths(...).length * REACH_PATH_STEPS samples (its whole set), gestures at most its paths'
 * steps, so they may return fewer. Gestures need `body`, the humanoid (else: an Error).
 */
export function generateTargets(
  spec: RigSpec,
  experiment: Experiment,
  count: number,
  seed: number,
  tips: TipsFn,
  body?: GestureBody,
): TargetSet {
  const m = spec.lower.length;
  const r = 3 * spec.effectors.length;
  const rest = project(spec, new Float64Array(m));
  const restTips = tips(rest);
  if (experiment === 'gestures' && !body) throw new Error('gestures: the rig is no recognised humanoid');
  const paths = experiment === 'reach' ? reachPaths(spec, restTips) : [];
  const gestures = experiment === 'gestures' ? gesturePaths(spec, body!, rest, restTips) : [];
  const whole = experiment === 'reach' ? paths.length * REACH_PATH_STEPS : gestureSteps(gestures);
  const n = hasReachability(experiment) ? Math.min(count, whole) : count;
  const set: TargetSet = {
    experiment,
    count: n,
    numAngles: m,
    numResiduals: r,
    starts: new Float64Array(n * m),
    targetAngles: null,
    targets: new Float64Array(n * r),
    orientations: null,
    chained: new Uint8Array(n),
    dragged: new Int32Array(n).fill(-1),
    group: Int32Array.from({ length: n }, (_, k) => k),
    reachable: new Uint8Array(n).fill(1),
  };
  if (experiment === 'reach') {
    fillReach(set, paths, rest, restTips);
    return set;
  }
  if (experiment === 'gestures') {
    fillGestures(set, gestures, rest, restTips);
    return set;
  }
  const targetAngles = (set.targetAngles = new Float64Array(n * m));
  const rand = streamFor(seed, experiment);
  if (experiment === 'tracik') fillTracik(spec, set, targetAngles, rand);
  else if (experiment === 'random') fillRandom(spec, set, targetAngles, rest, rand);
  else if (experiment === 'incremental') fillIncremental(spec, set, targetAngles, rest, rand);
  else fillDrag(spec, set, targetAngles, rand);
  for (let k = 0; k < n; k++) set.targets.set(tips(targetAngles.subarray(k * m, (k + 1) * m)), k * r);
  return set;
}

function fillRandom(spec: RigSpec, set: TargetSet, angles: Float64Array, rest: Float64Array, rand: () => number): void {
  const m = set.numAngles;
  for (let k = 0; k < set.count; k++) {
    angles.set(randomAngles(spec, rand), k * m);
    set.starts.set(rest, k * m);
  }
}

function fillIncremental(
  spec: RigSpec,
  set: TargetSet,
  angles: Float64Array,
  rest: Float64Array,
  rand: () => number,
): void {
  const m = set.numAngles;
  let previous = rest;
  for (let k = 0; k < set.count; k++) {
    angles.set(incrementalAngles(spec, previous, rand), k * m);
    set.starts.set(previous, k * m);
    previous = angles.subarray(k * m, (k + 1) * m);
  }
}

function fillDrag(spec: RigSpec, set: TargetSet, angles: Float64Array, rand: () => number): void {
  const m = set.numAngles;
  const exclusive = exclusiveAngles(spec);
  const draggable = draggableEffectors(spec);
  if (draggable.length === 0)
    throw new Error('drag: no end effector can move while the others stay pinned (every movable bone is shared)');
  const [ampLo, ampHi] = DRAG_AMPLITUDE_DEG;
  const pose = new Float64Array(m);
  for (let path = 0, k = 0; k < set.count; path++) {
    const effector = draggable[path % draggable.length];
    const base = new Float64Array(m);
    for (let i = 0; i < m; i++) base[i] = DRAG_BASE_DEG * signedUnit(rand);
    project(spec, base);
    const moving = exclusive[effector];
    const amplitude = moving.map(() => ampLo + (ampHi - ampLo) * rand());
    const phase = moving.map(() => 2 * Math.PI * rand());
    let previous: Float64Array = base;
    for (let t = 1; t <= DRAG_PATH_STEPS && k < set.count; t++, k++) {
      pose.set(base);
      moving.forEach((i, j) => {
        pose[i] =
          base[i] + amplitude[j] * (Math.sin((2 * Math.PI * t) / DRAG_PATH_STEPS + phase[j]) - Math.sin(phase[j]));
      });
      project(spec, pose);
      angles.set(pose, k * m);
      set.starts.set(previous, k * m);
      set.chained[k] = t > 1 ? 1 : 0;
      set.dragged[k] = effector;
      set.group[k] = path;
      previous = angles.subarray(k * m, (k + 1) * m);
    }
  }
}
