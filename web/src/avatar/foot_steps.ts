// Where the avatar's feet stand (issue 29): planted until the body leaves them behind, then one
// foot at a time steps to where the stance puts it. With three tracked points nothing tells where
// the feet are; they stay where they stood (no sliding) while the hips are within reach of them
// and the head faces their way. When the hips' floor point is more than STEP_DISTANCE of the
// height from where the stance would put a foot, or the head has turned more than STEP_TURN
// degrees from the feet (turning in place), the foot farther from its place steps there over
// STEP_FRAMES frames: lifted on an arc, never below the floor it stood on, turned with the body.
// The step is counted in frames, not seconds, so that a stream of inputs gives the same steps
// on any machine. No three.js: plain arrays, quaternions [x, y, z, w], rig units (y up).
import { inverse, mul, rotate } from '../rig/quat.js';

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

interface Foot {
  planted: FootPose;
  /** The step under way: where it goes, and the frame it is on (1..STEP_FRAMES); null while planted. */
  step: { to: FootPose; frame: number } | null;
}

export class FootSteps {
  private readonly feet: Foot[];
  /** Each foot's floor offset from the hips' floor point at rest, and its yaw there (radians). */
  private readonly restOffsets: number[][];
  private readonly restFeet: FootPose[];
  private readonly restHead: number[];

  /**
   * Feet standing at `feet` (left, right: the rest pose's tips and frames) under hips whose tip is
   * at `hips`, with the head's frame `head` at rest; `height`: the avatar's height (rig units).
   */
  constructor(feet: FootPose[], hips: ArrayLike<number>, head: ArrayLike<number>, private readonly height: number) {
    this.restFeet = feet.map(copyPose);
    this.feet = feet.map((f) => ({ planted: copyPose(f), step: null }));
    this.restOffsets = feet.map((f) => [f.position[0] - hips[0], f.position[2] - hips[2]]);
    this.restHead = Array.from(head);
  }

  /** The feet stand at `feet` (left, right), planted: tracked feet, when they stop being tracked, stay there. */
  plant(feet: FootPose[]): void {
    feet.forEach((f, k) => (this.feet[k] = { planted: copyPose(f), step: null }));
  }

  /** Where foot k (0 left, 1 right) stands, or null while it steps. */
  planted(k: number): FootPose | null {
    return this.feet[k].step ? null : this.feet[k].planted;
  }

  /** The feet's targets this frame (left, right), for the head's frame `head` and the hips' tip `hips` (the last pose's). */
  update(head: ArrayLike<number>, hips: ArrayLike<number>): FootPose[] {
    const yaw = yawFrom(head, this.restHead);
    const stepping = this.feet.some((f) => f.step !== null);
    if (!stepping) {
      // The foot farther from its place steps, if either is far enough.
      let worst = -1, worstMiss = 1;
      this.feet.forEach((foot, k) => {
        const home = this.home(k, yaw, hips);
        const miss = Math.max(
          Math.hypot(home.position[0] - foot.planted.position[0], home.position[2] - foot.planted.position[2]) / (STEP_DISTANCE * this.height),
          Math.abs(angleBetween(yaw, this.plantedYaw(k))) / ((STEP_TURN * Math.PI) / 180),
        );
        if (miss > worstMiss) (worst = k), (worstMiss = miss);
      });
      if (worst >= 0) this.feet[worst].step = { to: this.home(worst, yaw, hips), frame: 0 };
    }
    return this.feet.map((foot) => {
      if (!foot.step) return foot.planted;
      foot.step.frame++;
      const u = foot.step.frame / STEP_FRAMES, from = foot.planted, to = foot.step.to;
      const pose: FootPose = {
        position: from.position.map((p, i) => p + (to.position[i] - p) * smooth(u) + (i === 1 ? STEP_LIFT * this.height * Math.sin(Math.PI * u) : 0)),
        orientation: nlerp(from.orientation, to.orientation, smooth(u)),
      };
      if (foot.step.frame >= STEP_FRAMES) {
        foot.planted = copyPose(to);
        foot.step = null;
      }
      return pose;
    });
  }

  /** Where the stance puts foot k for the head's yaw `yaw` (radians) over the hips' tip `hips`: its rest offset turned with the head. */
  private home(k: number, yaw: number, hips: ArrayLike<number>): FootPose {
    const [ox, oz] = this.restOffsets[k], c = Math.cos(yaw), s = Math.sin(yaw);
    const rest = this.restFeet[k];
    return {
      position: [hips[0] + c * ox + s * oz, rest.position[1], hips[2] - s * ox + c * oz],
      orientation: mul(yawQuaternion(yaw), rest.orientation),
    };
  }

  /** Foot k's turn about the vertical from its rest frame (radians). */
  private plantedYaw(k: number): number {
    return yawFrom(this.feet[k].planted.orientation, this.restFeet[k].orientation);
  }
}

function copyPose(p: FootPose): FootPose {
  return { position: Array.from(p.position), orientation: Array.from(p.orientation) };
}

/** The turn about the vertical (radians, counter-clockwise seen from above) of the rotation that takes frame `rest` to frame `q`. */
function yawFrom(q: ArrayLike<number>, rest: ArrayLike<number>): number {
  // The rest frame's forward (z) in both, projected on the floor.
  const f = rotate(mul(q, inverse(rest)), [0, 0, 1]);
  return Math.atan2(f[0], f[2]);
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




function nlerp(a: ArrayLike<number>, b: ArrayLike<number>, t: number): number[] {
  const sign = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3] < 0 ? -1 : 1;
  const q = [0, 1, 2, 3].map((i) => a[i] + (sign * b[i] - a[i]) * t);
  const n = Math.hypot(...q);
  return q.map((x) => x / n);
}
