// Writes a solved pose into the three.js bones the avatar moves: the hips, the spine, neck and
// head, the arms and the legs (every bone from a root down to a tracked or planted one). The
// fingers, toes and any other bone keep what the app or an animation gives them. As in the page's
// write-back (web/src/three/pose_writer.ts), a bone with pose T_i (rest space -> posed space) and
// rig parent p gets the local matrix restLocal_i restWorld_i⁻¹ (T_p⁻¹ T_i) restWorld_i; the
// hips' carries the floating root's translation. It lands in position, quaternion and scale (and
// matrix, for bones that do not update their own).
import { Matrix4, Quaternion, Vector3, type Object3D } from 'three';

import type { RigSpec } from '../ik/rig_spec.js';
import type { GltfRigInfo } from '../rig/gltf_rig.js';
import { fromRowMajor } from '../three/row_major.js';

const _pose = new Matrix4();
const _local = new Matrix4();

interface RestState {
  position: Vector3;
  quaternion: Quaternion;
  scale: Vector3;
}

export class ChainWriter {
  /** The rig bones written, parents first. */
  private readonly bones: number[];
  /** restLocal_i restWorld_i⁻¹ and restWorld_i, per rig bone written (else undefined). */
  private readonly left: Matrix4[] = [];
  private readonly right: Matrix4[] = [];
  /** T_i⁻¹ of the last write, per rig bone written. */
  private readonly inverse: Matrix4[] = [];
  /** Each written bone's position, quaternion and scale when the writer was made. */
  private readonly rest: RestState[] = [];

  /** The bones `bones` (rig bone indices, parents first: AvatarSolver.movingBones) of the rig `spec`, carried by `objects`. */
  constructor(
    private readonly objects: Object3D[],
    private readonly spec: RigSpec,
    info: GltfRigInfo,
    bones: ArrayLike<number>,
  ) {
    this.bones = Array.from(bones);
    for (const b of this.bones) {
      this.right[b] = fromRowMajor(new Matrix4(), info.restWorld, 16 * b);
      this.left[b] = fromRowMajor(new Matrix4(), info.restLocal, 16 * b).multiply(this.right[b].clone().invert());
      this.inverse[b] = new Matrix4();
      const o = objects[b];
      this.rest[b] = { position: o.position.clone(), quaternion: o.quaternion.clone(), scale: o.scale.clone() };
    }
  }

  /** Writes `poses` (IkRig.poses: 16 row-major numbers per rig bone) into the bones. */
  write(poses: Float64Array): void {
    for (const b of this.bones) {
      const p = this.spec.parents[b];
      fromRowMajor(_pose, poses, 16 * b);
      this.inverse[b].copy(_pose).invert();
      if (p >= 0) _pose.premultiply(this.inverse[p]);
      _local.multiplyMatrices(this.left[b], _pose).multiply(this.right[b]);
      const o = this.objects[b];
      o.matrix.copy(_local);
      _local.decompose(o.position, o.quaternion, o.scale);
      o.matrixWorldNeedsUpdate = true;
    }
  }

  /** Puts the bones back as they were when the writer was made. */
  restore(): void {
    for (const b of this.bones) {
      const o = this.objects[b], r = this.rest[b];
      o.position.copy(r.position);
      o.quaternion.copy(r.quaternion);
      o.scale.copy(r.scale);
      o.updateMatrix();
    }
  }
}
