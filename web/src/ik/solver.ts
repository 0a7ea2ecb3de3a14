// The IK solvers living in WebAssembly: one method (lm, gn, bfgs, newton, gd) bound to one rig.
// Angles are 3 numbers per bone in DEGREES (XZX); targets are 3 numbers per end effector in rig
// units; E = 1/2 |tips - target|^2. In place of a target, start() and solve() take Goals
// (goals.ts): positions and orientations per effector, with weights. The object owns
// WebAssembly memory: call dispose() when done, and dispose it before its rig.
import type { EmbindSolver, EmbindSolverOptions, IkCoreModule } from './generated/ik_core.mjs';
import { isGoals, packGoals, type Goals, type PackedGoals } from './goals.js';
import { checkedNumbers, coreError, plainOptions, toFloat64 } from './inputs.js';
import type { IkRig, Numbers } from './rig.js';

/**
 * A method's name, as the core's registry (wasm/src/solvers/solver_registry.cpp) spells it: "lm"
 * (the default), "gn", "bfgs", "newton", "gd" in this build. `IkSolver.methods(module)` lists them;
 * no TypeScript list repeats them, so a method registered in C++ appears everywhere.
 */
export type SolverMethod = string;

/** Why a solve stopped (wasm/src/solvers/solver.h gives each one's exact test). */
export type StopReason =
  | 'running' // not stopped yet
  | 'converged_E' // on target (`reached`): E < errorTolerance, or every tip within tipTolerance when set
  | 'converged_grad' // |grad E| (free angles) < gradientTolerance off target, no negative curvature: a local closest point
  | 'zero_step' // no step lowered E (and restarts, if any, were used up)
  | 'max_iterations' // iterations reached maxIterations
  | 'timeout' // the time budget ran out
  | 'invalid_input' // the last start() or solve() was refused (it threw an Error); only result() shows it
  | 'numerical_failure' // E or a derivative became non-finite
  | 'joint_speed'; // a chain restart's answer lay farther than maxJointMove: the pose moved partway there; solve again to go on

/**
 * Solver options; every field is optional and defaults to the core's default (the list
 * wasm/src/solvers/solver_options.def, which Solver.defaultOptions() reports).
 * Tolerances default to the report's for rigs of about unit size (1e-4, 2e-4).
 */
