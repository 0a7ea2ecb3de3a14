// One tracked bone (the head or a hand): a target pose for its three.js bone becomes the avatar
// solver's input. The developer gives where the bone's joint should be and how the bone should
// turn (its world quaternion, as three.js has it); the solver tracks the bone's tip and the
// rotation of its bone frame (web/src/avatar/avatar_solver.ts). For the pose T that carries the
// joint's rest matrix W = [R_w S | t_w] to [R S | p], T = [R R_wᵀ | p - R R_wᵀ t_w], so
//   tip   = p + R (R_wᵀ (restTip - t_w)),
//   frame = R (R_wᵀ R_rest),
// with R_rest the bone frame's rest rotation. Everything is in rig space.
import { Matrix4, Quaternion, Vector3 } from 'three';

import type { TrackedPose } from '../avatar/avatar_solver.js';
import type { RigSpec } from '../ik/rig_arrays.js';
import type { GltfRigInfo } from '../rig/gltf/gltf_rig.js';
import { fromRowMajor } from '../view/row_major.js';

const _m = new Matrix4();
const _t = new Vector3();
const _s = new Vector3();
const _v = new Vector3();
const _q = new Quaternion();

export class TrackedBone {
  /** The rest tip seen from the joint, in the joint's rest rotation: R_wᵀ (restTip - t_w). */
  private readonly tipOffset = new Vector3();
  /** R_wᵀ R_rest. */
  private readonly frameOffset = new Quaternion();
  private readonly position = new Float64Array(3);
  private readonly orientation = new Float64Array(4);
  /** The solver's input, rewritten by set(). */
  readonly pose: TrackedPose = { position: this.position, orientation: this.orientation };

  /** Bone `bone` of the rig `spec`, imported with `info`. */
  constructor(spec: RigSpec, info: GltfRigInfo, bone: number) {
    const unturn = new Quaternion(); // R_wᵀ; _t is t_w
    fromRowMajor(_m, info.restWorld, 16 * bone).decompose(_t, unturn, _s);
    unturn.invert();
    const rest = fromRowMajor(_m, spec.rest, 16 * bone); // the bone frame: origin t_w, x along the bone
    this.tipOffset
      .setFromMatrixColumn(rest, 0)
      .multiplyScalar(spec.lengths[bone])
      .add(_v.setFromMatrixPosition(rest))
      .sub(_t)
      .applyQuaternion(unturn);
    this.frameOffset.setFromRotationMatrix(rest).premultiply(unturn);
  }

  /** The solver's input for the joint at `position` turned by `rotation` (rig space); returns `pose`. */
  set(position: Vector3, rotation: Quaternion): TrackedPose {
    _v.copy(this.tipOffset).applyQuaternion(rotation).add(position).toArray(this.position);
    _q.multiplyQuaternions(rotation, this.frameOffset).toArray(this.orientation);
    return this.pose;
  }
}
