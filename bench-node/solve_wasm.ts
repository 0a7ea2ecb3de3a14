// Our solvers through the WebAssembly API (web/src/ik/solver.ts), as a user calls them: one
// IkSolver per (rig, method, options), solve(start, target) per target.
import type { IkCoreModule } from '#ik/module.js';
import { IkRig } from '#ik/rig.js';
import type { RigSpec } from '#ik/rig_arrays.js';
import { IkSolver, type SolverOptions } from '#ik/solver.js';
import type { Goals } from '#ik/goals.js';
import { DragGoals } from './drag_goals.js';
import { errorOf, largestChange, pinnedDeviation, tipDistance } from './evaluate.js';
import type { SolveResult } from './metrics.js';
import { largestRotationErrorDeg, largestTwistComponent, poseGoals } from './pose_goals.js';
import type { Runner, RunSettings, SolveInput } from './runner.js';
import { project } from './target_set.js';

export class WasmSolverRunner implements Runner {
  private readonly rig: IkRig;
  /** A second rig for observing poses, so the solvers' own rig is never re-posed between steps. */
  private readonly observer: IkRig;
  private readonly solver: IkSolver;
  private readonly options: SolverOptions;
  private replayer: IkSolver | undefined;
  /** Where the previous solve ended: the start of a chained (drag, reach) solve. */
  private current: Float64Array;
  private readonly buffers: [Float64Array, Float64Array];
  /** --goals pose: the effectors' bone indices (goals name them); null for position targets. */
  private readonly poseEffectors: number[] | null;
  /** Drag, reach, gestures: the page's goals (RunSettings.pageGoals); null for plain targets. */
  private readonly dragGoals: DragGoals | null;

  constructor(ik: IkCoreModule, spec: RigSpec, settings: RunSettings) {
    this.rig = new IkRig(ik, spec);
    this.observer = new IkRig(ik, spec);
    this.options = {
      gradientTolerance: settings.gradientTolerance,
      errorTolerance: settings.errorTolerance,
      tipTolerance: settings.tipTolerance,
      timeBudgetSeconds: settings.timeBudgetSeconds,
      paperMode: settings.paper,
      ...(settings.orientationToleranceDeg === undefined
        ? {}
        : { orientationToleranceDeg: settings.orientationToleranceDeg }),
      ...(settings.restarts === undefined ? {} : { restarts: settings.restarts }),
      ...(settings.maxJointMove === undefined ? {} : { maxJointMove: settings.maxJointMove }),
    };
    this.solver = new IkSolver(this.rig, settings.method, this.options);
    this.current = project(spec, new Float64Array(this.rig.numAngles));
    this.buffers = [new Float64Array(this.rig.numAngles), new Float64Array(this.rig.numAngles)];
    this.poseEffectors = settings.goals === 'pose' ? Array.from(this.rig.effectors()) : null;
    this.dragGoals =
      settings.pageGoals && !settings.paper
        ? new DragGoals(spec, Array.from(this.rig.effectors()), settings.pinFrames ?? false)
        : null;
  }

  /** What the solver aims at for `input` (from `start`): pose goals, the page's drag goals, or the plain targets. */
  private problem(input: SolveInput, start: Float64Array): Float64Array | Goals {
    const pose = this.poseEffectors !== null && input.orientations ? input.orientations : null;
    if (pose) return poseGoals(this.poseEffectors!, input.target, pose);
    if (!this.dragGoals || input.dragged < 0) return input.target;
    if (input.start) this.dragGoals.pin(this.observer.tipRotations(start), input.dragged); // a path begins
    return this.dragGoals.goals(input.target, input.dragged);
  }

  solve(input: SolveInput): SolveResult {
    const start = input.start ?? this.current;
    const pose = this.poseEffectors !== null && input.orientations ? input.orientations : null;
    let result, problem: Float64Array | Goals;
    const t0 = performance.now();
    try {
      // Into one of two buffers of our own, never the start's (the replay below reads the start):
      // no new array per solve. Pose and drag goals go in as a user passes them: a Goals object.
      problem = this.problem(input, start);
      result = this.solver.solve(start, problem, start === this.buffers[0] ? this.buffers[1] : this.buffers[0]);
    } catch {
      // The API throws for invalid input instead of returning invalid_input.
      const seconds = (performance.now() - t0) / 1000;
      return {
        E: NaN,
        tipDistance: NaN,
        iterations: 0,
        seconds,
        stopReason: 'invalid_input',
        wobbleDuring: NaN,
        wobbleAfter: NaN,
        jumpDeg: NaN,
      };
    }
    const seconds = (performance.now() - t0) / 1000;
    this.current = result.angles;
    const tips = this.observer.tips(result.angles);
    const after = pinnedDeviation(tips, input.target, input.dragged);
    const during = Number.isNaN(after) ? NaN : this.replayWobble(start, input, problem, result.iterations, after);
    // With pose goals the solver's E holds the orientation rows too: judge the pose by its own
    // forward kinematics, E of the positions and the orientation error of the frames.
    const rotations = pose ? this.observer.tipRotations(result.angles) : null;
    const judged =
      pose && rotations
        ? {
            E: errorOf(tips, input.target),
            rotErrDeg: largestRotationErrorDeg(rotations, pose),
            twistMax: largestTwistComponent(tips, input.target, rotations, pose),
          }
        : {};
    return {
      E: result.E,
      tipDistance: tipDistance(tips, input.target),
      iterations: result.iterations,
      seconds,
      stopReason: result.stopReason,
      wobbleDuring: during,
      wobbleAfter: after,
      jumpDeg: largestChange(start, result.angles, this.rig.lower, this.rig.upper),
      angles: result.angles,
      ...judged,
    };
  }

  /**
   * The largest pinned deviation over the iterates of the same solve, replayed step by step with
   * the timed solve's iteration count and no time budget (deterministic, so the same iterates).
   */
  private replayWobble(
    start: Float64Array,
    input: SolveInput,
    problem: Float64Array | Goals,
    iterations: number,
    after: number,
  ): number {
    if (iterations === 0) return after;
    this.replayer ??= new IkSolver(this.rig, this.solver.method, this.options);
    this.replayer.setOptions({ ...this.options, maxIterations: iterations, timeBudgetSeconds: 0 });
    this.replayer.start(start, problem);
    let worst = 0,
      seen = 0;
    while (this.replayer.running) {
      this.replayer.step();
      const done = this.replayer.result().iterations;
      if (done === seen) continue;
      seen = done;
      worst = Math.max(worst, pinnedDeviation(this.observer.tips(this.replayer.angles()), input.target, input.dragged));
    }
    return worst;
  }

  dispose(): void {
    this.replayer?.dispose();
    this.solver.dispose();
    this.observer.dispose();
    this.rig.dispose();
  }
}
