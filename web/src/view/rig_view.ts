// Draws a rig: one instanced "bone" shape per bone from its pose transform, a sphere per joint,
// and optionally the skinned mesh (posed by a MeshBinding). Bone colours mark end effectors and
// the selected bone. Everything made here is freed by dispose().
import {
  Box3,
  BufferGeometry,
  Color,
  Float32BufferAttribute,
  Group,
  InstancedMesh,
  Matrix4,
  MeshStandardMaterial,
  type Object3D,
  Quaternion,
  type Raycaster,
  SphereGeometry,
  Vector3,
} from 'three';

import type { RigSpec } from '../ik/rig_arrays.js';
import { fromRowMajor } from './row_major.js';

/** A skinned mesh posed from the rig's bone poses (the glTF write-back of web/src/view/). */
export interface MeshBinding {
  readonly object: Object3D;
  /** `poses`: IkRig.poses(angles), 16 row-major numbers per bone. */
  apply(poses: Float64Array): void;
  dispose(): void;
}

const BONE = new Color(0x9fb4d0);
const EFFECTOR = new Color(0xff9a3c);
const SELECTED = new Color(0xffe45c);
const GHOST = new Color(0x8fe3ff);

/** A click picks a bone whose axis its ray passes within this many CSS pixels where it hits no glyph. */
const PICK_PIXELS = 6;

// Scratch objects: the per-frame path allocates nothing of its own.
const mPose = new Matrix4();
const mRest = new Matrix4();
const mBone = new Matrix4();
const mScale = new Matrix4();
const v = new Vector3();
const v2 = new Vector3();
const onRay = new Vector3();
const ORIGIN = new Vector3();
const X_AXIS = new Vector3(1, 0, 0);

/** An elongated octahedron from (0,0,0) to (1,0,0), the classic bone glyph. */
function boneGeometry(): BufferGeometry {
  const w = 0.1,
    h = 0.18;
  const p = [
    [0, 0, 0],
    [h, w, 0],
    [h, 0, w],
    [h, -w, 0],
    [h, 0, -w],
    [1, 0, 0],
  ];
  const faces = [
    [0, 2, 1],
    [0, 3, 2],
    [0, 4, 3],
    [0, 1, 4],
    [5, 1, 2],
    [5, 2, 3],
    [5, 3, 4],
    [5, 4, 1],
  ];
  const pos: number[] = [];
  for (const f of faces) for (const i of f) pos.push(...p[i]);
  const g = new BufferGeometry();
  g.setAttribute('position', new Float32BufferAttribute(pos, 3));
  g.computeVertexNormals();
  return g;
}

export class RigView {
  readonly root = new Group();
  /** A length for sizing markers: the diagonal of the rest pose's bounding box. */
  readonly size: number;
  private readonly bones: InstancedMesh;
  private readonly joints: InstancedMesh;
  private readonly boneWorld: Float64Array; // 16 per bone, column-major (three.js), bone frame
  /**
   * Per bone, how its glyph lies in its frame: its turn from the x axis and its length. Along x by
   * the bone's length, except for a bone whose one child's head lies elsewhere (a URDF link, whose
   * x axis is its joint's axis and whose next joint sits off it): from its head to that child's.
   */
  private readonly glyphTurn: Quaternion[];
  private readonly glyphLength: Float64Array;
  private mesh: MeshBinding | null = null;
  /** What the bone colours show now (recolor() skips the work when neither changed). */
  private colored: { effectors: Int32Array | null; selected: number | null } = { effectors: null, selected: null };

