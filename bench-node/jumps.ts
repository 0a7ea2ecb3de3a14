// Jumps, measured by where the joints go: a step of a drag, reach or gestures path is a jump when
// some joint (the head or the tip of any bone) moves more than JUMP_JOINT_SHARE of the rig size
// between the step's start pose and its solution while the dragged target moved less than
// JUMP_TARGET_SHARE of it. A straight limb that starts to bend turns its middle joint by some
// degrees for a small move of the tip: its joints move about as far as the tip, so that passes.
// A pose that snaps to another branch of solutions moves an elbow or a knee far at once: a jump.
//
// Poses are IkRig.poses() (16 row-major numbers per bone: the transform T_i from bone i's rest
// frame to its posed one); a bone's head is T_i applied to its rest origin, its tip T_i applied to
// rest origin + length * rest x axis (README "Conventions": tip = T_i * rest_i * (length, 0, 0)).
import type { RigSpec } from '#ik/rig_arrays.js';
import type { TargetSet, TipsFn } from './target_set.js';

/** A joint moving more than this share of the rig size in one step may be a jump. */
export const JUMP_JOINT_SHARE = 0.05;
/** ...when the dragged target moved less than this share of the rig size. */
export const JUMP_TARGET_SHARE = 0.01;

/**
 * Every bone's head and tip at `poses` (IkRig.poses: 16 per bone), 6 numbers per bone (head x, y,
 * z, tip x, y, z; rig units), into `out` (a new array when absent).
 */
export function jointPositions(
  spec: RigSpec,
  poses: ArrayLike<number>,
  out: Float64Array = new Float64Array(6 * spec.parents.length),
): Float64Array {
  const { rest, lengths } = spec;
  for (let b = 0; b < spec.parents.length; b++) {
    const r = 16 * b,
      p = 16 * b;
    // Rest origin o and rest tip o + length * x (x: the first column of the rest rotation).
    const o = [rest[r + 3], rest[r + 7], rest[r + 11]];
    const t = [o[0] + lengths[b] * rest[r], o[1] + lengths[b] * rest[r + 4], o[2] + lengths[b] * rest[r + 8]];
    for (let row = 0; row < 3; row++) {
      const m = p + 4 * row;
      out[6 * b + row] = poses[m] * o[0] + poses[m + 1] * o[1] + poses[m + 2] * o[2] + poses[m + 3];
      out[6 * b + 3 + row] = poses[m] * t[0] + poses[m + 1] * t[1] + poses[m + 2] * t[2] + poses[m + 3];
    }
  }
  return out;
}

/** The largest distance between corresponding points of two lists of 3-vectors (rig units). */
export function largestMove(from: ArrayLike<number>, to: ArrayLike<number>): number {
  let worst = 0;
  for (let i = 0; i < from.length; i += 3)
    worst = Math.max(worst, Math.hypot(to[i] - from[i], to[i + 1] - from[i + 1], to[i + 2] - from[i + 2]));
  return worst;
}

/**
 * Per sample of a drag, reach or gestures set, how far (rig units) the dragged effector's target
 * moved in that step: from the previous sample's target of that effector for a chained step, and
 * for a path's first step from the dragged effector's tip at the step's start pose (`tips`:
 * forward kinematics, 3 numbers per effector). NaN where a sample drags nothing.
 */
export function draggedTargetMoves(set: TargetSet, tips: TipsFn): Float64Array {
  const m = set.numAngles,
    r = set.numResiduals;
  const moves = new Float64Array(set.count).fill(NaN);
  for (let k = 0; k < set.count; k++) {
    const e = set.dragged[k];
    if (e < 0) continue;
    const from =
      set.chained[k] && k > 0
        ? set.targets.subarray((k - 1) * r, k * r)
        : tips(set.starts.subarray(k * m, (k + 1) * m));
    moves[k] = largestMove(from.subarray(3 * e, 3 * e + 3), set.targets.subarray(k * r + 3 * e, k * r + 3 * e + 3));
  }
  return moves;
}

/**
 * Whether a step is a jump: some joint moved `jointMove` (rig units) > JUMP_JOINT_SHARE * `size`
 * while the dragged target moved `targetMove` < JUMP_TARGET_SHARE * `size` (`size`: the rig size,
 * rigSize). NaN for either move is no jump (nothing measured).
 */
export function isJump(jointMove: number, targetMove: number, size: number): boolean {
  return jointMove > JUMP_JOINT_SHARE * size && targetMove < JUMP_TARGET_SHARE * size;
}

/** The number of steps k with isJump(jointMoves[k], targetMoves[k], size). */
export function countJumps(jointMoves: ArrayLike<number>, targetMoves: ArrayLike<number>, size: number): number {
  let n = 0;
  for (let k = 0; k < jointMoves.length; k++) if (isJump(jointMoves[k], targetMoves[k], size)) n++;
  return n;
}
