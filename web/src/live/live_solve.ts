// The per-frame solve the page and the widget run while targets move: from the current pose,
// bounded by the frame's iteration cap and time budget, never restarting. Its time is main-thread
// milliseconds around the call (JavaScript, the embind crossing and the WebAssembly solve).
import type { IkSession } from './session.js';
import type { SolveOutcome, SolveSettings } from './method_solver.js';

/**
 * Accepted steps every per-frame solve takes before its time budget can stop it (the solver option
 * stepsBeforeBudget): on a machine too slow for one step within the budget (a phone, a loaded
 * laptop: CPU throttled 8 times, the character's arm with pole handles took 0 steps a frame) the
 * pose still moves every frame; a step of the project's largest rig takes well under a frame.
 */
export const FRAME_STEPS_BEFORE_BUDGET = 1;

/**
 * lm's first damping of each per-frame solve outside paper mode (the solver option lmInitialMu;
 * the strict-priority steps every method takes start from it too). The core's default, 1, suits a
 * target placed far away; a drag's frame moves its target a few δ, and there the first steps of 1
 * are short. The character's right hand dragged across the chest (the browser test's path) took
 * 2.6 iterations a frame with 1 and 1.6 with 0.1; with 4 a frame, 5 frames ended off target with
 * 1 and none with 0.1, and with 3 or fewer the hand fell 145-220 δ behind with 1 while with 0.1
 * it followed. The largest joint move in a frame stayed 3.4% of the height.
 */
export const FRAME_LM_MU = 0.1;

/** What a front end solves each frame with unless told otherwise: iterations and milliseconds per frame. */
export const FRAME_DEFAULTS = { maxIterations: 50, timeBudgetMs: 3 } as const;

/**
 * Stop reasons after which the next frame goes on solving: the budget ran out, not the problem,
 * or the joints' speed bound (maxJointMove) stopped the body partway to its answer.
 */
export function budgetStop(reason: string): boolean {
  return reason === 'max_iterations' || reason === 'timeout' || reason === 'joint_speed';
}

/** How one per-frame solve went; one record is rewritten by every solve (no garbage per frame). */
export interface FrameTiming {
  /** Main-thread milliseconds of the solve. */
  ms: number;
  /** Solve again next frame (the per-frame budget stopped it). */
  again: boolean;
}

/**
 * One solve of `method` from the session's pose, which becomes the result (`outcome.angles` is
 * the session's pose array); `settings.restarts` should be 0 (a restart would jump the pose while
 * the user drags). Writes the time and whether to go on into `timing`.
 */
export function solveFrame(
  session: IkSession,
  method: string,
  settings: SolveSettings,
  timing: FrameTiming,
): SolveOutcome {
  const t0 = performance.now();
  const outcome = session.solve(method, settings);
  timing.ms = performance.now() - t0;
  timing.again = budgetStop(outcome.stopReason);
  return outcome;
}
