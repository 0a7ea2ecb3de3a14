// One row of the report's tables from per-solve results (summarize), and the iteration count as the report made it.
//
// Definitions (statistics.ts gives mean, quantiles and the IQM):
//   success rate    fraction of the reachable samples whose final pose is on target: E < errorTolerance, or
//                   with a tip tolerance (drag, reach) every tip within it of its target
//   unreachable     samples whose targets the reference solve could not reach (reachability.ts);
//                   left out of the success rate
//   wobble (drag,   per step, the largest distance (rig units) of a pinned end effector from its
//   reach)          target; "during" is the largest over the solve's iterates, "after" at its end.
//   wobble over     the mean and max of wobble after over the unreachable steps (reach, gestures):
//   unreachable     how far an out-of-reach target pulls the pinned effectors off theirs.
//   jump_max_deg    per step, the largest single-angle change (degrees) from the step's start pose
//   (dragging)      to its solution (an angle without limits the shortest way round); the largest
//                   over the row's steps.
//   jumps           steps where a joint moved more than 5% of the rig size while the dragged
//   (dragging)      target moved less than 1% of it (jumps.ts).
//   flips           steps where an elbow or knee bent against its anatomical direction or its bend
//   (dragging)      plane turned more than 90 degrees (flips.ts); null for a rig without limbs.
//   rotation error  --goals pose: per solve, the largest angle (degrees) between an effector's frame
//                   at the final pose and its target orientation; rot_err_avg_deg and
//                   rot_err_max_deg are their mean and max over the row's solves.
import { isOnTarget, type OnTargetTest } from './evaluate.js';
import { countJumps } from './jumps.js';
import type { GoalsKind } from './pose_goals.js';
import { interquartileMean, maxOf, mean, median, quantile } from './statistics.js';
import { isDragging, type Experiment } from './target_set.js';
import { timeToSuccess, type TimeToSuccess } from './time_to_success.js';

/**
 * Iterations as the report counted them (`--paper`). Its runner counted calls of do_iteration()
 * until the solver said it was done, and the call that finds a stop test true takes no step:
 * so a solve that ended on a test (converged_E, converged_grad, zero_step) counts its steps plus
 * one, and one cut short by the budget (timeout, max_iterations) counts its steps. `iterations`
 * is our count of accepted steps.
 */
export function paperIterations(iterations: number, stopReason: string): number {
  return stopReason === 'converged_E' || stopReason === 'converged_grad' || stopReason === 'zero_step'
    ? iterations + 1
    : iterations;
}

/** What one solve produced. Times in seconds, E in rig units^2, distances in rig units, angles in degrees. */
export interface SolveResult {
  E: number;
  /** The largest distance of an end effector's tip from its target at the final pose. */
  tipDistance: number;
  iterations: number;
  seconds: number;
  stopReason: string;
  /** drag, reach: pinned effectors' largest distance from their targets over the iterates / at the end. */
  wobbleDuring: number;
  wobbleAfter: number;
  /** The largest single-angle change from the start pose to the final pose (largestChange). */
  jumpDeg: number;
  /** Drag, reach, gestures: the largest distance (rig units) a joint moved from the start pose to the final pose. */
  jointMove?: number;
  /** Drag, reach, gestures: 1 when the step flipped a limb (flips.ts), 0 when not; NaN or absent: not measured (no limbs). */
  flip?: number;
  /** The final pose (degrees), as the runner returned it; dropped before results leave a worker. */
  angles?: Float64Array;
  /** --goals pose: the largest angle between an effector's frame and its target orientation, degrees. */
  rotErrDeg?: number;
  /** --goals pose: the largest component of the twists onto the targets (pose_goals.ts largestTwistComponent: rig units and radians). */
  twistMax?: number;
}

/** A row's statistics over its solves (with its time to success, time_to_success.ts). */
export interface RowStats extends TimeToSuccess {
  rig: string;
  experiment: Experiment;
  method: string;
  engine: string;
  /** What the targets were: tip positions, or whole tip poses (--goals). */
  goals: GoalsKind;
  samples: number;
  t_avg_s: number;
  t_median_s: number;
  t_p95_s: number;
  t_p99_s: number;
  t_max_s: number;
  iter_avg: number;
  E_avg: number;
  E_iqm: number;
  E_max: number;
  /** Over the reachable samples. */
  success_rate: number;
  /** Samples judged unreachable (reach; 0 elsewhere: reachable by construction). */
  unreachable: number;
  /** Count per stop reason, e.g. {"converged_E": 180, "timeout": 20}. */
  stop_reasons: Record<string, number>;
  /** drag only (null otherwise, and when the rig has a single end effector). */
  wobble_during_avg: number | null;
  wobble_during_max: number | null;
  wobble_after_avg: number | null;
  wobble_after_max: number | null;
  /** Reach and gestures (null otherwise, and without unreachable steps): wobble after over the unreachable steps. */
  wobble_unreachable_avg: number | null;
  wobble_unreachable_max: number | null;
  /** Drag, reach and gestures only (null otherwise): the largest single-angle change in one step, degrees. */
  jump_max_deg: number | null;
  /** Drag, reach and gestures only (null otherwise): the steps that were jumps (jumps.ts). */
  jumps: number | null;
  /** Drag, reach and gestures on a rig with limbs (null otherwise): the steps that flipped a limb (flips.ts). */
  flips: number | null;
  /** --goals pose only (null otherwise): mean and max over the solves of the largest orientation error, degrees. */
  rot_err_avg_deg: number | null;
  rot_err_max_deg: number | null;
  /**
   * --goals pose with a tip tolerance (null otherwise): the share of the reachable solves with every
   * component of the twist onto the targets within the tip tolerance, KDL's and TRAC-IK's own test
   * (success_rate tests the distance and the angle: at most as lenient).
   */
  twist_rate: number | null;
}

