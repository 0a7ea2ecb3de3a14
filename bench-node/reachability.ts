// Which reach steps can be reached at all, decided before any timing by an untimed reference
// solve per step: lm with its default restarts and a 1 s budget, each step starting from the
// reference's own solution of the previous step (chained like the path). A step is reachable when
// that solve puts every tip within REACH_MARGIN of the run's tip tolerance (with --error-tolerance: E below
// REACH_MARGIN^2 errorTolerance): a step the reference meets only with more than that, on the edge of what
// the limbs reach and the pinned tips' slack allows, counts as out of reach. Drag, random and
// incremental targets are poses' tips, reachable by construction, and are never solved here.
import type { RigSpec } from '#ik/rig_arrays.js';
import { isOnTarget } from './evaluate.js';
import type { RunSettings } from './runner.js';
import { runOnPool, type WorkerPool } from './run_wasm.js';
import type { TargetSet } from './target_set.js';

/** The reference solve's method and time budget (seconds). */
export const REFERENCE_METHOD = 'lm';
export const REFERENCE_BUDGET_S = 1;
/** Share of the run's tip tolerance within which the reference must put every tip. */
export const REACH_MARGIN = 0.5;

/**
 * The reference's settings: the run's drag settings (gradientTolerance, the page's goals) with its on-target
 * test tightened by REACH_MARGIN, and lm's defaults otherwise (restarts; no joint speed bound: it
 * decides what can be reached).
 */
export function referenceSettings(drag: RunSettings): RunSettings {
  return {
    method: REFERENCE_METHOD,
    gradientTolerance: drag.gradientTolerance,
    errorTolerance: REACH_MARGIN * REACH_MARGIN * drag.errorTolerance,
    tipTolerance: REACH_MARGIN * drag.tipTolerance,
    timeBudgetSeconds: REFERENCE_BUDGET_S,
    paper: false,
    rigSize: drag.rigSize,
    pageGoals: drag.pageGoals,
    pinFrames: drag.pinFrames,
  };
}

/**
 * Solves every sample of `set` with the reference on the pool and writes set.reachable (1: the
 * reference ended on target). `rigKey` names the rig for the workers' runner cache.
 */
export async function markReachable(
  pool: WorkerPool,
  rigKey: string,
  spec: RigSpec,
  drag: RunSettings,
  set: TargetSet,
  onProgress: (solved: number) => void,
): Promise<void> {
  const settings = referenceSettings(drag);
  // No dragged effector: the reference measures no wobble, so no replay of its solves.
  const unobserved = { ...set, dragged: new Int32Array(set.count).fill(-1) };
  const results = await runOnPool(pool, rigKey, spec, settings, unobserved, onProgress);
  results.forEach((r, k) => (set.reachable[k] = isOnTarget(settings, r.E, r.tipDistance) ? 1 : 0));
}
