// Pose write-back: the solver's bone poses become each three.js bone's local matrix, so the
// SkinnedMesh deforms. For a bone with pose T_i (rest world -> posed world, glTF scene space),
// the joint's posed world matrix is T_i * restWorld_i, and its local matrix is
// parentPosedWorld^-1 * T_i * restWorld_i = restLocal_i * restWorld_i^-1 * (T_p^-1 T_i) * restWorld_i
// (p = the rig parent), which keeps every scale of the file and works under any transform the
// page puts above the model. The hot path allocates nothing.
import { Matrix4, Vector3, type Object3D } from 'three';

import type { RigSpec } from '../ik/rig_spec.js';
import type { GltfRigInfo } from '../rig/gltf_rig.js';
import { fromRowMajor } from './row_major.js';

const _parentInv = new Matrix4();
const _pose = new Matrix4();
const _local = new Matrix4();
const _tip = new Vector3();

export class PoseWriter {
  /** restLocal_i * restWorld_i^-1 per bone. */
  private readonly left: Matrix4[];
  /** restWorld_i per bone. */
  private readonly right: Matrix4[];
  private readonly restLocal: Matrix4[];
  private readonly autoUpdate: boolean[];
  private readonly parents: Int32Array;

  /**
   * `bones[i]` is the three.js object of rig bone i (bonesFromGltf / bonesByName); `spec` and
   * `info` come from the glTF import. The bones get matrixAutoUpdate = false (their local matrix
   * is written directly; position/quaternion/scale are kept in step) until dispose().
   */
  constructor(
    readonly bones: Object3D[],
    spec: RigSpec,
    private readonly info: GltfRigInfo,
  ) {
    const n = spec.parents.length;
    if (bones.length !== n || info.boneNodes.length !== n)
      throw new Error(`PoseWriter: ${bones.length} three.js bones and ${info.boneNodes.length} glTF joints for a rig of ${n} bones`);
    this.parents = spec.parents;
    this.restLocal = bones.map((_, i) => fromRowMajor(new Matrix4(), info.restLocal, 16 * i));
    this.right = bones.map((_, i) => fromRowMajor(new Matrix4(), info.restWorld, 16 * i));
    this.left = bones.map((_, i) => this.restLocal[i].clone().multiply(this.right[i].clone().invert()));
    this.autoUpdate = bones.map((b) => b.matrixAutoUpdate);
    bones.forEach((b) => (b.matrixAutoUpdate = false));
  }

  /**
   * Writes `poses` (IkRig.poses(angles): 16 numbers per bone, row-major T_i) into the bones' local
   * matrices. World matrices follow on the next updateMatrixWorld (the renderer does it).
   */
  write(poses: ArrayLike<number>): void {
    const n = this.bones.length;
    if (poses.length !== 16 * n) throw new Error(`PoseWriter.write: poses has ${poses.length} values, expected ${16 * n}`);
    for (let i = 0; i < n; i++) {
      const p = this.parents[i];
      fromRowMajor(_pose, poses, 16 * i);
      if (p >= 0) _pose.premultiply(fromRowMajor(_parentInv, poses, 16 * p).invert()); // T_p^-1 T_i
      _local.multiplyMatrices(this.left[i], _pose).multiply(this.right[i]);
      this.setLocal(i, _local);
    }
  }

  /** Puts every bone back to its rest local matrix. */
  reset(): void {
    this.restLocal.forEach((m, i) => this.setLocal(i, m));
  }

  /**
   * Every bone's tip from the three.js side: bone.matrixWorld * tailLocal, into `out` (3 per bone),
   * in the space of the bones' world matrices (glTF scene space when the model is not moved).
   * Call updateMatrixWorld first.
   */
  tips(out: Float64Array = new Float64Array(3 * this.bones.length)): Float64Array {
    const t = this.info.tailLocal;
    this.bones.forEach((bone, i) => {
      _tip.set(t[3 * i], t[3 * i + 1], t[3 * i + 2]).applyMatrix4(bone.matrixWorld);
      out[3 * i] = _tip.x;
      out[3 * i + 1] = _tip.y;
      out[3 * i + 2] = _tip.z;
    });
    return out;
  }

  /** Restores the rest pose and the bones' matrixAutoUpdate flags. */
  dispose(): void {
    this.reset();
    this.bones.forEach((b, i) => (b.matrixAutoUpdate = this.autoUpdate[i]));
  }

  private setLocal(i: number, m: Matrix4): void {
    const bone = this.bones[i];
    bone.matrix.copy(m);
    m.decompose(bone.position, bone.quaternion, bone.scale);
    bone.matrixWorldNeedsUpdate = true;
  }
}
