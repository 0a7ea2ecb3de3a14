// Where the avatar's feet stand: planted until the body leaves them behind, then one
// foot at a time steps to where the stance puts it. With three tracked points nothing tells where
// the feet are; they stay where they stood (no sliding) while the body is within reach of them
// and the head faces their way. When the body's floor point (midway between the hips and where
// they would stand under the head: a crouch sits the hips back while the head stays over the
// feet) is more than STEP_DISTANCE of the height from where the stance would put a foot, or the
// head has turned more than STEP_TURN degrees from the feet (turning in place), or the last solve
// could not reach a tracked point from this stance and a foot is a little way from its place, the
// foot farther from its place steps over STEP_FRAMES frames: lifted on an arc, never below the
// floor it stood on, turned with the head, to its place under the tracked head (under the hips'
// drift, a turn in place walked the feet away from the head until the head was out of reach).
// The step is counted in frames, not seconds, so that a stream of inputs gives the same steps on
// any machine. No three.js, and no allocation but at a step's start and end: plain arrays,
// quaternions [x, y, z, w], rig units (y up).
import { mul, yawFrom } from '../rig/quat.js';

/** A foot's target: its bone's tip and frame (rig units; unit quaternion [x, y, z, w]). */
export interface FootPose {
  position: number[];
  orientation: number[];
}

/** A step starts when the stance puts a foot this share of the height away from where it stands... */
const STEP_DISTANCE = 0.15;
/** ...or when the head faces this many degrees away from the feet. */
const STEP_TURN = 60;
/** Frames a step takes (a third of a second at 30 frames per second). */
const STEP_FRAMES = 10;
/** The lift at the middle of a step, a share of the height. */
const STEP_LIFT = 0.04;
/**
 * When the last solve missed a tracked point (the stance left it out of reach: a turn finished
 * with the feet less than STEP_TURN behind), the foot farther from its place steps once it is
 * this share of the way to a step's distance or turn from it.
 */
const MISSED_SHARE = 0.1;

interface Foot {
  planted: FootPose;
  /** The planted foot's turn about the vertical from its rest frame (radians). */
  plantedYaw: number;
  /** The step under way: where it goes, and the frame it is on (1..STEP_FRAMES); null while planted. */
  step: { to: FootPose; frame: number } | null;
}

export class FootSteps {
  private readonly feet: Foot[];
  /** Each foot's floor offset from the hips' floor point at rest. */
  private readonly restOffsets: number[][];
  /** The hips' floor offset from the head's at rest. */
  private readonly restHipsFromHead: number[];
  private readonly restFeet: FootPose[];
  private readonly restHead: number[];
  /** turnOnFloor's answers (scratch, rewritten by each call). */
  private readonly turned = [0, 0];
  /** Each foot's target while it steps (rewritten every frame of its step). */
  private readonly stepPoses: FootPose[];

  /**
   * Feet standing at `feet` (left, right: the rest pose's tips and frames) under hips whose tip is
   * at `hips`, with the head's tip and frame `head` at rest; `height`: the avatar's height (rig units).
   */
  constructor(
    feet: FootPose[],
    hips: ArrayLike<number>,
    head: FootPose,
    private readonly height: number,
  ) {
    this.restFeet = feet.map(copyPose);
    this.feet = feet.map((f, k) => this.standing(f, k));
    this.restOffsets = feet.map((f) => [f.position[0] - hips[0], f.position[2] - hips[2]]);
    this.restHipsFromHead = [hips[0] - head.position[0], hips[2] - head.position[2]];
    this.restHead = Array.from(head.orientation);
    this.stepPoses = feet.map(copyPose);
  }

  /** The feet stand at `feet` (left, right), planted: tracked feet, when they stop being tracked, stay there. */
  plant(feet: ReadonlyArray<{ position: ArrayLike<number>; orientation: ArrayLike<number> }>): void {
    feet.forEach((f, k) => {
      const foot = this.feet[k];
      for (let i = 0; i < 3; i++) foot.planted.position[i] = f.position[i];
      for (let i = 0; i < 4; i++) foot.planted.orientation[i] = f.orientation[i];
      foot.plantedYaw = yawFrom(f.orientation, this.restFeet[k].orientation);
      foot.step = null;
    });
  }

  /** Where foot k (0 left, 1 right) stands, or null while it steps. */
  planted(k: number): FootPose | null {
    return this.feet[k].step ? null : this.feet[k].planted;
  }

  /** Which foot (0 left, 1 right) is stepping, or -1. */
  stepping(): number {
    for (let k = 0; k < this.feet.length; k++) if (this.feet[k].step !== null) return k;
    return -1;
  }