export interface SolverOptions {
  /** Stop when |grad E| < this (rig units^2 per degree). Default 1e-4. */
  gradientTolerance?: number;
  /** Stop when E < this (rig units^2), > 0 (0 could never be met). Default 2e-4. Unused when tipTolerance > 0. */
  errorTolerance?: number;
  /**
   * Rig units. > 0: on target means every end effector's tip lies within this distance of its
   * target (replaces the E test). Default 0 (the E test).
   */
  tipTolerance?: number;
  /**
   * Degrees. With orientation goals, on target also needs every effector's orientation within
   * this angle of its target (the E test then reads the position rows only). Default 0.5.
   */
  orientationToleranceDeg?: number;
  /** Iteration cap. Default 100000. */
  maxIterations?: number;
  /**
   * Iterations a solve takes before on target ends it (within maxIterations): a tracked frame that
   * starts within the tolerance is polished instead of left. Default 0.
   */
  minIterations?: number;
  /** Time budget of one solve, seconds (time spent inside start/step); 0 or Infinity: none. Default 1. */
  timeBudgetSeconds?: number;
  /**
   * Accepted steps a solve takes before timeBudgetSeconds can stop it (within maxIterations), 0..10:
   * a per-frame solve on a slow machine still moves; 0: the budget holds from the start. Default 0.
   */
  stepsBeforeBudget?: number;
  /** E values kept per solve for errorHistory(). Default 10000. */
  historyCapacity?: number;
  /** Reproduce the original program (finite differences, its line searches). Default false. */
  paperMode?: boolean;
  /** Finite-difference step in paper mode, degrees, in 1e-9..1 (smaller is lost to rounding, larger misses the slope). Default 1e-7. */
  fdStepDeg?: number;
  /**
   * Gradient descent's first trial step length: at every iteration in paper mode; outside it only
   * where no Barzilai-Borwein step is at hand (a run's first iteration, or no positive curvature
   * met). Default 180/pi.
   */
  gdInitialStep?: number;
  /** Backtracking factor, in (0, 1). Default 0.5. */
  backtrackFactor?: number;
  /**
   * Sufficient-decrease constant of bfgs's and gn's line searches. Default 1e-3. (gd uses its own:
   * 0 in paper mode, 1e-4 outside it.)
   */
  armijoC1?: number;
  /** Backtracking trials before giving up (outside paper mode). Default 60. */
  maxBacktracks?: number;
  /** Gauss-Newton: singular values below this times the largest are dropped (not in paper mode). Default 3e-3. */
  gnSingularCutoff?: number;
  /** Gauss-Newton's largest step per angle, degrees (not in paper mode). Default 60. */
  gnMaxStepDeg?: number;
  /** Newton's largest step per angle, degrees. Default 45. */
  newtonMaxStepDeg?: number;
  /**
   * Initial Levenberg-Marquardt damping factor mu, of lm's step and of newton's shift (the
   * Levenberg-Marquardt modification of Newton's method), at the start of every run. Default 1.
   */
  lmInitialMu?: number;
  /** Smallest damping (lm and newton), relative to the mean diagonal of J J^T (newton: of the Hessian). Default 1e-12. */
  lmDampingFloor?: number;
  /** Rejected trials per iteration (lm and newton) before stopping with zero_step. Default 30. */
  lmMaxRejections?: number;
  /**
   * A floating root's move (rig units) that the damped steps (lm's, the strict-priority step)
   * weigh as one degree of a joint's turn: they take the least change that meets the goals, the
   * root's translation counted in these units. Default 1; smaller keeps the root still and moves
   * the joints instead. No effect without a floating root.
   */
  rootUnit?: number;
  /**
   * Pulls the angles of the bones on a goal's or a pole's chain towards the rest pose (all 0), or
   * with restFromStart towards the solve's start angles: rows restWeight * stiffness * L * (pi/180)
   * * (angle - reference), rig units (Goals.stiffness per bone; L the goals' length scale). Never at
   * the cost of the goals: on target reads only them, and a run that stops off target drops the
   * pull. At most 1000, like a stiffness and a pole's weight. Not in paper mode. Default 0 (none).
   */
  restWeight?: number;
  /** The rest pull's reference is the solve's start angles instead of the rest pose. Default false. */
  restFromStart?: boolean;
  /**
   * With soft rows on (poles, a rest pull): the iterations a solve takes towards the soft terms'
   * optimum once its hard goals are on target; then it ends. Default 0 (no cap). A solve per frame
   * goes on from where the last stopped.
   */
  softIterations?: number;
  /** Restarts from quasi-random points after a stall, within the time budget (every method outside paper mode; set 0 while dragging). Default 1000. */
  restarts?: number;
  /** Iterations without a 10% improvement that count as a stall (with restarts). Default 30. */
  stallIterations?: number;
  /** The restart sequence's seed, an integer in [0, 2^32). Default 1. */
  seed?: number;
  /**
   * At a stationary point off target (a straight limb whose target moved along it), step along a
   * direction of negative curvature of E before stopping or restarting (not in paper mode). Default true.
   */
  escapeSaddles?: boolean;
  /**
   * With no restart left (restarts 0 while dragging): restarts of only the off-target chains from
   * the best point, when a run ends at a local minimum off target that no escape leaves. The other
   * chains keep their pose. Default 64 per solve.
   */
  chainRestarts?: number;
  /**
   * When the goals cannot all be met (not in paper mode): the ones that can are held within their
   * tolerance and the others brought as close as the freedom left allows, an orientation given
   * up before a position; a target out of reach no longer pulls the others off theirs (result:
   * outOfReach, orientationOutOfReach). false: the least-squares point of all goals. Default true.
   */
  strictPriority?: boolean;
  /**
   * Bounded joint speed, rig units: > 0 caps how far any joint (a bone's head or tip) moves in a
   * solve that lands on another branch of solutions (after a chain restart), beyond how far the
   * targets moved. Such an answer comes back as the pose partway there, with stopReason
   * 'joint_speed'; solving again from that pose resumes the move. A run that follows E down from
   * the start is never cut. The page and the bench's dragging experiments use 4% of the rig size.
   * Default 0 (no cap).
   */
  maxJointMove?: number;
}

