// A glTF's animation clips, played by three.js (AnimationMixer, at each clip's own rate) on a
// faint copy of the model standing beside the avatar, the ghost; and the tracked points of each
// frame it shows: the head's and hands' positions and bone frames in rig coordinates (the ghost's
// offset taken off), formed as the track experiment forms them (bench-node/track.ts): a bone's
// motion from rest G = W(t) W(rest)^-1, its point G p(rest), its frame rot(G) q(rest).
import { type AnimationAction, AnimationMixer, type Bone, Group, Matrix4, Quaternion, Vector3 } from 'three';
import { type GLTF, GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { MeshoptDecoder } from 'three/addons/libs/meshopt_decoder.module.js';

import { errorText } from '../live/error_text.js';
import type { RigSource } from '../view/rig_source.js';
import { parseGltfContainer } from '../rig/gltf/gltf_file.js';
import { bonesFromGltf } from '../view/find_bones.js';
import { fromRowMajor } from '../view/row_major.js';
import { disposeObject3D } from '../view/dispose_three.js';
import { makeFaint } from '../view/faint_model.js';
import { TRACKED_KEYS, type TrackedPoints } from './tracked_points.js';

/** The ghost's opacity. */
const GHOST_OPACITY = 0.3;

const inverseRoot = new Matrix4();
const motion = new Matrix4();
const v = new Vector3();
const unusedScale = new Vector3();
const rotation = new Quaternion();
const rest = new Quaternion();

/** The names of `source`'s animation clips in file order, as three.js names them ("animation_2" for an unnamed one); none for a rig that is no glTF. */
export function clipNames(source: RigSource): string[] {
  const gltf = source.gltf;
  if (!gltf) return [];
  const animations = parseGltfContainer(gltf.bytes, gltf.fileName).json.animations;
  if (!Array.isArray(animations)) return [];
  return animations.map((a: { name?: unknown }, i) => (typeof a?.name === 'string' ? a.name : `animation_${i}`));
}

export class ClipPlayer {
  /** The ghost: the model's copy, moved sideways by the offset given to load(). Shown while a clip plays. */
  readonly root = new Group();
  private readonly mixer: AnimationMixer;
  private action: AnimationAction | null = null;
  private current: number | null = null;

  private constructor(
    private readonly model: GLTF,
    /** The ghost's head and hand bones (tracked point order). */
    private readonly bones: Bone[],
    /** Per tracked point, the inverse of its bone's rest world matrix (rig coordinates). */
    private readonly restInverse: Matrix4[],
    /** Per tracked point, its bone's tip in the bone's node coordinates (for ghostTips). */
    private readonly tails: Vector3[],
    /** The tracked points at rest, where G(t) moves them from. */
    private readonly standing: TrackedPoints,
  ) {
    this.root.add(model.scene);
    this.root.visible = false;
    makeFaint(model.scene, GHOST_OPACITY);
    this.mixer = new AnimationMixer(model.scene);
  }

  /**
   * The clips of `source`'s glTF on a ghost moved by `offset` (rig units), for the tracked bones
   * `bones` (the whole rig's indices of the head and hands) whose points at rest are `standing`.
   * Rejects with an Error naming the file when three.js cannot load it (a .gltf with side files).
   */
  static async load(
    source: RigSource,
    bones: ArrayLike<number>,
    standing: TrackedPoints,
    offset: Vector3,
  ): Promise<ClipPlayer> {
    const gltf = source.gltf;
    if (!gltf) throw new Error(`${source.name} is no glTF file: it has no clips`);
    const bytes = gltf.bytes;
    const data = gltf.fileName.toLowerCase().endsWith('.gltf')
      ? new TextDecoder().decode(bytes)
      : (bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer);
    const model = await new GLTFLoader()
      .setMeshoptDecoder(MeshoptDecoder)
      .parseAsync(data, '')
      .catch((e: unknown) => {
        throw new Error(`${gltf.fileName}: three.js cannot load its clips: ${errorText(e)}`);
      });
    try {
      const all = bonesFromGltf(model, gltf.info);
      const tracked = TRACKED_KEYS.map((_, k) => bones[k]);
      const player = new ClipPlayer(
        model,
        tracked.map((b) => all[b]),
        tracked.map((b) => fromRowMajor(new Matrix4(), gltf.info.restWorld, 16 * b).invert()),
        tracked.map((b) => new Vector3().fromArray(gltf.info.tailLocal, 3 * b)),
        standing,
      );
      player.root.position.copy(offset);
      return player;
    } catch (e) {
      disposeObject3D(model.scene);
      throw e;
    }
  }

  /** The clip playing (an index into the file's clips), or null. */
  get playing(): number | null {
    return this.current;
  }

  /** How many clips the file has. */
  get count(): number {
    return this.model.animations.length;
  }

  /** Plays clip `index` (file order) from its start, looping, and shows the ghost. */
  play(index: number): void {
    const clip = this.model.animations[index];
    if (!clip) throw new Error(`there is no clip ${index}: the file has ${this.count}`);
    this.stop();
    this.action = this.mixer.clipAction(clip).play();
    this.current = index;
    this.root.visible = true;
    this.advance(0);
  }

  /** Stops the clip and hides the ghost. */
  stop(): void {
    this.action?.stop();
    this.action = null;
    this.current = null;
    this.root.visible = false;
  }

  /** Moves the clip on by `seconds` of its own time and poses the ghost. */
  advance(seconds: number): void {
    this.mixer.update(seconds);
    this.root.updateMatrixWorld(true);
  }

  /** Writes the head's and hands' positions and frames as the ghost shows them now into `out` (rig coordinates). */
  read(out: TrackedPoints): void {
    inverseRoot.copy(this.root.matrixWorld).invert();
    this.bones.forEach((bone, k) => {
      motion.multiplyMatrices(inverseRoot, bone.matrixWorld).multiply(this.restInverse[k]);
      v.fromArray(this.standing.positions, 3 * k).applyMatrix4(motion);
      out.setPosition(k, v.x, v.y, v.z);
      motion.decompose(v, rotation, unusedScale);
      rotation.multiply(rest.fromArray(this.standing.rotations, 4 * k));
      out.setRotation(k, rotation.x, rotation.y, rotation.z, rotation.w);
    });
  }

  /** The ghost's head and hand tips as its bones are drawn, offset taken off: 3 per point (rig units), a new array. */
  ghostTips(): Float64Array {
    inverseRoot.copy(this.root.matrixWorld).invert();
    const out = new Float64Array(3 * this.bones.length);
    this.bones.forEach((bone, k) =>
      v
        .copy(this.tails[k])
        .applyMatrix4(bone.matrixWorld)
        .applyMatrix4(inverseRoot)
        .toArray(out, 3 * k),
    );
    return out;
  }

  dispose(): void {
    this.stop();
    this.mixer.uncacheRoot(this.model.scene);
    disposeObject3D(this.root);
  }
}
