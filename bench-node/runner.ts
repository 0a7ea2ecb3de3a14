// What every method looks like to a worker: solve one target from a start (or from where the
// previous solve ended), time it, and report the result. Implemented for our solvers
// (solve_wasm.ts) and for the peers (peers/).
import type { OnTargetTest } from './evaluate.js';
import type { SolveResult } from './metrics.js';
import type { GoalsKind } from './pose_goals.js';

export interface SolveInput {
  /** Start angles (#angles, degrees), or null to continue from the previous solve's pose (drag, reach). */
  start: Float64Array | null;
  /** Targets x_b (3 per end effector, rig units). */
  target: Float64Array;
  /** --goals pose: the effectors' target orientations (4 per effector, quaternions [x, y, z, w]); else absent. */
  orientations?: Float64Array | null;
  /** Drag, reach: the dragged effector (index into the rig's effectors); the others are pinned. -1: none. */
  dragged: number;
  /** Time budget of this call, seconds; default the settings' timeBudgetSeconds (peers/restarting.ts passes what is left). */
  budgetSeconds?: number;
}

/**
 * Settings of one method on one rig and experiment. The on-target test (errorTolerance, tipTolerance) is
 * both the solvers' stopping test and the success test; the peers stop on it too.
 */
export interface RunSettings extends OnTargetTest {
  method: string;
  gradientTolerance: number;
  timeBudgetSeconds: number;
  paper: boolean;
  /** Rig size (rig units; see rigs.ts), for peers whose settings are lengths. */
  rigSize: number;
  /**
   * Restarts from quasi-random points after a stall, for every method: ours restart inside the
   * solver (outside paper mode), the peers through the harness (peers/restarting.ts) from the same
   * points. undefined: the solvers' default; drag and reach set 0, as the page does while dragging
   * (a restart jumps the whole pose).
   */
  restarts?: number;
  /**
   * Drag, reach and gestures: the farthest a joint moves in one solve (our solvers' option
   * maxJointMove, rig units; the page's, from dragTolerances). undefined: no cap. The peers have none.
   */
  maxJointMove?: number;
  /**
   * Drag, reach and gestures: our solvers get the page's goals (drag_goals.ts: the dragged
   * effector yields, the others keep their positions and their frames from the path's start)
   * instead of plain positions. The peers take the positions alone.
   */
  pageGoals?: boolean;
  /** With pageGoals: the rig is a recognised humanoid, whose pinned effectors keep their frames too. */
  pinFrames?: boolean;
  /**
   * What the targets are (pose_goals.ts): 'pose' adds each effector's orientation (and then
   * orientationToleranceDeg is set); absent or 'position': tip positions only.
   */
  goals?: GoalsKind;
}

export interface Runner {
  /**
   * Solves once. `seconds` is performance.now() around the whole call a user would make: copying
   * the start and targets in, the solve, and copying the pose out. Never throws for a failed
   * solve: the failure is its stopReason.
   */
  solve(input: SolveInput): SolveResult;
  dispose(): void;
}