export interface SolverResult {
  /** Best angles found (a fresh array), degrees, inside the limits. */
  angles: Float64Array;
  /** E at `angles`. */
  E: number;
  /** E at the start angles (after clamping into the limits). */
  initialE: number;
  /** |grad E| over the free angles at `angles` (paper mode: the full gradient). */
  gradNorm: number;
  /** The largest distance of an end effector's tip from its target at `angles`, rig units. */
  tipDistance: number;
  /**
   * `angles` is on target (the test of converged_E); stopReason is converged_E exactly when this is
   * true. No number of a result is NaN: one that overflowed reads Infinity, with numerical_failure.
   */
  reached: boolean;
  iterations: number;
  functionEvaluations: number;
  jacobianEvaluations: number;
  restarts: number;
  /** Steps out of a stationary point along negative curvature (escapeSaddles). */
  escapes: number;
  /** Restarts of the off-target chains only (chainRestarts). */
  chainRestarts: number;
  /**
   * Strict priority (option strictPriority): a position goal could not be met and is at its
   * closest point, with every goal that can be met on target (the others are not pulled off
   * theirs). Also true for a solve that ended at the closest point of goals that cannot all be met.
   */
  outOfReach: boolean;
  /** Only orientation goals could not be met: every position goal is on target (position first). */
  orientationOutOfReach: boolean;
  /** Goals (an effector's position or orientation) given up in this solve to hold the others. */
  goalsGivenUp: number;
  stopReason: StopReason;
  /** Explains numerical_failure; empty otherwise. */
  message: string;
  /** Seconds spent inside start() and step(). */
  elapsedSeconds: number;
}

function equal(a: Float64Array, b: Float64Array): boolean {
  if (a.length !== b.length) return false;
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) return false;
  return true;
}

/** Copies `from` into `to` when it has the same length, else returns a copy of `from`. */
function keepCopy(to: Float64Array, from: Float64Array): Float64Array {
  if (to.length !== from.length) return from.slice();
  to.set(from);
  return to;
}

/** The first `n` numbers of `from` written into `out` (no view made: called every frame); returns `out`. */
function copyInto(out: Float64Array, from: Float64Array<ArrayBufferLike>, n: number): Float64Array {
  for (let i = 0; i < n; i++) out[i] = from[i];
  return out;
}

/** Goals as last handed to the core, for the rig's effectors of version `effectors`. */
interface SentGoals {
  packed: Float64Array;
  poles: Float64Array;
  stiffness: Float64Array;
  lengthScale: number;
  effectors: number;
}

/**
 * A result record with every field a solve writes, in the order it writes them (one shape): the
 * numbers start as a double (NaN), so that writing one later rewrites it in place, not in a new box.
 */
function resultRecord(ioNames: readonly string[], ioFlags: readonly boolean[]): Record<string, unknown> {
  const record: Record<string, unknown> = { angles: null, stopReason: '', message: '' };
  ioNames.forEach((name, k) => (record[name] = ioFlags[k] ? false : NaN));
  return record;
}

/** What the API reads once per module: stop reasons by solveIo()'s index, option names, the result numbers. */
interface ModuleFacts {
  stopReasons: readonly string[];
  optionNames: readonly string[];
  /** The result numbers' names in the order the core writes them after the target (wasm/src/solvers/summary_numbers.def). */
  ioNames: readonly string[];
  /** Per result number, whether it is a flag (1 or 0, read as a boolean). */
  ioFlags: readonly boolean[];
}
const factsCache = new WeakMap<IkCoreModule, ModuleFacts>();

function moduleFacts(module: IkCoreModule): ModuleFacts {
  let facts = factsCache.get(module);
  if (!facts) {
    const names = module.Solver.ioStats(),
      flags = new Set(module.Solver.ioFlags());
    facts = {
      stopReasons: module.Solver.stopReasons(),
      optionNames: Object.keys(module.Solver.defaultOptions()),
      ioNames: names,
      ioFlags: names.map((name) => flags.has(name)),
    };
    factsCache.set(module, facts);
  }
  return facts;
}

/** `options` as a fresh plain object the core can read, or an Error naming the problem. */
function coreOptions(module: IkCoreModule, options: unknown): EmbindSolverOptions {
  return plainOptions(options, moduleFacts(module).optionNames, 'solver option') as EmbindSolverOptions;
}

