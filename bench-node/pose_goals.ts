// --goals pose: every end effector's target is the full pose of its tip frame at the target angles
// A_k, its position x(A_k) and its bone frame's rotation at A_k (IkRig.tipRotations), so every
// target is reachable by construction. Success then also needs every orientation within
// ORIENTATION_TOLERANCE_DEG of its target, judged from the returned angles' forward kinematics.
// Quaternions are [x, y, z, w], 4 per end effector in the rig's effector order.
import type { Goals } from '#ik/goals.js';
import type { TargetSet } from './target_set.js';

/** What each effector's target is: its tip's position (the protocol's), or the tip frame's whole pose. */
export type GoalsKind = 'position' | 'pose';
export const goalsKinds: readonly GoalsKind[] = ['position', 'pose'];

/** Degrees: the largest orientation error of an on-target pose (the core's orientationToleranceDeg default). */
export const ORIENTATION_TOLERANCE_DEG = 0.5;

/** Effector frame rotations at some angles (degrees): 4 numbers per effector. */
export type RotationsFn = (angles: Float64Array) => Float64Array;

/**
 * Fills `set.orientations` (4 per effector per sample) with the effectors' frame rotations at the
 * set's target angles A_k; a set without target angles (reach) cannot take pose goals and throws.
 */
export function addOrientations(set: TargetSet, rotations: RotationsFn): TargetSet {
  const angles = set.targetAngles;
  if (!angles) throw new Error(`--goals pose: the ${set.experiment} experiment has no target angles`);
  const m = set.numAngles,
    q = (4 * set.numResiduals) / 3;
  const out = new Float64Array(set.count * q);
  for (let k = 0; k < set.count; k++) out.set(rotations(angles.subarray(k * m, (k + 1) * m)), k * q);
  set.orientations = out;
  return set;
}

/**
 * The Goals object a user passes to IkSolver.solve() for one sample: per effector (bone indices
 * `effectors`, in the rig's effector order) its position (3 per effector, rig units) and its
 * orientation (4 per effector, a quaternion [x, y, z, w]), weight 1.
 */
export function poseGoals(effectors: readonly number[], target: Float64Array, orientations: Float64Array): Goals {
  return {
    effectors: effectors.map((bone, e) => ({
      bone,
      position: target.subarray(3 * e, 3 * e + 3),
      orientation: orientations.subarray(4 * e, 4 * e + 4),
    })),
  };
}

/**
 * The angle in DEGREES between two rotations given as quaternions [x, y, z, w] at offset 4e of
 * `a` and `b` (any nonzero lengths): 2 atan2(|vector part of a* b|, |scalar part|).
 */
export function rotationAngleDeg(a: ArrayLike<number>, b: ArrayLike<number>, e: number): number {
  const [ax, ay, az, aw] = [a[4 * e], a[4 * e + 1], a[4 * e + 2], a[4 * e + 3]];
  const [bx, by, bz, bw] = [b[4 * e], b[4 * e + 1], b[4 * e + 2], b[4 * e + 3]];
  // conj(a) * b
  const w = aw * bw + ax * bx + ay * by + az * bz;
  const x = aw * bx - ax * bw - ay * bz + az * by;
  const y = aw * by - ay * bw - az * bx + ax * bz;
  const z = aw * bz - az * bw - ax * by + ay * bx;
  return (2 * Math.atan2(Math.hypot(x, y, z), Math.abs(w)) * 180) / Math.PI;
}

/**
 * The largest orientation error in DEGREES over the effectors: `rotations` (the pose's, e.g.
 * IkRig.tipRotations of the returned angles) against `goal` (the targets), 4 numbers per effector.
 */
export function largestRotationErrorDeg(rotations: ArrayLike<number>, goal: ArrayLike<number>): number {
  let worst = 0;
  for (let e = 0; 4 * e < goal.length; e++) worst = Math.max(worst, rotationAngleDeg(rotations, goal, e));
  return worst;
}

/**
 * The largest component of the twists that take the pose's tips onto their targets, KDL's and
 * TRAC-IK's success test (each of them within the tolerance): per effector the position's
 * difference x, y, z (rig units; `tips` and `targets`, 3 per effector) and the world rotation
 * vector, RADIANS, that turns the frame (`rotations`, quaternions [x, y, z, w], 4 per effector)
 * onto its target (`goal`, the same).
 */
export function largestTwistComponent(
  tips: ArrayLike<number>,
  targets: ArrayLike<number>,
  rotations: ArrayLike<number>,
  goal: ArrayLike<number>,
): number {
  let worst = 0;
  for (let e = 0; 4 * e < goal.length; e++) {
    for (let i = 0; i < 3; i++) worst = Math.max(worst, Math.abs(targets[3 * e + i] - tips[3 * e + i]));
    // goal * conj(rotation): the world turn from the frame onto its target, as an axis times its angle
    const [ax, ay, az, aw] = [rotations[4 * e], rotations[4 * e + 1], rotations[4 * e + 2], rotations[4 * e + 3]];
    const norm = Math.hypot(goal[4 * e], goal[4 * e + 1], goal[4 * e + 2], goal[4 * e + 3]);
    const [bx, by, bz, bw] = [
      goal[4 * e] / norm,
      goal[4 * e + 1] / norm,
      goal[4 * e + 2] / norm,
      goal[4 * e + 3] / norm,
    ];
    let w = bw * aw + bx * ax + by * ay + bz * az;
    let x = -bw * ax + bx * aw - by * az + bz * ay;
    let y = -bw * ay + by * aw - bz * ax + bx * az;
    let z = -bw * az + bz * aw - bx * ay + by * ax;
    if (w < 0) [w, x, y, z] = [-w, -x, -y, -z];
    const s = Math.hypot(x, y, z);
    const scale = s > 0 ? (2 * Math.atan2(s, w)) / s : 2;
    worst = Math.max(worst, Math.abs(x) * scale, Math.abs(y) * scale, Math.abs(z) * scale);
  }
  return worst;
}
