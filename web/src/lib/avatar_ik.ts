// AvatarIK: a three.js character driven by three tracked points, its head and hands (a headset
// and two controllers, or gizmos), through the project's avatar solver in WebAssembly
// (web/src/avatar/avatar_solver.ts): the hips move, the feet stay planted, the spine, arms and legs
// bend within anatomical limits.
//
//   const avatar = await AvatarIK.attach(gltf);       // or gltf.scene, or a SkinnedMesh
//   avatar.leftHand.position.set(0.3, 1.2, 0.4);       // world space; head and rightHand alike
//   avatar.update();                                   // every frame: solves, poses the bones
//   avatar.dispose();
import { Matrix4, Object3D, Quaternion, Vector3 } from 'three';

import { AvatarSolver, type AvatarInput } from '../avatar/avatar_solver.js';
import type { HumanoidRole } from '../rig/humanoid/humanoid_roles.js';
import type { AvatarSource } from './avatar_source.js';
import { packageCore } from './package_core.js';
import { PoseWriter } from '../view/pose_writer.js';
import { skeletonRig, type SkeletonRig } from './skeleton_rig.js';
import { TrackedBone } from './tracked_bone.js';

/** The bones AvatarIK drives and reports: the tracked ones, the planted feet and the hips. */
export type AvatarBone = 'hips' | 'head' | 'leftHand' | 'rightHand' | 'leftFoot' | 'rightFoot';

/** The tracked bones, in the solver's order. */
const TRACKED = ['head', 'leftHand', 'rightHand'] as const;

// web/src/rig/humanoid/humanoid_roles.ts's HumanoidSource, spelled out so that the package's types stand
// alone; assigning the project's to it fails the type check when the project's gains a source.
/** How a humanoid was recognised: a VRM extension (1.0, 0.x) or a naming convention. */
export type HumanoidSource = 'vrm1' | 'vrm0' | 'mixamo' | 'unreal' | 'rigify' | 'biped' | 'generic';

const _spaceInverse = new Matrix4();
const _m = new Matrix4();
const _p = new Vector3();
const _q = new Quaternion();
const _s = new Vector3();

export class AvatarIK {
  /**
   * Where the head bone should be and how it should turn: this object's world position and world
   * quaternion (the head bone's joint and its world rotation as three.js has it). It starts at the
   * head bone's pose at attach time. Move it, or put in its place any Object3D, such as an XR
   * camera rig's child; it need not be in the scene.
   */
  head: Object3D;
  /** The left hand's target, as `head`: where the wrist joint should be and how the hand bone turns. */
  leftHand: Object3D;
  /** The right hand's target, as `leftHand`. */
  rightHand: Object3D;
  /** The three.js bones moved and reported: hips, head, hands, feet. */
  readonly bones: Readonly<Record<AvatarBone, Object3D>>;
  /** The character's standing height at attach time, world units (the vertical extent of its bones). */
  readonly height: number;
  /** How the humanoid was recognised: the VRM extension (vrm1, vrm0) or the bone names' convention. */
  readonly humanoid: HumanoidSource;

  private readonly solver: AvatarSolver;
  private readonly tracked: TrackedBone[];
  private readonly writer: PoseWriter;
  /** The object whose local coordinates the rig lives in; it may move (the targets stay in world space). */
  private readonly space: Object3D;
  private readonly input = {} as AvatarInput;
  /** The bones' poses written each frame (16 per bone; no new array per frame). */
  private readonly poses: Float64Array;
  private disposed = false;

  private constructor(solver: AvatarSolver, rig: SkeletonRig) {
    this.solver = solver;
    this.poses = new Float64Array(16 * solver.rig.numBones);
    this.space = rig.space;
    const bone = (role: HumanoidRole): Object3D => rig.objects[rig.humanoid.bones[role]!];
    this.bones = {
      hips: bone('hips'),
      head: bone('head'),
      leftHand: bone('leftHand'),
      rightHand: bone('rightHand'),
      leftFoot: bone('leftFoot'),
      rightFoot: bone('rightFoot'),
    };
    this.tracked = TRACKED.map((role) => new TrackedBone(rig.spec, rig.info, rig.humanoid.bones[role]!));
    this.writer = new PoseWriter(rig.objects, rig.spec, rig.info, solver.movingBones);
    this.height = solver.height * this.space.matrixWorld.getMaxScaleOnAxis();
    this.humanoid = rig.humanoid.source;
    [this.head, this.leftHand, this.rightHand] = TRACKED.map((role) => {
      const target = new Object3D();
      target.name = `${role} target`;
      this.bones[role].matrixWorld.decompose(target.position, target.quaternion, _s);
      return target;
    });
  }

  /**
   * Attaches to a loaded character standing in its rest pose: `source` is what GLTFLoader gives
   * (`gltf`: its VRM humanoid is read too), or `gltf.scene`, or any three.js object holding a
   * SkinnedMesh. Its skeleton must be a humanoid with a head, two hands and two feet (VRM, Mixamo,
   * Unreal, Rigify, 3ds Max Biped or plain bone names). The first call loads the WebAssembly.
   * Resolves to the avatar, its targets at the bones' current poses; rejects with an Error naming
   * the problem (no SkinnedMesh, no humanoid and the roles missing, the WebAssembly not loaded).
   */
  static async attach(source: AvatarSource): Promise<AvatarIK> {
    const rig = await skeletonRig(source);
    const core = await packageCore();
    let solver: AvatarSolver;
    try {
      solver = new AvatarSolver(core, rig.spec, rig.humanoid);
    } catch (e) {
      throw new Error(`AvatarIK.attach: ${(e as Error).message}`, { cause: e });
    }
    return new AvatarIK(solver, rig);
  }

  /**
   * Solves one frame from the last pose towards the targets' current world poses and writes the
   * result into the bones (quaternions; the hips' position too). Call it once per frame, before
   * rendering. Returns true when the head and hands are on their targets (within 0.1% of the
   * height and 0.5 degrees) with the feet planted; false when a target is out of reach (the body
   * then comes as close as it can) or the solve continues on the next frames.
   */
  update(): boolean {
    if (this.disposed) throw new Error('AvatarIK.update: the avatar was disposed');
    this.space.updateWorldMatrix(true, false);
    _spaceInverse.copy(this.space.matrixWorld).invert();
    for (let k = 0; k < TRACKED.length; k++) {
      const target = this[TRACKED[k]];
      target.updateWorldMatrix(true, false);
      _m.multiplyMatrices(_spaceInverse, target.matrixWorld).decompose(_p, _q, _s);
      this.input[TRACKED[k]] = this.tracked[k].set(_p, _q);
    }
    const outcome = this.solver.update(this.input);
    this.writer.write(this.solver.rig.poses(this.solver.angles, this.poses));
    return outcome.reached;
  }

  /** Frees the WebAssembly memory and puts the bones back as attach() found them; update() then throws. Safe to call twice. */
  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.solver.dispose();
    this.writer.dispose();
  }
}
