// The solves the page and the widget run: one per animation frame while targets move, and one
// iteration at a time in step mode. Times are main-thread milliseconds around the call
// (JavaScript, the embind crossing and the WebAssembly solve).
import type { IkSession } from './session.js';
import { METHOD_LABELS, type Method, type SolveOutcome, type SolveSettings } from './solver_port.js';

/** True while a solve has not stopped ('' from a solver that reports no state). */
export function isRunning(reason: string): boolean {
  return reason === '' || reason === 'running';
}

/** Stop reasons after which the next frame goes on solving: the budget ran out, not the problem. */
export function budgetStop(reason: string): boolean {
  return reason === 'max_iterations' || reason === 'timeout';
}

export interface FrameSolve {
  outcome: SolveOutcome;
  ms: number;
  /** Solve again next frame (the per-frame budget stopped it). */
  again: boolean;
}

/** One per-frame solve from the current pose; random restarts are always off here. */
export function solveFrame(session: IkSession, method: Method, settings: SolveSettings): FrameSolve {
  const t0 = performance.now();
  const outcome = session.solve(method, { ...settings, restarts: 0 });
  const ms = performance.now() - t0;
  return { outcome, ms, again: budgetStop(outcome.stopReason) };
}

/** Largest tip-to-target distance over the effectors other than `except` (the dragged one). */
export function pinnedDrift(tips: Float64Array, targets: Float64Array, except: number | null): number {
  let worst = 0;
  for (let k = 0; k < targets.length / 3; k++) {
    if (k === except) continue;
    const d = Math.hypot(tips[3 * k] - targets[3 * k], tips[3 * k + 1] - targets[3 * k + 1], tips[3 * k + 2] - targets[3 * k + 2]);
    worst = Math.max(worst, d);
  }
  return worst;
}

export interface StepReport {
  outcome: SolveOutcome;
  ms: number;
  /** The pose before the step (the ghost). */
  before: Float64Array;
  /** E before the step. */
  E0: number;
  /** |A_k+1 - A_k| in degrees. */
  stepLength: number;
  /** One line for the step-info box. */
  text: string;
}

/**
 * One iteration of `method` from the current pose. `restart` begins a new step-mode solve first
 * (after the targets, the method or the pose changed).
 */
export function takeStep(session: IkSession, method: Method, settings: SolveSettings, restart: boolean): StepReport {
  if (restart || session.steppingMethod !== method) session.beginSteps(method, { ...settings, timeBudgetMs: Infinity, restarts: 0 });
  const before = session.angles;
  const E0 = session.objective();
  const t0 = performance.now();
  const outcome = session.step();
  const ms = performance.now() - t0;
  let len = 0;
  for (let j = 0; j < before.length; j++) len += (outcome.angles[j] - before[j]) ** 2;
  const stepLength = Math.sqrt(len);
  const alpha = outcome.stepLength !== null ? `, line-search step α = ${outcome.stepLength.toPrecision(3)}` : '';
  const state = isRunning(outcome.stopReason) ? 'running' : `stopped: ${outcome.stopReason}`;
  const text =
    `${METHOD_LABELS[method]}, iteration ${outcome.iterations}: E ${E0.toExponential(3)} → ${outcome.E.toExponential(3)}; ` +
    `|ΔA| = ${stepLength.toPrecision(3)}°${alpha} (${state}). Faint bones: the previous iterate.`;
  return { outcome, ms, before, E0, stepLength, text };
}
