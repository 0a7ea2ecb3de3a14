// A still body while one target is dragged on a rig without a humanoid map. The per-frame
// solve takes the least change that meets the goals, and on a rig whose root bone sits on the
// floor (a fox) a turn of the root or the spine is the cheapest way to move a paw: lifting one paw
// moved the hips and swung the tail. Here the bones that the dragged chain does not have to itself
// get a soft pull towards the pose the solve starts from (the solver options restWeight and
// restFromStart, Goals.stiffness per bone; wasm/src/rest_residual.h): the bones from the dragged
// effector up to its branch point (where the chain of another effector with a goal joins it) are
// free, every other bone on a goal's chain is held where it was. The pull is soft: a paw its own
// leg can reach moves that leg only (the pull costs nothing there), and a target beyond the leg's
// reach still brings the body along, since a solve that stalls off target drops the soft rows.
// A recognised humanoid is left as it was (its hips float and its limits shape the motion).
import type { RigSpec } from '../ik/rig_arrays.js';
import type { IkSession } from './session.js';
import type { SolveSettings } from './method_solver.js';

/**
 * The rest pull's weight (the solver option restWeight): a turn of 1 radian of a held bone weighs
 * as a tip this many reaches off its target. Any weight holds the body while the leg can reach
 * alone; 1 converges as fast as 0.1 and faster than 10 or 100 (measured on the test quadruped).
 */
export const STILL_BODY_WEIGHT = 1;

/**
 * Per bone, the stiffness (Goals.stiffness: 0 or 1) of a drag of effector `dragged` (an index into
 * `effectors`, the end effectors' bone indices in effector order): 0 for the bones on the dragged
 * effector's chain below every other effector's chain (the bones only it needs: a leg up to the
 * body), 1 for every other bone. With `dragged` out of range every bone gets 1. A new array of
 * one number per bone of `spec`.
 */
export function stillBodyStiffness(spec: RigSpec, effectors: ArrayLike<number>, dragged: number): Float64Array {
  const parents = spec.parents;
  const out = new Float64Array(parents.length).fill(1);
  if (dragged < 0 || dragged >= effectors.length) return out;
  const shared = new Uint8Array(parents.length);
  for (let k = 0; k < effectors.length; k++) {
    if (k === dragged) continue;
    for (let b = effectors[k]; b >= 0 && !shared[b]; b = parents[b]) shared[b] = 1;
  }
  for (let b = effectors[dragged]; b >= 0 && !shared[b]; b = parents[b]) out[b] = 0;
  return out;
}

/** The last stiffness made, kept while the rig, its effectors and the dragged one stay the same. */
const cache: { spec: RigSpec | null; effectors: Int32Array | null; dragged: number; stiffness: Float64Array } = {
  spec: null,
  effectors: null,
  dragged: -2,
  stiffness: new Float64Array(0),
};

/**
 * Sets up the next per-frame solve of `session` (its `yielding` effector is the one dragged, or
 * last dragged: the selected target): with `on`, no humanoid map (`humanoid` false), not in paper
 * mode and a target selected, writes `settings.restWeight` (STILL_BODY_WEIGHT) and
 * `settings.restFromStart` (true) and the session's per-bone stiffness (stillBodyStiffness);
 * otherwise clears them (restWeight 0, no stiffness), so the solve is the one without a still
 * body. Allocates only when the rig, its effectors or the dragged effector change.
 */
export function applyStillBody(session: IkSession, on: boolean, humanoid: boolean, settings: SolveSettings): void {
  const effectors = session.effectors(),
    dragged = session.yielding;
  const active = on && !humanoid && !settings.paperMode && dragged >= 0 && dragged < effectors.length;
  settings.restWeight = active ? STILL_BODY_WEIGHT : 0;
  settings.restFromStart = active;
  if (!active) {
    if (session.goals.stiffness.length) session.goals.stiffness = new Float64Array(0);
    return;
  }
  if (cache.spec !== session.spec || cache.effectors !== effectors || cache.dragged !== dragged) {
    cache.spec = session.spec;
    cache.effectors = effectors;
    cache.dragged = dragged;
    cache.stiffness = stillBodyStiffness(session.spec, effectors, dragged);
  }
  session.goals.stiffness = cache.stiffness;
}
