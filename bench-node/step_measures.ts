// What one step of a drag, reach or gestures path did to the body, from the step's start pose and
// its solution: the largest distance a joint moved (jumps.ts) and whether an elbow or knee flipped
// (flips.ts). The same for every engine and method: the wasm engine and the peers measure in their
// worker from the angles they return, the native engine's steps in the main thread from the
// angles its tool writes (the tool measures the joint move itself too: jump_move).
import type { IkRig } from '#ik/rig.js';
import type { RigSpec } from '#ik/rig_arrays.js';
import { isFlip, type FlipLimb } from './flips.js';
import { jointPositions, largestMove } from './jumps.js';
import type { SolveResult } from './metrics.js';
import type { TargetSet } from './target_set.js';

export interface StepMeasures {
  /** The largest distance (rig units) a bone's head or tip moved from the start pose to the solution. */
  jointMove: number;
  /** 1 when a limb flipped in the step (flips.ts), 0 when none did; NaN when the rig has no limbs. */
  flip: number;
}

export class StepMeasurer {
  private readonly fromJoints: Float64Array<ArrayBuffer>;
  private readonly toJoints: Float64Array<ArrayBuffer>;

  /** `rig`: forward kinematics of `spec` (not disposed here); `limbs`: flipLimbs of the rig. */
  constructor(
    private readonly spec: RigSpec,
    private readonly rig: IkRig,
    private readonly limbs: readonly FlipLimb[],
  ) {
    this.fromJoints = new Float64Array(6 * spec.parents.length);
    this.toJoints = new Float64Array(6 * spec.parents.length);
  }

  /** The measures of a step from angles `from` to angles `to` (degrees). */
  measure(from: ArrayLike<number>, to: ArrayLike<number>): StepMeasures {
    const a = this.rig.poses(from),
      b = this.rig.poses(to);
    const jointMove = largestMove(
      jointPositions(this.spec, a, this.fromJoints),
      jointPositions(this.spec, b, this.toJoints),
    );
    const flip = this.limbs.length === 0 ? NaN : isFlip(this.spec, this.limbs, a, b) ? 1 : 0;
    return { jointMove, flip };
  }

  /** Only whether the step from `from` to `to` flipped a limb (StepMeasures.flip). */
  flip(from: ArrayLike<number>, to: ArrayLike<number>): number {
    return this.limbs.length === 0
      ? NaN
      : isFlip(this.spec, this.limbs, this.rig.poses(from), this.rig.poses(to))
        ? 1
        : 0;
  }
}

/**
 * The native engine's steps: sets each result's flip from its start (the previous result's angles
 * for a chained step, else the set's start) and its `angles` (the solution the tool wrote), then
 * drops the angles. `results`: one per sample of `set`, in order. The joint move comes from the
 * tool itself (jump_move).
 */
export function addFlips(results: SolveResult[], set: TargetSet, measurer: StepMeasurer): void {
  const m = set.numAngles;
  let previous: Float64Array | undefined;
  results.forEach((result, k) => {
    const from = set.chained[k] && k > 0 ? previous : set.starts.subarray(k * m, (k + 1) * m);
    if (from && result.angles) result.flip = measurer.flip(from, result.angles);
    previous = result.angles;
    delete result.angles;
  });
}
