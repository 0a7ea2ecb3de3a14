// One method's WebAssembly solver (web/src/ik/solver.ts) on one rig, as the page and the widget
// use it: settings in the panel's units (milliseconds), sent to WebAssembly only when they change,
// the result's angles written into an array the caller keeps, and the E history copied out only
// when asked for. A per-frame solve is then one call in and one result object out.
import { type Goals, isPackedGoals, type PackedGoals } from '../ik/goals.js';
import type { IkRig } from '../ik/rig.js';
import { IkSolver, type SolverResult } from '../ik/solver.js';

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
  /** Random restarts after a stall (every method); the per-frame solve uses 0. */
  restarts: number;
  /** The report's original algorithms (finite-difference Jacobian, its line searches). */
  paperMode: boolean;
  /**
   * When not every target can be met, hold the ones that can and bring the others as close as
   * they get (the solver option strictPriority). Default true; false: the least-squares point of
   * all, which pulls pinned effectors off their targets (the report's "wobble").
   */
  strictPriority?: boolean;
  /** The farthest a joint moves in one solve, rig units (the solver option maxJointMove). Default 0: no cap. */
  maxJointMove?: number;
  /**
   * lm's damping factor at the start of a solve (the solver option lmInitialMu). Default 1: a
   * cautious first step; a stream of small changes (tracking) takes near Gauss-Newton steps.
   */
  lmInitialMu?: number;
  /** Iterations a solve takes before on target ends it (the solver option minIterations). Default 0. */
  minIterations?: number;
  /** Accepted steps a solve takes before its time budget can stop it (the solver option stepsBeforeBudget). Default 0. */
  stepsBeforeBudget?: number;
  /** Rejected steps after which an lm iteration is stuck (the solver option lmMaxRejections). Default 30. */
  lmMaxRejections?: number;
  /** A floating root's move (rig units) that a step weighs as a joint's degree (the solver option rootUnit). Default 1. */
  rootUnit?: number;
  /** A soft pull of the goals' chains towards a reference pose, 0..1000 (the solver option restWeight; Goals.stiffness per bone). Default 0: none. */
  restWeight?: number;
  /** The rest pull's reference is the solve's start angles, not the rest pose (the solver option restFromStart). Default false. */
  restFromStart?: boolean;
  /** Iterations towards the soft terms' optimum once the hard goals are on target (the solver option softIterations). Default 0: no cap. */
  softIterations?: number;
}

/** What a solve or a step reached (angles in degrees, distances in rig units, see SolverResult). */
export type SolveOutcome = SolverResult;

/** Every SolveSettings field (the type checks that none is missing and none is extra). */
const SETTING_KEYS = Object.keys({
  gradientTolerance: true,
  tipTolerance: true,
  maxIterations: true,
  timeBudgetMs: true,
  restarts: true,
  paperMode: true,
  strictPriority: true,
  maxJointMove: true,
  lmInitialMu: true,
  minIterations: true,
  stepsBeforeBudget: true,
  lmMaxRejections: true,
  rootUnit: true,
  restWeight: true,
  restFromStart: true,
  softIterations: true,
} satisfies Record<keyof SolveSettings, true>) as (keyof SolveSettings)[];

/** Whether `a` and `b` hold the same value in every field (an absent one is undefined). No allocation: called every frame. */
function sameSettings(a: SolveSettings, b: SolveSettings): boolean {
  for (let i = 0; i < SETTING_KEYS.length; i++) if (a[SETTING_KEYS[i]] !== b[SETTING_KEYS[i]]) return false;
  return true;
}

export class MethodSolver {
  private readonly solver: IkSolver;
  private readonly sent: SolveSettings = {
    gradientTolerance: NaN,
    tipTolerance: NaN,
    maxIterations: NaN,
    timeBudgetMs: NaN,
    restarts: NaN,
    paperMode: false,
  };
  /** Iterations of the last solve or step-mode solve (0: its history holds only the start). */
  lastIterations = 0;

  /** `method`: a name from the core's registry (IkSolver.methods). Owns WebAssembly memory: dispose() frees it. */
  constructor(
    rig: IkRig,
    readonly method: string,
  ) {
    this.solver = new IkSolver(rig, method);
  }

  /** The next solve's preferred move (IkSolver.setPreferredMove: degrees per angle, then a floating root's translation). */
  preferMove(move: ArrayLike<number>): void {
    this.solver.setPreferredMove(move);
  }

  /**
   * Solves from `start` (degrees, 3 per bone) towards `target` (3 per end effector, rig units) or
   * `goals` (positions and orientations, web/src/ik/goals.ts), a Goals object or packed ones
   * (EffectorGoals.packed: the per-frame path, checked by the core only). The angles found are written into `out` when given (it may be `start` itself) and returned as
   * `outcome.angles`; otherwise `outcome.angles` is a new array.
   */
  solve(
    start: Float64Array,
    target: Float64Array | Goals | PackedGoals,
    settings: SolveSettings,
    out?: Float64Array,
  ): SolveOutcome {
    this.configure(settings);
    return this.keep(
      isPackedGoals(target) ? this.solver.solvePacked(start, target, out) : this.solver.solve(start, target, out),
    );
  }

  /** Begins an iteration-by-iteration solve; returns the state before any step. */
  start(start: Float64Array, target: Float64Array | Goals, settings: SolveSettings): SolveOutcome {
    this.configure(settings);
    this.solver.start(start, target);
    return this.keep(this.solver.result());
  }

  /** One iteration of the solve begun by start() (none once it has stopped); its angles are a new array. */
  step(): SolveOutcome {
    if (this.solver.running) this.solver.step();
    return this.keep(this.solver.result());
  }

  /** E before the first iteration and after each one of the last solve or step-mode solve (a new array). */
  history(): Float64Array {
    return this.solver.errorHistory();
  }

  /** history() written into `out` as far as it fits (no new array); returns its whole length. */
  copyHistory(out: Float64Array): number {
    return this.solver.copyErrorHistory(out);
  }

  dispose(): void {
    this.solver.dispose();
  }

  private keep(outcome: SolveOutcome): SolveOutcome {
    this.lastIterations = outcome.iterations;
    return outcome;
  }

  /** Sends `settings` to the core now (a solve with the same settings then sends nothing). */
  configure(s: SolveSettings): void {
    if (sameSettings(this.sent, s)) return;
    this.solver.setOptions({
      gradientTolerance: s.gradientTolerance,
      tipTolerance: s.tipTolerance,
      maxIterations: s.maxIterations,
      timeBudgetSeconds: s.timeBudgetMs / 1000,
      restarts: s.restarts,
      paperMode: s.paperMode,
      strictPriority: s.strictPriority ?? true,
      maxJointMove: s.maxJointMove ?? 0,
      lmInitialMu: s.lmInitialMu ?? 1,
      minIterations: s.minIterations ?? 0,
      stepsBeforeBudget: s.stepsBeforeBudget ?? 0,
      lmMaxRejections: s.lmMaxRejections ?? 30,
      rootUnit: s.rootUnit ?? 1,
      restWeight: s.restWeight ?? 0,
      restFromStart: s.restFromStart ?? false,
      softIterations: s.softIterations ?? 0,
    });
    const sent = this.sent as unknown as Record<string, unknown>;
    for (let i = 0; i < SETTING_KEYS.length; i++) sent[SETTING_KEYS[i]] = s[SETTING_KEYS[i]];
  }
}
