// The live IK state of one rig: the WebAssembly rig, the pose, the targets and one solver per
// method (made on first use). No three.js and no DOM: the page and the widget both drive it.
// dispose() frees every WebAssembly object it made.
import type { IkCoreModule } from '../ik/module.js';
import { IkRig } from '../ik/rig.js';
import type { RigSpec } from '../ik/rig_spec.js';
import type { Method, MethodSolver, SolveOutcome, SolveSettings, SolverFactory } from './solver_port.js';

export class IkSession {
  /** Sessions and solvers not yet disposed, over the whole page (a leak check for tests). */
  static readonly alive = { sessions: 0, solvers: 0 };

  readonly rig: IkRig;
  /** The current pose, 3 angles per bone, degrees. Replaced (not mutated) by solves. */
  angles: Float64Array;
  /** 3 target coordinates per end effector, in effector order. */
  targets: Float64Array;
  private readonly solvers = new Map<Method, MethodSolver>();
  private stepping: MethodSolver | null = null;
  private disposed = false;

  /** Builds the rig in WebAssembly; throws (and holds nothing) if the spec is bad. */
  constructor(
    module: IkCoreModule,
    spec: RigSpec,
    private readonly makeSolver: SolverFactory,
  ) {
    this.rig = new IkRig(module, spec);
    try {
      this.angles = this.restPose();
      this.targets = this.rig.tips(this.angles);
    } catch (e) {
      this.rig.dispose();
      throw e;
    }
    IkSession.alive.sessions++;
  }

  get spec(): RigSpec {
    return this.rig.spec;
  }

  effectors(): Int32Array {
    return this.rig.effectors();
  }

  /** The rest pose (all angles 0) clamped into the limits. */
  restPose(): Float64Array {
    return this.rig.project(new Float64Array(this.rig.numAngles));
  }

  /** Current end-effector tips, 3 per effector. */
  tips(): Float64Array {
    return this.rig.tips(this.angles);
  }

  /** Every bone's pose transform (16 row-major numbers per bone) at the current pose. */
  poses(): Float64Array {
    return this.rig.poses(this.angles);
  }

  /** E at the current pose and targets. */
  objective(): number {
    return this.rig.numEffectors === 0 ? 0 : this.rig.objective(this.angles, this.targets);
  }

  /**
   * Makes `bones` the end effectors. Effectors kept keep their targets; new ones get a target
   * at their current tip, so E does not jump. Solvers are remade for the new problem size.
   */
  setEffectors(bones: readonly number[]): void {
    const before = Array.from(this.rig.effectors());
    const oldTargets = this.targets;
    this.rig.setEffectors(bones);
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
   * effectors and targets, the pose clamped into the new limits. This session is left as it is
   * (the caller disposes it).
   */
  withLimits(lower: Float64Array, upper: Float64Array): IkSession {
    const next = new IkSession(this.rig.module, { ...this.spec, lower, upper }, this.makeSolver);
    next.setEffectors(Array.from(this.effectors()));
    next.angles = next.rig.project(this.angles);
    next.targets = this.targets.slice();
    return next;
  }

  /** Back to the rest pose, targets on the rest tips. */
  reset(): void {
    this.stepping = null;
    this.angles = this.restPose();
    this.targets = this.rig.tips(this.angles);
  }

  /** One solve from the current pose; the pose becomes the solver's result. */
  solve(method: Method, settings: SolveSettings): SolveOutcome {
    const out = this.solver(method).solve(this.angles, this.targets, settings);
    this.angles = out.angles;
    return out;
  }

  /** Solves from `start` (default: the current pose) without changing the pose (for the compare table). */
  trySolve(method: Method, settings: SolveSettings, start: Float64Array = this.angles): SolveOutcome {
    return this.solver(method).solve(start, this.targets, settings);
  }

  /** Starts step mode with `method` from the current pose. */
  beginSteps(method: Method, settings: SolveSettings): SolveOutcome {
    this.stepping = this.solver(method);
    return this.stepping.start(this.angles, this.targets, settings);
  }

  /** One iteration of the step-mode solve; the pose becomes the iterate. */
  step(): SolveOutcome {
    if (!this.stepping) throw new Error('step mode was not started');
    const out = this.stepping.step();
    this.angles = out.angles;
    return out;
  }

  get steppingMethod(): Method | null {
    return this.stepping?.method ?? null;
  }

  endSteps(): void {
    this.stepping = null;
  }

  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.disposeSolvers();
    this.rig.dispose();
    IkSession.alive.sessions--;
  }

  private solver(method: Method): MethodSolver {
    let s = this.solvers.get(method);
    if (!s) {
      s = this.makeSolver(this.rig, method);
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
