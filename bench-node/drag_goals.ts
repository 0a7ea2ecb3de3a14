// The page's goals for a step of drag, reach or gestures, as a user drags in the page and the
// widget (web/src/live/effector_goals.ts): the dragged effector yields (strict priority: it gives
// way first when not every goal can be met), and every other effector keeps its position and,
// on a recognised humanoid where its chain can keep both (web/src/live/pinned_frames.ts), the
// frame it had when the path began. Our solvers get these goals on both engines (the native tool's --page-goals); the peers
// take the positions alone.
import type { EffectorGoal, Goals } from '#ik/goals.js';
import type { RigSpec } from '#ik/rig_arrays.js';
import { framesKept } from '#live/pinned_frames.js';

export class DragGoals {
  private pins: Float64Array;
  private keep: Uint8Array;

  /** For `spec` with the end effectors `effectors` (bone indices, in effector order); `frames`: a humanoid's, which pins frames. */
  constructor(
    private readonly spec: RigSpec,
    private readonly effectors: readonly number[],
    private readonly frames: boolean,
  ) {
    this.pins = new Float64Array(4 * effectors.length);
    this.keep = new Uint8Array(effectors.length);
  }

  /** A path of `dragged` begins: the effectors' frames at its start pose (IkRig.tipRotations: 4 per effector [x, y, z, w]). */
  pin(rotations: ArrayLike<number>, dragged: number): void {
    this.pins = Float64Array.from(rotations);
    this.keep = this.frames ? framesKept(this.spec, this.effectors, dragged) : new Uint8Array(this.effectors.length);
  }

  /** The goals of a step towards `target` (3 per effector, rig units) with effector `dragged` yielding. */
  goals(target: Float64Array, dragged: number): Goals {
    return {
      effectors: this.effectors.map((bone, k): EffectorGoal => {
        const position = target.subarray(3 * k, 3 * k + 3);
        if (k === dragged) return { bone, position, yields: true };
        return this.keep[k]
          ? { bone, position, orientation: this.pins.subarray(4 * k, 4 * k + 4) }
          : { bone, position };
      }),
    };
  }
}

/**
 * The native tool's --page-goals value: per dragged effector d (in effector order) a row of one
 * digit per effector, 1 where it keeps its frame (framesKept; `frames` false: none), rows joined
 * by commas.
 */
export function pinnedFramesArgument(spec: RigSpec, effectors: ArrayLike<number>, frames: boolean): string {
  return Array.from(effectors, (_, d) =>
    (frames ? framesKept(spec, effectors, d) : new Uint8Array(effectors.length)).join(''),
  ).join(',');
}