  /** `ghost`: a faint copy used to show the previous iterate in step mode. */
  constructor(
    readonly spec: RigSpec,
    restPoses: Float64Array,
    private readonly ghost = false,
  ) {
    const n = spec.parents.length;
    this.boneWorld = new Float64Array(16 * n);
    const box = new Box3();
    for (let i = 0; i < n; i++) {
      this.frameOf(restPoses, i, mBone);
      box.expandByPoint(v.setFromMatrixPosition(mBone));
      box.expandByPoint(v.set(spec.lengths[i], 0, 0).applyMatrix4(mBone));
    }
    this.size = Math.max(box.getSize(v).length(), 1e-3);
    this.glyphTurn = Array.from({ length: n }, () => new Quaternion());
    this.glyphLength = Float64Array.from(spec.lengths);
    const children = new Int32Array(n),
      child = new Int32Array(n).fill(-1);
    for (let i = 0; i < n; i++) {
      const p = spec.parents[i];
      if (p < 0) continue;
      children[p]++;
      child[p] = i;
    }
    for (let i = 0; i < n; i++) {
      if (children[i] !== 1 || spec.lengths[i] <= 0) continue;
      fromRowMajor(mRest, spec.rest, 16 * i);
      fromRowMajor(mBone, spec.rest, 16 * child[i]);
      const local = v.setFromMatrixPosition(mBone).applyMatrix4(mRest.invert()); // the child's head in bone i's frame
      if (local.distanceTo(v2.set(spec.lengths[i], 0, 0)) <= 1e-6 * this.size || local.length() === 0) continue;
      this.glyphLength[i] = local.length();
      this.glyphTurn[i].setFromUnitVectors(X_AXIS, local.normalize());
    }

    const boneMat = new MeshStandardMaterial({
      color: 0xffffff,
      roughness: 0.5,
      metalness: 0.1,
      depthTest: false,
      transparent: true,
      opacity: ghost ? 0.3 : 0.92,
      depthWrite: !ghost,
    });
    this.bones = new InstancedMesh(boneGeometry(), boneMat, n);
    this.bones.name = 'bones';
    this.bones.frustumCulled = false;
    this.bones.renderOrder = ghost ? 9 : 10;
    for (let i = 0; i < n; i++) this.bones.setColorAt(i, BONE);

    const jointMat = new MeshStandardMaterial({ color: 0xe8eef7, roughness: 0.6, depthTest: false, transparent: true });
    this.joints = new InstancedMesh(new SphereGeometry(1, 12, 8), jointMat, n);
    this.joints.name = 'joints';
    this.joints.frustumCulled = false;
    this.joints.renderOrder = 11;
    this.joints.visible = !ghost;
    this.root.add(this.bones, this.joints);
    this.update(restPoses, new Int32Array(0), null);
  }

  /** Adds the skinned mesh; the view owns it from now on (disposed with the view). */
  attachMesh(binding: MeshBinding): void {
    this.mesh?.dispose();
    this.mesh = binding;
    this.root.add(binding.object);
  }

  get hasMesh(): boolean {
    return this.mesh !== null;
  }

  setMeshVisible(visible: boolean): void {
    if (this.mesh) this.mesh.object.visible = visible;
  }

  setBonesVisible(visible: boolean): void {
    this.bones.visible = visible;
    this.joints.visible = visible && !this.ghost;
  }

  /** Poses every bone (and the mesh) from `poses`, 16 row-major numbers per bone. */
  update(poses: Float64Array, effectors: Int32Array, selected: number | null): void {
    const n = this.spec.parents.length;
    const jointRadius = this.size * 0.008;
    for (let i = 0; i < n; i++) {
      this.frameOf(poses, i, mBone);
      mBone.toArray(this.boneWorld, 16 * i);
      const len = this.glyphLength[i];
      const thick = Math.min(len, this.size * 0.25);
      mScale.compose(ORIGIN, this.glyphTurn[i], v2.set(len, thick, thick));
      this.bones.setMatrixAt(i, mPose.multiplyMatrices(mBone, mScale));
      v.setFromMatrixPosition(mBone);
      this.joints.setMatrixAt(i, mPose.makeScale(jointRadius, jointRadius, jointRadius).setPosition(v));
    }
    this.bones.instanceMatrix.needsUpdate = true;
    this.joints.instanceMatrix.needsUpdate = true;
    this.bones.computeBoundingSphere();
    this.recolor(effectors, selected);
    this.mesh?.apply(poses);
  }

