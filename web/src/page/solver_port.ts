// What the page needs from a solver, independent of how the solver is built. The page and the
// widget talk only to this interface; solver_adapter.ts implements it over web/src/ik/solver.ts.
import type { IkRig } from '../ik/rig.js';

/** The five methods, in the order the panel, the plots and the compare table list them. */
export const METHODS = ['gd', 'bfgs', 'gn', 'newton', 'lm'] as const;
export type Method = (typeof METHODS)[number];

export const METHOD_LABELS: Record<Method, string> = {
  gd: 'gradient descent',
  bfgs: 'damped BFGS',
  gn: 'Gauss–Newton',
  newton: 'Newton',
  lm: 'Levenberg–Marquardt',
};

export function isMethod(value: string | null | undefined): value is Method {
  return value !== null && value !== undefined && (METHODS as readonly string[]).includes(value);
}

/** The knobs of one solve. Times are milliseconds here (the panel's unit). */
export interface SolveSettings {
  /** Stop when ||grad E|| falls below this (rig units^2 per degree). */
  gradientTolerance: number;
  /** On target when every end effector lies within this distance of its target (rig units). */
  tipTolerance: number;
  /** Iteration cap of one solve. */
  maxIterations: number;
  /** Wall-clock budget of one solve, milliseconds. */
  timeBudgetMs: number;
  /** Random restarts after a stall (every method); the per-frame solve forces 0. */
  restarts: number;
  /** The report's original algorithms (finite-difference Jacobian, its line searches). */
  paperMode: boolean;
}

/** The outcome of a solve or of one step. `angles` is a fresh array the caller may keep. */
export interface SolveOutcome {
  angles: Float64Array;
  E: number;
  gradNorm: number;
  /** Largest distance of an end effector from its target, rig units. */
  tipDistance: number;
  /** Every end effector within the tip tolerance of its target. */
  reached: boolean;
  iterations: number;
  stopReason: string;
  elapsedSeconds: number;
  /** Line-search step length of the last iteration, when the solver reports one. */
  stepLength: number | null;
  /** E before the first iteration and after each one (length iterations + 1). */
  history: Float64Array;
}

/** One method bound to one rig. Owns WebAssembly memory: dispose() frees it. */
export interface MethodSolver {
  readonly method: Method;
  /** Solves from `start` towards `target` (3 numbers per end effector). */
  solve(start: Float64Array, target: Float64Array, settings: SolveSettings): SolveOutcome;
  /** Begins an iteration-by-iteration solve; returns the state before any step. */
  start(start: Float64Array, target: Float64Array, settings: SolveSettings): SolveOutcome;
  /** One iteration of the solve begun by start(); `stopReason` is non-empty once it has stopped. */
  step(): SolveOutcome;
  dispose(): void;
}

/** Makes solvers for a rig. Called again after the rig's end effectors change. */
export type SolverFactory = (rig: IkRig, method: Method) => MethodSolver;
