// From a headset's poses to the avatar's tracked points: the viewer (head) and the two
// controllers' grips, in an XR reference space (meters, +Y up, the viewer looking along its -Z),
// become the head's and hands' positions and bone frames in rig coordinates.
//
// The first sample with the head and both grips calibrates the mapping, with the user standing as
// the avatar stands at rest (a T-pose for the project's character) and looking ahead: the head's
// height over the floor scales to the avatar's, the way the user faces turns about +Y to the way
// the avatar faces, the head's point goes onto the avatar's head, and each device's frame is taken
// for its bone's frame as the avatar stands. Every later sample maps by that same turn, scale and
// shift (rigid), and each device's frame by its fixed offset from then on.
//
// XrTracking.input() is the single entry point: the page's XR frames (xr_session.ts, through
// xrSample()) and a recorded stream of samples drive it alike.
import { Quaternion, Vector3 } from 'three';

import type { StandingAvatar } from './avatar_driver.js';
import type { TrackedPoints } from './tracked_points.js';

/** One device's pose: a position (meters) and a unit quaternion [x, y, z, w], in the XR reference space. */
export interface XrPose {
  position: ArrayLike<number>;
  orientation: ArrayLike<number>;
}

/** One XR frame's poses; null where the device is not tracked in this frame. */
export interface XrSample {
  head: XrPose | null;
  left: XrPose | null;
  right: XrPose | null;
}

/** What xrSample() reads: the parts of WebXR's XRFrame, XRInputSource and XRPose it uses (real ones fit). */
export interface XrPoseLike {
  transform: {
    position: { x: number; y: number; z: number };
    orientation: { x: number; y: number; z: number; w: number };
  };
}
export interface XrInputSourceLike {
  handedness: string;
  gripSpace?: object;
}
export interface XrFrameLike {
  getViewerPose(space: object): XrPoseLike | null | undefined;
  getPose(space: object, base: object): XrPoseLike | null | undefined;
}

/** Head heights under this (meters) mean a reference space without a floor ('local'): the user is then taken to be ASSUMED_HEAD_HEIGHT tall. */
const MIN_FLOOR_HEAD_HEIGHT = 0.5;
const ASSUMED_HEAD_HEIGHT = 1.6;
/** Calibration needs the user looking ahead: the viewer's forward at least this much horizontal (cos 60°). */
const MIN_LEVEL_GAZE = 0.5;
const POSE_NAMES = ['head', 'left grip', 'right grip'] as const;

const UP = new Vector3(0, 1, 0);
const v = new Vector3();
const q = new Quaternion();

/**
 * The head's (viewer) and grips' poses of `frame` in `space`, as a sample; `sources` are the
 * session's input sources (a left- or right-handed one with a grip space gives that hand).
 */
export function xrSample(frame: XrFrameLike, space: object, sources: Iterable<XrInputSourceLike>): XrSample {
  const sample: XrSample = { head: poseOf(frame.getViewerPose(space)), left: null, right: null };
  for (const source of sources) {
    if (source.gripSpace && (source.handedness === 'left' || source.handedness === 'right'))
      sample[source.handedness] = poseOf(frame.getPose(source.gripSpace, space));
  }
  return sample;
}

function poseOf(pose: XrPoseLike | null | undefined): XrPose | null {
  if (!pose) return null;
  const { position: p, orientation: o } = pose.transform;
  return { position: [p.x, p.y, p.z], orientation: [o.x, o.y, o.z, o.w] };
}

export class XrTracking {
  private calibrated = false;
  /** Rig units per meter. */
  private scale = 1;
  /** XR reference space -> rig coordinates, a turn about +Y. */
  private readonly turn = new Quaternion();
  /** The XR point that maps onto the avatar's standing head (meters). */
  private readonly origin = new Vector3();
  /** Per device (head, left, right): its frame -> its bone's frame. */
  private readonly offsets = POSE_NAMES.map(() => new Quaternion());

  /** Maps onto `standing`: the avatar as it stands at rest (AvatarDriver.standing). */
  constructor(private readonly standing: StandingAvatar) {}

