// A target set of the bench's experiments: the samples every method and engine solves (starts,
// targets, what is chained and reachable), the experiments' names, and what each kind of set
// needs. Made by targets.ts (and reach.ts, gestures.ts, tracik.ts); read by the runners and the
// measures. Angles are degrees.
import type { RigSpec } from '#ik/rig_arrays.js';

export type Experiment = 'random' | 'incremental' | 'drag' | 'reach' | 'gestures' | 'tracik';
export const experiments: readonly Experiment[] = ['random', 'incremental', 'drag', 'reach', 'gestures', 'tracik'];

/**
 * Drag, reach and gestures: paths a user drags an effector along. Solved as the page solves while
 * dragging (the drag tolerances, no restarts), judged by the tip test, with wobble, jump and flip
 * columns.
 */
export function isDragging(experiment: Experiment): boolean {
  return experiment === 'drag' || experiment === 'reach' || experiment === 'gestures';
}

/** Reach and gestures: fixed sets of target points, some perhaps out of reach (reachability.ts decides). */
export function hasReachability(experiment: Experiment): boolean {
  return experiment === 'reach' || experiment === 'gestures';
}

/** Forward kinematics: end-effector tips (3 per effector) at `angles`. */
export type TipsFn = (angles: Float64Array) => Float64Array;

export interface TargetSet {
  experiment: Experiment;
  count: number;
  numAngles: number;
  numResiduals: number;
  /** count x numAngles: start angles of each solve (chained steps: drag's ideal previous pose, reach's rest pose). */
  starts: Float64Array;
  /** count x numAngles: the angles A_k the target was made from; null for reach (its targets are points). */
  targetAngles: Float64Array | null;
  /** count x numResiduals: x_b = x(A_k) (reach: the path's points). */
  targets: Float64Array;
  /**
   * --goals pose only (else null): count x (4 per effector) quaternions [x, y, z, w], each
   * effector's frame rotation at A_k (pose_goals.ts).
   */
  orientations: Float64Array | null;
  /** 1 where the solve starts from the previous solve's result instead of `starts` (drag, reach). */
  chained: Uint8Array;
  /** drag, reach: the dragged effector (index into spec.effectors) per sample; -1 otherwise. */
  dragged: Int32Array;
  /** drag, reach: path index per sample; for other experiments each sample is its own group. */
  group: Int32Array;
  /** 1 where the sample's targets can be reached together (all but reach: by construction). */
  reachable: Uint8Array;
}

/** A view of samples [0, count) of a set (a prefix: what a method with fewer samples gets). */
export function prefix(set: TargetSet, count: number): TargetSet {
  const n = Math.min(count, set.count);
  const m = set.numAngles,
    r = set.numResiduals;
  return {
    ...set,
    count: n,
    starts: set.starts.subarray(0, n * m),
    targetAngles: set.targetAngles?.subarray(0, n * m) ?? null,
    targets: set.targets.subarray(0, n * r),
    orientations: set.orientations?.subarray(0, (n * 4 * r) / 3) ?? null,
    chained: set.chained.subarray(0, n),
    dragged: set.dragged.subarray(0, n),
    group: set.group.subarray(0, n),
    reachable: set.reachable.subarray(0, n),
  };
}

/** Clamps `a` into the spec's limits, in place. */
export function project(spec: RigSpec, a: Float64Array): Float64Array {
  for (let i = 0; i < a.length; i++) a[i] = Math.min(spec.upper[i], Math.max(spec.lower[i], a[i]));
  return a;
}

/**
 * Ranges [begin, end) of samples that can be solved independently: single samples, or whole
 * drag and reach paths. Workers take whole ranges, so results never depend on the partition.
 */
export function independentRanges(set: TargetSet): Array<[number, number]> {
  const ranges: Array<[number, number]> = [];
  for (let k = 0; k < set.count;) {
    let end = k + 1;
    while (end < set.count && set.chained[end]) end++;
    ranges.push([k, end]);
    k = end;
  }
  return ranges;
}
