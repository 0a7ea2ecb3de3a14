// How far a clip's pose leaves a rig's joint limits: per bone, the angle (degrees) from its
// rotation at the frame to the nearest rotation its XZX limits allow. The track experiment reads
// a frame whose moving bones are all within the limits as reachable: the clip's own pose is a
// pose the solver may find. The root bone's rotation is its world one (it has no parent).
import { Matrix4, Quaternion, Vector3 } from 'three';

import type { RigSpec } from '#ik/rig_arrays.js';
import { fromRowMajor } from '#view/row_major.js';
import { xzxWithinLimits } from '#rig/xzx_angles.js';

const X = new Vector3(1, 0, 0),
  Z = new Vector3(0, 0, 1),
  RAD = Math.PI / 180;

/**
 * Degrees between bone `bone`'s rotation at `motion` (16 row-major numbers per bone: each bone's
 * motion from its rest pose, clip_frames.ts) and the nearest one within `spec`'s XZX limits: its
 * rotation from its parent's in its canonical frame, rest^-1 G_parent^-1 G rest. 0 when within.
 */
export function limitExcessDeg(spec: RigSpec, motion: Float64Array, bone: number): number {
  const parent = spec.parents[bone];
  const rest = fromRowMajor(new Matrix4(), spec.rest, 16 * bone);
  const above = parent < 0 ? new Matrix4() : fromRowMajor(new Matrix4(), motion, 16 * parent).invert();
  const local = rest
    .clone()
    .invert()
    .multiply(above)
    .multiply(fromRowMajor(new Matrix4(), motion, 16 * bone))
    .multiply(rest);
  const q = new Quaternion().setFromRotationMatrix(local).normalize();
  const angles = new Float64Array(3);
  xzxWithinLimits(q, spec.lower.subarray(3 * bone, 3 * bone + 3), spec.upper.subarray(3 * bone, 3 * bone + 3), angles);
  const within = new Quaternion()
    .setFromAxisAngle(X, angles[0] * RAD)
    .multiply(new Quaternion().setFromAxisAngle(Z, angles[1] * RAD))
    .multiply(new Quaternion().setFromAxisAngle(X, angles[2] * RAD));
  return q.angleTo(within) / RAD;
}
