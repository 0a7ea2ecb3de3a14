// Pose write-back: the solver's bone poses become the three.js bones' local matrices, so the
// SkinnedMesh deforms. For a bone with pose T_i (rest world -> posed world, glTF scene space),
// the joint's posed world matrix is T_i * restWorld_i, and its local matrix is
// parentPosedWorld^-1 * T_i * restWorld_i = restLocal_i * restWorld_i^-1 * (T_p^-1 T_i) * restWorld_i
// (p = the rig parent), which keeps every scale of the file and works under any transform the
// page puts above the model. A writer may own every bone (the page) or only some (the avatar
// package: the bones its solves move; the fingers, toes and the rest keep what the app or an
// animation gives them). The hot path allocates nothing.
import { Matrix4, Quaternion, Vector3, type Object3D } from 'three';

import type { RigSpec } from '../ik/rig_arrays.js';
import type { GltfRigInfo } from '../rig/gltf/gltf_rig.js';
import { fromRowMajor } from './row_major.js';

const _pose = new Matrix4();
const _local = new Matrix4();
const _tip = new Vector3();

/** A bone's local state when a writer took it over. */
interface Initial {
  matrix: Matrix4;
  position: Vector3;
  quaternion: Quaternion;
  scale: Vector3;
  matrixAutoUpdate: boolean;
}

export class PoseWriter {
  /** The rig bones written, parents before their children. */
  private readonly written: number[];
  /** Per rig bone written (else undefined): restLocal_i * restWorld_i^-1, restWorld_i, restLocal_i. */
  private readonly left: Matrix4[] = [];
  private readonly right: Matrix4[] = [];
  private readonly restLocal: Matrix4[] = [];
  /** T_i^-1 of the last write, per rig bone written (a child's T_p^-1). */
  private readonly inverse: Matrix4[] = [];
  private readonly initial: Initial[] = [];
  private readonly parents: Int32Array;

  /**
   * `bones[i]` is the three.js object of rig bone i (bonesFromGltf / bonesByName); `spec` and
   * `info` come from the glTF import. `only` (rig bone indices) limits the writer to those bones
   * and must hold every written bone's rig parent; default every bone. The written bones get
   * matrixAutoUpdate = false (their local matrix is written directly; position/quaternion/scale
   * are kept in step) until dispose().
   */
  constructor(
    readonly bones: Object3D[],
    spec: RigSpec,
    private readonly info: GltfRigInfo,
    only?: ArrayLike<number>,
  ) {
    const n = spec.parents.length;
    if (bones.length !== n || info.boneNodes.length !== n)
      throw new Error(
        `PoseWriter: ${bones.length} three.js bones and ${info.boneNodes.length} glTF joints for a rig of ${n} bones`,
      );
    this.parents = spec.parents;
    this.written = parentsFirst(this.parents, only ? Array.from(only) : bones.map((_, i) => i));
    const chosen = new Set(this.written);
    for (const i of this.written) {
      const p = this.parents[i];
      if (p >= 0 && !chosen.has(p)) throw new Error(`PoseWriter: bone ${i} is written but its parent ${p} is not`);
      this.restLocal[i] = fromRowMajor(new Matrix4(), info.restLocal, 16 * i);
      this.right[i] = fromRowMajor(new Matrix4(), info.restWorld, 16 * i);
      this.left[i] = this.restLocal[i].clone().multiply(this.right[i].clone().invert());
      this.inverse[i] = new Matrix4();
      const b = bones[i];
      this.initial[i] = {
        matrix: b.matrix.clone(),
        position: b.position.clone(),
        quaternion: b.quaternion.clone(),
        scale: b.scale.clone(),
        matrixAutoUpdate: b.matrixAutoUpdate,
      };
      b.matrixAutoUpdate = false;
    }
  }

  /**
   * Writes `poses` (IkRig.poses(angles): 16 numbers per rig bone, row-major T_i) into the written
   * bones' local matrices. World matrices follow on the next updateMatrixWorld (the renderer does it).
   */
  write(poses: ArrayLike<number>): void {
    const n = this.bones.length;
    if (poses.length !== 16 * n)
      throw new Error(`PoseWriter.write: poses has ${poses.length} values, expected ${16 * n}`);
    for (const i of this.written) {
      const p = this.parents[i];
      fromRowMajor(_pose, poses, 16 * i);
      this.inverse[i].copy(_pose).invert();
      if (p >= 0) _pose.premultiply(this.inverse[p]); // T_p^-1 T_i
      _local.multiplyMatrices(this.left[i], _pose).multiply(this.right[i]);
      this.setLocal(i, _local);
    }
  }

  /** Puts every written bone back to its rest local matrix. */
  reset(): void {
    for (const i of this.written) this.setLocal(i, this.restLocal[i]);
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

  /** Gives the written bones back as they were when the writer took them: local matrix, position, quaternion, scale and matrixAutoUpdate. */
  dispose(): void {
    for (const i of this.written) {
      const b = this.bones[i],
        s = this.initial[i];
      b.matrix.copy(s.matrix);
      b.position.copy(s.position);
      b.quaternion.copy(s.quaternion);
      b.scale.copy(s.scale);
      b.matrixAutoUpdate = s.matrixAutoUpdate;
      b.matrixWorldNeedsUpdate = true;
    }
  }

  private setLocal(i: number, m: Matrix4): void {
    const bone = this.bones[i];
    bone.matrix.copy(m);
    m.decompose(bone.position, bone.quaternion, bone.scale);
    bone.matrixWorldNeedsUpdate = true;
  }
}

/** `bones` (rig bone indices) ordered by their depth in the tree (`parents`): every parent before its children. */
function parentsFirst(parents: Int32Array, bones: number[]): number[] {
  const depth = (i: number): number => {
    let d = 0;
    for (let p = parents[i]; p >= 0; p = parents[p]) d++;
    return d;
  };
  const depths = new Map(bones.map((b) => [b, depth(b)]));
  return bones.sort((a, b) => depths.get(a)! - depths.get(b)! || a - b);
}