  /** World frame of bone i's canonical bone (T_i * rest_i) at the last update. */
  boneFrame(i: number, out: Matrix4): Matrix4 {
    return out.fromArray(this.boneWorld, 16 * i);
  }

  boneBase(i: number, out: Vector3): Vector3 {
    return out.setFromMatrixPosition(this.boneFrame(i, mBone));
  }

  boneTip(i: number, out: Vector3): Vector3 {
    return out.set(this.spec.lengths[i], 0, 0).applyMatrix4(this.boneFrame(i, mBone));
  }

  /** Where bone i's glyph ends (world, at the last update): its tip, or its one child's head (glyphTurn). */
  glyphEnd(i: number, out: Vector3): Vector3 {
    this.bones.getMatrixAt(i, mBone);
    return out.set(1, 0, 0).applyMatrix4(mBone);
  }

  /** Bounds of the bones (and mesh) at the last update. */
  bounds(): Box3 {
    const box = new Box3();
    for (let i = 0; i < this.spec.parents.length; i++) {
      box.expandByPoint(this.boneBase(i, v));
      box.expandByPoint(this.boneTip(i, v));
    }
    if (this.mesh && this.mesh.object.visible) box.expandByObject(this.mesh.object);
    return box;
  }

  /**
   * The bone under the ray, or null. Bones of length 0 cannot be picked. A ray that hits no glyph
   * picks the bone whose axis it passes within PICK_PIXELS, the nearest along the ray, given
   * `pixelSlope` (ViewClick.pixelSlope; 0: no such tolerance): a glyph tapers to a point at both
   * ends, and one seen end-on is a dot.
   */
  pick(raycaster: Raycaster, pixelSlope = 0): number | null {
    if (!this.bones.visible) return null;
    const hits = raycaster.intersectObject(this.bones, false);
    for (const h of hits) if (h.instanceId !== undefined && this.spec.lengths[h.instanceId] > 0) return h.instanceId;
    if (!(pixelSlope > 0)) return null;
    let nearest: number | null = null,
      nearestAlong = Infinity;
    for (let i = 0; i < this.spec.parents.length; i++) {
      if (!(this.spec.lengths[i] > 0)) continue;
      const d2 = raycaster.ray.distanceSqToSegment(this.boneBase(i, v), this.glyphEnd(i, v2), onRay);
      const along = onRay.distanceTo(raycaster.ray.origin);
      if (d2 <= (PICK_PIXELS * pixelSlope * along) ** 2 && along < nearestAlong) {
        nearest = i;
        nearestAlong = along;
      }
    }
    return nearest;
  }

  dispose(): void {
    this.mesh?.dispose();
    this.mesh = null;
    for (const m of [this.bones, this.joints]) {
      m.geometry.dispose();
      (m.material as MeshStandardMaterial).dispose();
      m.dispose();
    }
    this.root.removeFromParent();
    this.root.clear();
  }

  /** T_i * rest_i from the row-major pose array and the spec's rest transforms. */
  private frameOf(poses: Float64Array, i: number, out: Matrix4): Matrix4 {
    fromRowMajor(mPose, poses, 16 * i);
    fromRowMajor(mRest, this.spec.rest, 16 * i);
    return out.multiplyMatrices(mPose, mRest);
  }

  /** `effectors` is compared by identity: the session hands out the same array until the effectors change. */
  private recolor(effectors: Int32Array, selected: number | null): void {
    if (effectors === this.colored.effectors && selected === this.colored.selected) return;
    this.colored.effectors = effectors;
    this.colored.selected = selected;
    const n = this.spec.parents.length;
    for (let i = 0; i < n; i++) this.bones.setColorAt(i, this.ghost ? GHOST : BONE);
    if (this.ghost) {
      if (this.bones.instanceColor) this.bones.instanceColor.needsUpdate = true;
      return;
    }
    for (const e of effectors) this.bones.setColorAt(e, EFFECTOR);
    if (selected !== null) this.bones.setColorAt(selected, SELECTED);
    if (this.bones.instanceColor) this.bones.instanceColor.needsUpdate = true;
  }
}