  /** Whether a sample has calibrated the mapping. */
  get isCalibrated(): boolean {
    return this.calibrated;
  }

  /** The next sample with the head and both grips (the user standing as the avatar does) calibrates anew. */
  recalibrate(): void {
    this.calibrated = false;
  }

  /**
   * Maps `sample` into `out`: the head and hands it tracks (a device missing from the sample
   * leaves its point in `out` as it was). Returns false, leaving `out` as it was, while not
   * calibrated: until a sample has the head and both grips with the head looking ahead. Throws an
   * Error naming the pose and field of a non-finite number or a zero quaternion.
   */
  input(sample: XrSample, out: TrackedPoints): boolean {
    const poses = [sample.head, sample.left, sample.right];
    poses.forEach((pose, k) => {
      if (pose) checkPose(pose, POSE_NAMES[k]);
    });
    if (!this.calibrated && !this.calibrate(poses)) return false;
    poses.forEach((pose, k) => {
      if (pose) this.map(pose, k, out);
    });
    return true;
  }

  /** Calibrates on `poses` (head, left, right); false when one is missing or the head looks too far up or down. */
  private calibrate(poses: (XrPose | null)[]): boolean {
    const [head, left, right] = poses;
    if (!head || !left || !right) return false;
    v.set(0, 0, -1).applyQuaternion(unitQuaternion(head.orientation, q));
    if (Math.hypot(v.x, v.z) < MIN_LEVEL_GAZE) return false;
    const s = this.standing,
      points = s.points;
    const headY = head.position[1];
    this.scale = (points.positions[1] - s.floorY) / (headY > MIN_FLOOR_HEAD_HEIGHT ? headY : ASSUMED_HEAD_HEIGHT);
    this.turn.setFromAxisAngle(UP, Math.atan2(s.forward[0], s.forward[2]) - Math.atan2(v.x, v.z));
    this.origin.fromArray(head.position);
    poses.forEach((pose, k) => {
      // offset = (turn * device)^-1 * bone, so that turn * device * offset is the bone's frame now.
      const device = unitQuaternion(pose!.orientation, q).premultiply(this.turn);
      this.offsets[k].fromArray(points.rotations, 4 * k).premultiply(device.invert());
    });
    this.calibrated = true;
    return true;
  }

  /** Writes device k's pose, mapped into rig coordinates, as tracked point k of `out`. */
  private map(pose: XrPose, k: number, out: TrackedPoints): void {
    const head = this.standing.points.positions;
    v.fromArray(pose.position).sub(this.origin).applyQuaternion(this.turn).multiplyScalar(this.scale);
    out.setPosition(k, head[0] + v.x, head[1] + v.y, head[2] + v.z);
    unitQuaternion(pose.orientation, q).premultiply(this.turn).multiply(this.offsets[k]);
    out.setRotation(k, q.x, q.y, q.z, q.w);
  }
}

/** `values` (x, y, z, w) as a unit quaternion in `out`. */
function unitQuaternion(values: ArrayLike<number>, out: Quaternion): Quaternion {
  return out.set(values[0], values[1], values[2], values[3]).normalize();
}

/** Throws an Error naming `name`'s field when `pose` has a position that is not 3 finite numbers or an orientation that is not 4 finite numbers, not all 0. */
function checkPose(pose: XrPose, name: string): void {
  const fields = [
    ['position', pose.position, 3],
    ['orientation', pose.orientation, 4],
  ] as const;
  for (const [field, values, n] of fields) {
    if (!values || values.length !== n)
      throw new Error(`XR sample: ${name} ${field} has ${values?.length ?? 'no'} values, expected ${n}`);
    for (let i = 0; i < n; i++)
      if (typeof values[i] !== 'number' || !Number.isFinite(values[i]))
        throw new Error(`XR sample: ${name} ${field}[${i}] is ${String(values[i])}, not a finite number`);
  }
  const o = pose.orientation;
  if (Math.hypot(o[0], o[1], o[2], o[3]) < 1e-9) throw new Error(`XR sample: ${name} orientation is a zero quaternion`);
}