  /**
   * The feet's targets this frame (left, right), for the head's tracked tip and frame `head` and
   * the hips' tip `hips` (the last pose's); `missed`: the last solve left a tracked point off its
   * target. A foot steps when it is far from its place under the body (the hips and the head),
   * or turned away from the head; it steps to its place under the head (where the hips stand
   * under it upright), so that the stance follows the tracked head, not the hips' drift. A
   * planted foot's target is the pose planted() gives (no new object while the feet stand).
   */
  update(
    head: { position: ArrayLike<number>; orientation: ArrayLike<number> },
    hips: ArrayLike<number>,
    missed = false,
  ): FootPose[] {
    const yaw = yawFrom(head.orientation, this.restHead);
    if (this.stepping() < 0) {
      // The body's floor point (by the hips alone, a crouch a little deeper than the crouch
      // clip's, its hips 14% of the height back, walked the feet back). [hx, hz]: the hips' place
      // under the head, from the head.
      const hipsOffset = turnOnFloor(this.restHipsFromHead, yaw, this.turned);
      const hx = hipsOffset[0],
        hz = hipsOffset[1];
      const bodyX = 0.5 * (hips[0] + head.position[0] + hx),
        bodyZ = 0.5 * (hips[2] + head.position[2] + hz);
      // The foot farther from its place steps, if either is far enough.
      let worst = -1,
        worstMiss = missed ? MISSED_SHARE : 1;
      for (let k = 0; k < this.feet.length; k++) {
        const offset = turnOnFloor(this.restOffsets[k], yaw, this.turned),
          at = this.feet[k].planted.position;
        const dx = bodyX + offset[0] - at[0],
          dz = bodyZ + offset[1] - at[2];
        const miss = Math.max(
          Math.sqrt(dx * dx + dz * dz) / (STEP_DISTANCE * this.height),
          Math.abs(angleBetween(yaw, this.feet[k].plantedYaw)) / ((STEP_TURN * Math.PI) / 180),
        );
        if (miss > worstMiss) {
          worst = k;
          worstMiss = miss;
        }
      }
      if (worst >= 0) {
        const under = [head.position[0] + hx, 0, head.position[2] + hz];
        this.feet[worst].step = { to: this.home(worst, yaw, under), frame: 0 };
      }
    }
    for (let k = 0; k < this.feet.length; k++) this.targets[k] = this.target(k);
    return this.targets;
  }

  private readonly targets: FootPose[] = [];

  /** Foot k's target this frame: where it stands, or the next frame of its step (a pose rewritten every frame). */
  private target(k: number): FootPose {
    const foot = this.feet[k];
    if (!foot.step) return foot.planted;
    foot.step.frame++;
    const u = foot.step.frame / STEP_FRAMES,
      from = foot.planted,
      to = foot.step.to,
      pose = this.stepPoses[k];
    for (let i = 0; i < 3; i++) pose.position[i] = from.position[i] + (to.position[i] - from.position[i]) * smooth(u);
    pose.position[1] += STEP_LIFT * this.height * Math.sin(Math.PI * u);
    nlerp(from.orientation, to.orientation, smooth(u), pose.orientation);
    if (foot.step.frame >= STEP_FRAMES) this.feet[k] = this.standing(to, k);
    return pose;
  }

  /** Foot k standing at `pose` (a copy). */
  private standing(pose: FootPose, k: number): Foot {
    return { planted: copyPose(pose), plantedYaw: yawFrom(pose.orientation, this.restFeet[k].orientation), step: null };
  }

  /** Where the stance puts foot k for the head's yaw `yaw` (radians) over the hips' tip `hips`: its rest offset turned with the head. */
  private home(k: number, yaw: number, hips: ArrayLike<number>): FootPose {
    const offset = turnOnFloor(this.restOffsets[k], yaw, this.turned),
      rest = this.restFeet[k];
    return {
      position: [hips[0] + offset[0], rest.position[1], hips[2] + offset[1]],
      orientation: mul(yawQuaternion(yaw), rest.orientation),
    };
  }
}

function copyPose(p: FootPose): FootPose {
  return { position: Array.from(p.position), orientation: Array.from(p.orientation) };
}

/** A floor offset [x, z] turned by `yaw` (radians, counter-clockwise seen from above) about the vertical, written into `out`. */
function turnOnFloor(offset: readonly number[], yaw: number, out: number[]): number[] {
  const c = Math.cos(yaw),
    s = Math.sin(yaw),
    x = offset[0],
    z = offset[1];
  out[0] = c * x + s * z;
  out[1] = -s * x + c * z;
  return out;
}

function angleBetween(a: number, b: number): number {
  return Math.atan2(Math.sin(a - b), Math.cos(a - b));
}

function smooth(u: number): number {
  return u * u * (3 - 2 * u);
}

function yawQuaternion(yaw: number): number[] {
  return [0, Math.sin(yaw / 2), 0, Math.cos(yaw / 2)];
}

/** The normalised blend of unit quaternions a and b at `t` (the shorter way), written into `out`. */
function nlerp(a: ArrayLike<number>, b: ArrayLike<number>, t: number, out: number[]): number[] {
  const sign = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3] < 0 ? -1 : 1;
  let n = 0;
  for (let i = 0; i < 4; i++) {
    out[i] = a[i] + (sign * b[i] - a[i]) * t;
    n += out[i] * out[i];
  }
  n = Math.sqrt(n);
  for (let i = 0; i < 4; i++) out[i] /= n;
  return out;
}
