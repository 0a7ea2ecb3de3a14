// The live IK state of one rig: the WebAssembly rig, the pose, the targets, the goals beyond
// positions (orientation goals, effector_goals.ts) and one solver per method (made on first use).
// No three.js and no DOM: the page and the widget both drive it. dispose() frees every
// WebAssembly object it made.
import { type Goals, orientationErrorsDeg, type PackedGoals } from '../ik/goals.js';
import type { IkCoreModule } from '../ik/module.js';
import { IkRig } from '../ik/rig.js';
import type { RigSpec } from '../ik/rig_arrays.js';
import { EffectorGoals } from './effector_goals.js';
import { framesKept } from './pinned_frames.js';
import { MethodSolver, type SolveOutcome, type SolveSettings } from './method_solver.js';

export class IkSession {
  /** Sessions and solvers not yet disposed, over the whole page (a leak check for tests). */
  static readonly alive = { sessions: 0, solvers: 0 };

  readonly rig: IkRig;
  /** The current pose, 3 angles per bone, degrees. Always this array: solves and steps write into it. */
  readonly angles: Float64Array;
  /** 3 target coordinates per end effector, in effector order (a new array when the effectors change). */
  targets: Float64Array;
  /** Which effectors have position and orientation goals, and the orientations (a new object when the effectors change). */
  goals: EffectorGoals;
  /**
   * The effector that gives way first when not every target can be met (the one being dragged,
   * or last dragged: the page's selected target), or -1. The others stay pinned: strict priority.
   */
  yielding = -1;
  /**
   * Whether a drag pins the other effectors' frames (pinOrientations) as well as their places: on
   * a recognised humanoid (LiveRig sets it), where pinned_frames.ts tells which chains can keep both.
   */
  pinsFrames = false;
  private effectorList: Int32Array;
  private readonly solvers = new Map<string, MethodSolver>();
  private stepping: MethodSolver | null = null;
  private disposed = false;

  /** Builds the rig in WebAssembly; throws (and holds nothing) if the spec is bad. */
  constructor(module: IkCoreModule, spec: RigSpec) {
    this.rig = new IkRig(module, spec);
    try {
      this.angles = this.restPose();
      this.targets = this.rig.tips(this.angles);
      this.effectorList = this.rig.effectors();
      this.goals = new EffectorGoals(this.effectorList.length);
    } catch (e) {
      this.rig.dispose();
      throw e;
    }
    IkSession.alive.sessions++;
  }

  get spec(): RigSpec {
    return this.rig.spec;
  }

  /** The end effectors' bone indices, in effector order (the same array until they change: do not modify). */
  effectors(): Int32Array {
    return this.effectorList;
  }

  /** The rest pose (all angles 0) clamped into the limits (a new array). */
  restPose(): Float64Array {
    return this.rig.project(new Float64Array(this.rig.numAngles));
  }

  /** Current end-effector tips, 3 per effector: written into `out` when given (3 per effector), else a new array. */
  tips(out?: Float64Array): Float64Array {
    return this.rig.tips(this.angles, out);
  }

  /**
   * Every bone's pose transform (16 row-major numbers per bone) at the current pose: written into
   * `out` when given (16 per bone), else a new array.
   */
  poses(out?: Float64Array): Float64Array {
    return this.rig.poses(this.angles, out);
  }

  /** Each end effector's bone-frame rotation at the current pose: 4 per effector [x, y, z, w], rig coordinates (a new array). */
  tipRotations(): Float64Array {
    return this.rig.tipRotations(this.angles);
  }

  /**
   * The largest angle, DEGREES, between an effector's bone frame and its orientation goal at the
   * current pose; NaN when no effector has an orientation goal.
   */
  orientationErrorDeg(): number {
    if (!this.goals.anyOrientation) return NaN;
    let worst = 0;
    for (const e of orientationErrorsDeg(this.rig, this.angles, this.problem() as Goals)) if (e > worst) worst = e;
    return worst;
  }

  /**
   * What the solves aim at: the targets, or Goals when some effector has more or less than a
   * position goal or yields to the others (never in `paperMode`, which takes plain targets only).
   */
  problem(paperMode = false): Float64Array | Goals {
    const yielding = this.yieldingIn(paperMode);
    return this.goals.beyondPositions || yielding >= 0
      ? this.goals.goals(this.effectorList, this.targets, yielding)
      : this.targets;
  }

  /** problem(), its goals packed as the core takes them (the per-frame solve's fast path). */
  private packedProblem(paperMode: boolean): Float64Array | PackedGoals {
    const yielding = this.yieldingIn(paperMode);
    return this.goals.beyondPositions || yielding >= 0 ? this.goals.packed(this.targets, yielding) : this.targets;
  }

  private yieldingIn(paperMode: boolean): number {
    return paperMode || this.yielding >= this.effectorList.length ? -1 : this.yielding;
  }

  /**
   * Pins the orientations at the current pose (a drag of the `yielding` effector begins: on a
   * humanoid, pinsFrames, the effectors not dragged keep their frames as well as their positions
   * where their chains can keep both, pinned_frames.ts), or with `on` false unpins them (the drag
   * and its solves are over).
   */
  pinOrientations(on: boolean): void {
    if (on && this.pinsFrames)
      this.goals.pin(this.tipRotations(), framesKept(this.spec, this.effectorList, this.yielding));
    else if (this.goals.pinned) this.goals.unpin();
  }