export class IkSolver {
  readonly handle: EmbindSolver;
  readonly method: string;
  private disposed = false;
  /** solve()'s buffer in WebAssembly memory: angles | target | the result numbers (ModuleFacts.io). */
  private io: Float64Array<ArrayBufferLike> = new Float64Array(0);
  /** errorHistory()'s buffer in WebAssembly memory (at least the history's length after readHistory()). */
  private history: Float64Array<ArrayBufferLike> = new Float64Array(0);
  /** The result record of the solves with `out` (rewritten by each: no new object per frame). */
  private outResult: Record<string, unknown> | null = null;
  /** Copies of the goals last handed to the core (undefined: plain targets), to skip handing them again. */
  private goals?: SentGoals;
  /** The record `goals` points to while there are goals (kept: no new object per frame). */
  private sentGoals?: SentGoals;
  /** The core's goals buffer (goalsView; asked anew when its length changes or the memory grew). */
  private goalsIo: Float64Array<ArrayBufferLike> = new Float64Array(0);
  /** The core's preferred-move buffer (preferredView; asked anew when stale). */
  private preferredIo: Float64Array<ArrayBufferLike> = new Float64Array(0);

  /** The methods this build registers, in display order (lm, the default, first). */
  static methods(module: IkCoreModule): SolverMethod[] {
    return module.Solver.methods();
  }

  /** A method's short human name ("Levenberg–Marquardt"). Throws for an unknown name. */
  static label(module: IkCoreModule, method: string): string {
    if (typeof method !== 'string') throw new Error(`a solver method is a name such as "lm", not ${typeof method}`);
    const text = module.Solver.label(method);
    if (!text) throw coreError(module, 'label');
    return text;
  }

  /** One line describing a method. Throws for an unknown name. */
  static describe(module: IkCoreModule, method: string): string {
    if (typeof method !== 'string') throw new Error(`a solver method is a name such as "lm", not ${typeof method}`);
    const line = module.Solver.describe(method);
    if (!line) throw coreError(module, 'describe');
    return line;
  }

  /**
   * A solver of `method` on `rig`. Throws an Error for an unknown method or option name, or a
   * value of the wrong type; option ranges are checked by start() and solve().
   */
  constructor(
    readonly rig: IkRig,
    method: SolverMethod = 'lm',
    options: SolverOptions = {},
  ) {
    if (typeof method !== 'string') throw new Error(`a solver method is a name such as "lm", not ${typeof method}`);
    const plain = coreOptions(rig.module, options);
    if (rig.isDisposed) throw new Error('this rig was disposed');
    const handle = rig.module.Solver.create(rig.handle, method, plain);
    if (!handle) throw coreError(rig.module, 'creating the solver');
    this.handle = handle;
    this.method = handle.method;
  }

  /** Options for the next start() or solve(); the solve in progress keeps its own. */
  setOptions(options: SolverOptions): void {
    this.live();
    const plain = coreOptions(this.rig.module, options);
    if (!this.live().setOptions(plain)) throw coreError(this.rig.module, 'setOptions');
  }

  /** The options of the current solve, every field filled in. */
  options(): Required<SolverOptions> {
    return this.live().options() as Required<SolverOptions>;
  }

  /**
   * Begins a solve from `angles` towards `target` (3 numbers per current end effector) or `goals`.
   * Returns 'running', or 'converged_E' / 'converged_grad' if the start already meets a tolerance.
   * Throws an Error for wrong lengths, non-finite numbers, bad goals or out-of-range options.
   */
  start(angles: Numbers, target: Numbers | Goals): StopReason {
    this.live();
    const a = toFloat64(angles, 'angles', this.rig.numAngles, false); // the core refuses non-finite ones
    const t = Float64Array.from(this.useGoals(target)); // a copy: the core reads it after user code ran
    const reason = this.live().start(a, t);
    if (!reason) throw coreError(this.rig.module, 'start');
    return reason as StopReason;
  }

  /** One iteration; true while the solve is still running. */
  step(): boolean {
    return this.live().step();
  }

  get running(): boolean {
    return this.live().running;
  }

  /**
   * start() then step() to the end. Throws like start(). The numbers cross in one shared buffer
   * (ioView / solveIo), so a call costs well under a microsecond more than the solve itself.
   * `out` (optional, a Float64Array of #angles): the result's angles are written there and it is
   * returned as `angles` (no new array per call; it may be `angles` itself), and the result is
   * this solver's one record for such solves, rewritten by the next (copy what you keep).
   * Otherwise `angles` is a new array and the result a new record.
   */
  solve(angles: Numbers, target: Numbers | Goals, out?: Float64Array): SolverResult {
    this.live();
    const n = this.rig.numAngles,
      m = 3 * this.rig.numEffectors;
    if (out !== undefined && !(out instanceof Float64Array && out.length === n))
      throw new Error(`out must be a Float64Array of ${n} numbers (the angles)`);
    const a = checkedNumbers(angles, 'angles', n);
    const t = this.useGoals(target);
    this.live(); // reading a Proxy may have disposed it
    if (3 * this.rig.numEffectors !== m) throw new Error('the end effectors changed while the target was being read');
    return this.run(a, t, out);
  }