/** One row of the tables and of --json: its statistics and the restarts every method had. */
export interface Row extends RowStats {
  /** Restarts allowed per solve, the same for every method of the run (0 in paper mode, drag and reach). */
  restarts: number;
}

export interface RowKey {
  rig: string;
  experiment: Experiment;
  method: string;
  engine: string;
  /** Default 'position'. */
  goals?: GoalsKind;
}

/** What tells a jump (jumps.ts): per result how far the dragged target moved, and the rig size (rig units). */
export interface JumpRule {
  targetMoves: ArrayLike<number>;
  size: number;
}

/**
 * Summarises per-solve results into a table row. `test`: what counts as on target (success);
 * `reachable`: 1 per result whose targets are reachable (the others are left out of success);
 * `jumpRule`: for drag, reach and gestures, what makes a step a jump (without it jumps is null).
 */
export function summarize(
  key: RowKey,
  results: readonly SolveResult[],
  test: OnTargetTest,
  reachable: ArrayLike<number>,
  jumpRule?: JumpRule,
): RowStats {
  const E = results.map((r) => r.E);
  const t = results.map((r) => r.seconds);
  const stop: Record<string, number> = {};
  for (const r of results) stop[r.stopReason] = (stop[r.stopReason] ?? 0) + 1;
  const during = results.map((r) => r.wobbleDuring).filter((w) => Number.isFinite(w));
  const after = results.map((r) => r.wobbleAfter).filter((w) => Number.isFinite(w));
  const jumps = results.map((r) => r.jumpDeg).filter((j) => Number.isFinite(j));
  const orNull = (v: number): number | null => (Number.isFinite(v) ? v : null);
  const judged = results.filter((_, k) => reachable[k] === 1);
  const succeeded = judged.map((r) => isOnTarget(test, r.E, r.tipDistance, r.rotErrDeg));
  const goals = key.goals ?? 'position';
  const rotation = goals === 'pose' ? results.map((r) => r.rotErrDeg ?? NaN) : [];
  const dragging = isDragging(key.experiment);
  const unreachableWobble = results
    .filter((r, k) => reachable[k] !== 1 && Number.isFinite(r.wobbleAfter))
    .map((r) => r.wobbleAfter);
  const flips = results.map((r) => r.flip ?? NaN).filter((f) => Number.isFinite(f));
  return {
    ...key,
    goals,
    samples: results.length,
    t_avg_s: mean(t),
    t_median_s: median(t),
    t_p95_s: quantile(t, 0.95),
    t_p99_s: quantile(t, 0.99),
    t_max_s: maxOf(t),
    iter_avg: mean(results.map((r) => r.iterations)),
    E_avg: mean(E),
    E_iqm: interquartileMean(E),
    E_max: maxOf(E),
    success_rate: judged.length ? succeeded.filter(Boolean).length / judged.length : NaN,
    ...timeToSuccess(
      judged.map((r) => r.seconds),
      succeeded,
    ),
    unreachable: results.length - judged.length,
    stop_reasons: stop,
    wobble_during_avg: orNull(mean(during)),
    wobble_during_max: orNull(maxOf(during)),
    wobble_after_avg: orNull(mean(after)),
    wobble_after_max: orNull(maxOf(after)),
    wobble_unreachable_avg: dragging ? orNull(mean(unreachableWobble)) : null,
    wobble_unreachable_max: dragging ? orNull(maxOf(unreachableWobble)) : null,
    jump_max_deg: dragging ? orNull(maxOf(jumps)) : null,
    jumps:
      dragging && jumpRule
        ? countJumps(
            results.map((r) => r.jointMove ?? NaN),
            jumpRule.targetMoves,
            jumpRule.size,
          )
        : null,
    flips: dragging && flips.length > 0 ? flips.filter((f) => f === 1).length : null,
    rot_err_avg_deg: goals === 'pose' ? orNull(mean(rotation)) : null,
    rot_err_max_deg: goals === 'pose' ? orNull(maxOf(rotation)) : null,
    twist_rate:
      goals === 'pose' && test.tipTolerance > 0 && judged.length
        ? judged.filter((r) => (r.twistMax ?? NaN) <= test.tipTolerance).length / judged.length
        : null,
  };
}