  /** Effector k's orientation goal on at `q` ([x, y, z, w], rig coordinates; omitted: its current frame) or off. */
  setOrientationGoal(k: number, on: boolean, q?: ArrayLike<number>): void {
    if (on && !q) q = this.tipRotations().subarray(4 * k, 4 * k + 4);
    this.goals.setOrientation(k, on, q);
  }

  /** E at the current pose and targets (position goals only). */
  objective(): number {
    return this.rig.numEffectors === 0 ? 0 : this.rig.objective(this.angles, this.targets);
  }

  /**
   * Makes `bones` the end effectors. Effectors kept keep their targets; new ones get a target
   * at their current tip, so E does not jump. Solvers are remade for the new problem size.
   */
  setEffectors(bones: readonly number[]): void {
    const before = Array.from(this.effectorList);
    const oldTargets = this.targets;
    this.rig.setEffectors(bones);
    this.goals = this.goals.remapped(before, bones);
    this.effectorList = this.rig.effectors();
    const tips = this.rig.tips(this.angles);
    bones.forEach((b, k) => {
      const j = before.indexOf(b);
      if (j >= 0) tips.set(oldTargets.subarray(3 * j, 3 * j + 3), 3 * k);
    });
    this.targets = tips;
    this.disposeSolvers();
  }

  /**
   * A new session on the same skeleton with other limits (3 per bone, degrees): the same end
   * effectors, targets and goals, the pose clamped into the new limits. This session is left as it is
   * (the caller disposes it).
   */
  withLimits(lower: Float64Array, upper: Float64Array): IkSession {
    const next = new IkSession(this.rig.module, { ...this.spec, lower, upper });
    next.setEffectors(Array.from(this.effectorList));
    next.angles.set(next.rig.project(this.angles));
    next.targets = this.targets.slice();
    next.goals = this.goals.clone();
    next.pinsFrames = this.pinsFrames;
    return next;
  }

  /** Back to the rest pose, targets on the rest tips, position goals only (orientation goals cleared). */
  reset(): void {
    this.stepping = null;
    this.angles.set(this.restPose());
    this.targets = this.rig.tips(this.angles);
    this.goals = new EffectorGoals(this.effectorList.length);
  }

  /** One solve from the current pose; the pose becomes the solver's result (outcome.angles is `angles`). */
  solve(method: string, settings: SolveSettings): SolveOutcome {
    return this.solver(method).solve(this.angles, this.packedProblem(settings.paperMode), settings, this.angles);
  }

  /**
   * A move for `method`'s next solve to add where the goals leave room (IkSolver.setPreferredMove):
   * #angles numbers, degrees per angle, then a floating root's translation (rig units).
   */
  preferMove(method: string, move: ArrayLike<number>): void {
    this.solver(method).preferMove(move);
  }

  /** Solves from `start` (default: the current pose) without changing the pose (for the compare table). */
  trySolve(method: string, settings: SolveSettings, start: Float64Array = this.angles): SolveOutcome {
    return this.solver(method).solve(start, this.problem(settings.paperMode), settings);
  }

  /** Starts step mode with `method` from the current pose. */
  beginSteps(method: string, settings: SolveSettings): SolveOutcome {
    this.stepping = this.solver(method);
    return this.stepping.start(this.angles, this.problem(settings.paperMode), settings);
  }

  /** One iteration of the step-mode solve; the pose becomes the iterate. */
  step(): SolveOutcome {
    if (!this.stepping) throw new Error('step mode was not started');
    const out = this.stepping.step();
    this.angles.set(out.angles);
    return out;
  }

  get steppingMethod(): string | null {
    return this.stepping?.method ?? null;
  }

  endSteps(): void {
    this.stepping = null;
  }

  /** E before the first iteration and after each one of `method`'s last solve or step (a new array); null before its first. */
  history(method: string): Float64Array | null {
    return this.solvers.get(method)?.history() ?? null;
  }

  /**
   * history(method) written into `out` as far as it fits (no new array); returns its whole length,
   * or -1 before `method`'s first solve.
   */
  copyHistory(method: string, out: Float64Array): number {
    return this.solvers.get(method)?.copyHistory(out) ?? -1;
  }

  /** Iterations of `method`'s last solve or step-mode solve (0 before its first). */
  lastIterations(method: string): number {
    return this.solvers.get(method)?.lastIterations ?? 0;
  }

  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.disposeSolvers();
    this.rig.dispose();
    IkSession.alive.sessions--;
  }

  private solver(method: string): MethodSolver {
    let s = this.solvers.get(method);
    if (!s) {
      s = new MethodSolver(this.rig, method);
      this.solvers.set(method, s);
      IkSession.alive.solvers++;
    }
    return s;
  }

  private disposeSolvers(): void {
    this.stepping = null;
    for (const s of this.solvers.values()) {
      s.dispose();
      IkSession.alive.solvers--;
    }
    this.solvers.clear();
  }
}
