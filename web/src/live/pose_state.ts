// A copy of everything a user edits on a live session: the pose, the end effectors, their targets
// and goals (orientation goals, poles). Undo and redo keep these; a pose file read back becomes
// one. No three.js and no DOM.
import { EffectorGoals } from './effector_goals.js';
import type { IkSession } from './session.js';

export interface PoseState {
  /** XZX angles, 3 per bone, degrees. */
  angles: Float64Array;
  /** End effectors' bone indices, in effector order. */
  effectors: Int32Array;
  /** 3 target coordinates per effector, rig units. */
  targets: Float64Array;
  /** The effectors' goals beyond positions and the poles (a private copy). */
  goals: EffectorGoals;
}

/** A copy of `session`'s pose, effectors, targets and goals. */
export function capturePose(session: IkSession): PoseState {
  return {
    angles: session.angles.slice(),
    effectors: session.effectors().slice(),
    targets: session.targets.slice(),
    goals: session.goals.clone(),
  };
}

const sameNumbers = (a: ArrayLike<number>, b: ArrayLike<number>): boolean => {
  if (a.length !== b.length) return false;
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) return false;
  return true;
};

/** Whether two states are the same edit (every number equal). */
export function samePose(a: PoseState, b: PoseState): boolean {
  const g = a.goals,
    h = b.goals;
  return (
    sameNumbers(a.angles, b.angles) &&
    sameNumbers(a.effectors, b.effectors) &&
    sameNumbers(a.targets, b.targets) &&
    sameNumbers(g.position, h.position) &&
    sameNumbers(g.orientation, h.orientation) &&
    sameNumbers(g.rotations, h.rotations) &&
    sameNumbers(g.poleBones, h.poleBones) &&
    sameNumbers(g.polePoints, h.polePoints)
  );
}

/**
 * Makes `state` the session's pose, effectors, targets and goals (copied, so `state` can be
 * restored again). The angles are clamped into the session's limits (which may have changed since).
 * Throws, changing nothing, when the state was taken on a rig with another number of bones.
 */
export function restorePose(session: IkSession, state: PoseState): void {
  if (state.angles.length !== session.angles.length)
    throw new Error(`the pose has ${state.angles.length / 3} bones, the rig ${session.angles.length / 3}`);
  session.setEffectors(Array.from(state.effectors));
  session.angles.set(session.rig.project(state.angles));
  session.targets = state.targets.slice();
  session.goals = state.goals.clone();
}

/** A state for `session` with every goal a fresh EffectorGoals would have but the given orientations (null: none). */
export function poseWithOrientations(
  angles: Float64Array,
  effectors: ArrayLike<number>,
  targets: Float64Array,
  orientations: readonly (ArrayLike<number> | null)[],
): PoseState {
  const goals = new EffectorGoals(effectors.length);
  orientations.forEach((q, k) => {
    if (q) goals.setOrientation(k, true, q);
  });
  return { angles, effectors: Int32Array.from(effectors), targets, goals };
}