  /**
   * solve() for goals packed already (packGoals, or a caller that keeps its own PackedGoals in the
   * rig's effector order, as the live session does every frame): TypeScript checks the lengths
   * only, not each goal (the core checks the goals when they change, with the same errors, and
   * refuses non-finite angles and targets on every path). `angles`: degrees, 3 per bone.
   */
  solvePacked(angles: Float64Array, goals: PackedGoals, out?: Float64Array): SolverResult {
    const n = this.rig.numAngles,
      m = 3 * this.rig.numEffectors;
    if (!(angles instanceof Float64Array) || angles.length !== n)
      throw new Error(`angles must be a Float64Array of ${n} numbers`);
    if (out !== undefined && !(out instanceof Float64Array && out.length === n))
      throw new Error(`out must be a Float64Array of ${n} numbers (the angles)`);
    if (goals.target.length !== m)
      throw new Error(`the goals' target has ${goals.target.length} values, expected ${m}`);
    this.sendGoals(goals);
    return this.run(angles, goals.target, out);
  }

  /** Solves from angles `a` towards target `t` (checked) through the shared buffer; see solve(). */
  private run(a: ArrayLike<number>, t: ArrayLike<number>, out?: Float64Array): SolverResult {
    const handle = this.live();
    const n = this.rig.numAngles,
      m = t.length;
    let io = this.buffer(n, m);
    io.set(a, 0);
    io.set(t, n);
    const code = handle.solveIo();
    if (code < 0) throw coreError(this.rig.module, 'solve');
    if (io.length === 0) io = this.buffer(n, m); // the memory grew during the solve
    return this.readResult(io, n, m, code, out);
  }

  /**
   * A move for the next solve's first lm step to add where the goals leave room (the core's
   * Solver::set_preferred_move): `move`, #angles numbers, degrees per angle, then a floating
   * root's translation (rig units). To first order the goals see none of it: a posture preference
   * such as a body unwinding its twist, once per solve. Other methods ignore it, and the solve
   * after the next has none unless it is set again. Throws for a wrong length or a value that is
   * not finite. No allocation once its buffer is sized.
   */
  setPreferredMove(move: ArrayLike<number>): void {
    const live = this.live(),
      n = this.rig.numAngles;
    if (move.length !== n) throw new Error(`the preferred move has ${move.length} values, expected ${n} (the angles)`);
    if (this.preferredIo.length !== n) {
      const view = live.preferredView();
      if (!view) throw coreError(this.rig.module, 'setPreferredMove');
      this.preferredIo = view;
    }
    this.preferredIo.set(move);
    if (!live.setPreferredIo()) throw coreError(this.rig.module, 'setPreferredMove');
  }

  /** The solve so far (or the finished one). */
  result(): SolverResult {
    const handle = this.live();
    const n = this.rig.numAngles,
      m = 3 * this.rig.numEffectors;
    const io = this.buffer(n, m);
    const code = handle.resultIo();
    if (code < 0) throw coreError(this.rig.module, 'result');
    return this.readResult(io, n, m, code);
  }

  /**
   * The result the core wrote into `io` (n angles, m target numbers, then the result numbers in
   * ModuleFacts.ioNames's order) with stop reason index `code`; the angles into `out` when given.
   * The message crosses only when there is one to tell (a string per frame otherwise).
   */
  private readResult(
    io: Float64Array<ArrayBufferLike>,
    n: number,
    m: number,
    code: number,
    out?: Float64Array,
  ): SolverResult {
    const facts = moduleFacts(this.rig.module);
    const stopReason = facts.stopReasons[code] as StopReason;
    const failed = stopReason === 'numerical_failure' || stopReason === 'invalid_input';
    const names = facts.ioNames,
      flags = facts.ioFlags;
    const result: Record<string, unknown> = out ? (this.outResult ??= resultRecord(names, flags)) : {};
    // A refused solve (invalid_input; result() before any solve too) has no angles.
    result.angles = stopReason === 'invalid_input' ? new Float64Array(0) : out ? copyInto(out, io, n) : io.slice(0, n);
    result.stopReason = stopReason;
    result.message = failed ? this.handle.message() : '';
    for (let k = 0, at = n + m; k < names.length; k++, at++) result[names[k]] = flags[k] ? io[at] === 1 : io[at];
    return result as unknown as SolverResult;
  }

