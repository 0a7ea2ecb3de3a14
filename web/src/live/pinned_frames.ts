// Which end effectors keep their frame while another is dragged, on a recognised humanoid (its
// anatomical limits say what a joint can make up for; other rigs pin positions only). Pinned means
// pinned: an effector not being dragged keeps its position, and its orientation too unless its
// chain cannot keep both.
// The dragged target moves the bones the two chains share (a character's spine, a hand's wrist);
// the pinned effector keeps its whole pose only with enough of its own joints below them to make
// up for that: at least FRAME_ANGLES angles that each turn FRAME_RANGE_DEG or more, as many as a
// pose has degrees of freedom. A character's arm from the clavicle down has 10 such angles and
// keeps its hand's frame while the head bows; a finger below the wrist has 3, so a hand's other
// fingers keep only their tips' places while one finger is dragged and the wrist turns.
import type { RigSpec } from '../ik/rig_arrays.js';

/** Angles an effector needs below the shared bones to keep its frame (a pose has 6 degrees of freedom). */
export const FRAME_ANGLES = 6;
/** An angle counts when its range (upper - lower) is at least this, degrees. */
export const FRAME_RANGE_DEG = 30;

/** The bones from `bone` up to its root. */
function chain(spec: RigSpec, bone: number): Set<number> {
  const out = new Set<number>();
  for (let b = bone; b >= 0; b = spec.parents[b]) out.add(b);
  return out;
}

/**
 * Per end effector (bone indices `effectors`, in effector order): 1 where it keeps its frame while
 * effector `dragged` (an index into `effectors`; -1: none) is dragged, 0 where it keeps only its
 * position. The dragged effector itself gets 0.
 */
export function framesKept(spec: RigSpec, effectors: ArrayLike<number>, dragged: number): Uint8Array {
  const out = new Uint8Array(effectors.length);
  const shared = dragged >= 0 ? chain(spec, effectors[dragged]) : new Set<number>();
  for (let k = 0; k < effectors.length; k++) {
    if (k === dragged) continue;
    let angles = 0;
    for (const b of chain(spec, effectors[k])) {
      if (shared.has(b)) continue;
      for (let j = 3 * b; j < 3 * b + 3; j++) if (spec.upper[j] - spec.lower[j] >= FRAME_RANGE_DEG) angles++;
    }
    out[k] = angles >= FRAME_ANGLES ? 1 : 0;
  }
  return out;
}