  /** E at the start and after each iteration so far (a fresh array). */
  errorHistory(): Float64Array {
    const n = this.readHistory();
    return this.history.slice(0, n);
  }

  /**
   * errorHistory() written into `out` (as much of it as fits, from the start) with no new array;
   * returns the history's whole length, so a caller whose `out` is too short can grow it and ask
   * again.
   */
  copyErrorHistory(out: Float64Array): number {
    const n = this.readHistory();
    const h = this.history;
    for (let i = 0, m = Math.min(n, out.length); i < m; i++) out[i] = h[i];
    return n;
  }

  /** The current iterate, degrees (a fresh array). With restarts it can differ from result().angles. */
  angles(): Float64Array {
    return this.live().angles();
  }

  /** Frees the WebAssembly object. Safe to call twice. */
  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.handle.delete();
  }

  /**
   * Hands `target`'s goals to the core (only when they changed since the last call), or clears
   * them for a plain target. Returns the target positions (3 per effector), checked. Reading
   * `target` may run user code (a getter, a Proxy), so the handle is asked for at each use.
   */
  private useGoals(target: Numbers | Goals): ArrayLike<number> {
    this.live();
    if (!isGoals(target)) {
      const t = checkedNumbers(target, 'target', 3 * this.rig.numEffectors);
      if (this.goals) {
        this.live().clearGoals(); // reading a Proxy may have disposed it
        this.goals = undefined;
      }
      return t;
    }
    const packed = packGoals(this.rig, target);
    this.sendGoals(packed);
    return packed.target;
  }

  /**
   * Hands `goals` to the core unless they are those it has (for the rig's current effectors),
   * through the core's goals buffer (no new object once the sizes settle: every frame of a
   * tracked avatar turns its goals).
   */
  private sendGoals(goals: PackedGoals): void {
    const last = this.goals,
      effectors = this.rig.effectorsVersion;
    if (
      last !== undefined &&
      last.effectors === effectors &&
      last.lengthScale === goals.lengthScale &&
      equal(last.packed, goals.packed) &&
      equal(last.poles, goals.poles) &&
      equal(last.stiffness, goals.stiffness)
    )
      return;
    this.goals = undefined;
    const live = this.live();
    const p = goals.packed.length,
      q = goals.poles.length,
      total = p + q + goals.stiffness.length;
    if (this.goalsIo.length !== total) {
      const view = live.goalsView(total);
      if (!view) throw coreError(this.rig.module, 'setGoals');
      this.goalsIo = view;
    }
    this.goalsIo.set(goals.packed, 0);
    this.goalsIo.set(goals.poles, p);
    this.goalsIo.set(goals.stiffness, p + q);
    if (!live.setGoalsIo(p, q, goals.stiffness.length, goals.lengthScale)) throw coreError(this.rig.module, 'setGoals');
    const kept = (this.sentGoals ??= {
      packed: new Float64Array(0),
      poles: new Float64Array(0),
      stiffness: new Float64Array(0),
      lengthScale: 0,
      effectors: 0,
    });
    kept.packed = keepCopy(kept.packed, goals.packed);
    kept.poles = keepCopy(kept.poles, goals.poles);
    kept.stiffness = keepCopy(kept.stiffness, goals.stiffness);
    kept.lengthScale = goals.lengthScale;
    kept.effectors = effectors;
    this.goals = kept;
  }

  /** Has the core copy E's history into its buffer (this.history, asked anew when short); returns its length. */
  private readHistory(): number {
    const handle = this.live();
    const n = handle.historyIo();
    if (n < 0) throw coreError(this.rig.module, 'errorHistory');
    if (this.history.length < n) this.history = handle.historyView();
    return n;
  }

  /** The solve buffer for n angles, m target numbers and the result numbers (asked anew when stale or resized). */
  private buffer(n: number, m: number): Float64Array<ArrayBufferLike> {
    if (this.io.length === n + m + moduleFacts(this.rig.module).ioNames.length) return this.io;
    const view = this.live().ioView();
    if (!view) throw coreError(this.rig.module, 'solve');
    return (this.io = view);
  }

  private live(): EmbindSolver {
    if (this.disposed) throw new Error('this solver was disposed');
    if (this.rig.isDisposed) throw new Error('this rig was disposed (dispose its solvers first)');
    return this.handle;
  }
}
