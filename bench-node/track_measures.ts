// The track experiment's measures of one clip (track.ts): the tracked points on target, every
// joint against the clip's, flips between frames and the planted feet's slide.
import type { AvatarInput, AvatarSolver } from '#avatar/avatar_solver.js';
import { rotationAngleDeg } from '#ik/goals.js';
import { HUMANOID_ROLES, type HumanoidMap, type HumanoidRole } from '#rig/humanoid/humanoid_roles.js';
import { transformPoint } from '#rig/mat4.js';
import type { ClipFrames } from './clip_frames.js';
import { limitExcessDeg } from './clip_limits.js';
import { flipLimbs, isFlip } from './flips.js';
import { restBase } from './reach.js';

/** The bones mpjpe_upper averages over: the spine, neck, head, shoulders and arms (HUMANOID_ROLES from spine to rightHand). */
const UPPER_ROLES: readonly HumanoidRole[] = HUMANOID_ROLES.slice(
  HUMANOID_ROLES.indexOf('spine'),
  HUMANOID_ROLES.indexOf('rightHand') + 1,
);

/** The effector index of each input in AvatarSolver.bones' order, and the inputs of 3 and 6 tracked points. */
export const EFFECTOR: Record<keyof AvatarInput, number> = {
  head: 0,
  leftHand: 1,
  rightHand: 2,
  leftFoot: 3,
  rightFoot: 4,
  hips: 5,
};
export const POINTS: Record<number, Array<keyof AvatarInput>> = {
  3: ['head', 'leftHand', 'rightHand'],
  6: ['head', 'leftHand', 'rightHand', 'hips', 'leftFoot', 'rightFoot'],
};
const FEET: Array<keyof AvatarInput> = ['leftFoot', 'rightFoot'];
/** A clip's foot that moved less than this share of the height since the last frame is planted. */
const STILL_SHARE = 1e-4;

/** A clip's bone this many degrees past the avatar's limits still counts as within them. */
const REACH_TOLERANCE_DEG = 0.05;

/** The tracked points' orientation tolerance, degrees. */
const TRACK_TOLERANCE_DEG = 0.5;

/** What the timed runs give: each frame's pose and planted feet (NaN: in the air), and its time (µs). */
export interface TimedRuns {
  numAngles: number;
  /** Frame f's angles at f * numAngles. */
  solved: Float64Array;
  /** Frame f's planted feet (left, right tips, rig units) at 6 f. */
  plantedLog: Float64Array;
  times: Float64Array;
}

/** A clip's measures over its frames: counts, and sums over the frames of the errors (shares of the height). */
export interface ClipMeasures {
  onTarget: number;
  reachable: number;
  onTargetReachable: number;
  mpjpe: number;
  mpjpeUpper: number;
  jitterRatio: number | null;
  flips: number;
  slide: number;
}

/**
 * Compares the poses of `run` with clip `clip` frame by frame (`avatar` mapped by `humanoid`): the tracked points against
 * `inputs`, every joint against the clip's, flips between frames and the planted feet's slide.
 */
export function measureClip(
  avatar: AvatarSolver,
  humanoid: HumanoidMap,
  clips: ClipFrames,
  clip: number,
  points: number,
  inputs: readonly AvatarInput[],
  run: TimedRuns,
): ClipMeasures {
  const spec = avatar.rig.spec,
    h = avatar.height,
    delta = 1e-3 * h;
  const heads = Array.from({ length: spec.parents.length }, (_, i) => restBase(spec, i));
  const upper = UPPER_ROLES.map((r) => humanoid.bones[r]).filter((b): b is number => b !== undefined);
  const limbs = flipLimbs(spec, humanoid);
  const moving = Array.from(avatar.movingBones);
  const m: ClipMeasures = {
    onTarget: 0,
    reachable: 0,
    onTargetReachable: 0,
    mpjpe: 0,
    mpjpeUpper: 0,
    jitterRatio: null,
    flips: 0,
    slide: 0,
  };
  const ours: number[][] = [],
    theirs: number[][] = [];
  let previousPoses: Float64Array | null = null;
  const slides = new FootSlides(points, h);
  for (let f = 0; f < inputs.length; f++) {
    const motion = clips.motion(clip, f),
      input = inputs[f];
    const angles = run.solved.subarray(f * run.numAngles, (f + 1) * run.numAngles);
    const truthHeads = heads.map((p, i) => transformPoint(motion.subarray(16 * i, 16 * i + 16), p));
    const tips = avatar.rig.tips(angles),
      turns = avatar.rig.tipRotations(angles),
      poses = avatar.rig.poses(angles);
    const tipAt = (k: number): number[] => [tips[3 * k], tips[3 * k + 1], tips[3 * k + 2]];
    const within = POINTS[points].every((key) => {
      const k = EFFECTOR[key],
        { position, orientation } = input[key]!;
      return (
        distance(tipAt(k), position) < delta &&
        rotationAngleDeg(turns.subarray(4 * k, 4 * k + 4), orientation) < TRACK_TOLERANCE_DEG
      );
    });
    if (within) m.onTarget++;
    if (moving.every((b) => limitExcessDeg(spec, motion, b) <= REACH_TOLERANCE_DEG)) {
      m.reachable++;
      if (within) m.onTargetReachable++;
    }
    const mine = heads.map((p, i) => transformPoint(poses.subarray(16 * i, 16 * i + 16), p));
    const error = (b: number): number => distance(mine[b], truthHeads[b]);
    m.mpjpe += mean(heads.map((_, b) => error(b))) / h;
    m.mpjpeUpper += mean(upper.map(error)) / h;
    ours.push(mine.flat());
    theirs.push(truthHeads.flat());
    if (previousPoses && isFlip(spec, limbs, previousPoses, poses)) m.flips++;
    previousPoses = poses;
    slides.frame(tipAt, input, run.plantedLog.subarray(6 * f, 6 * f + 6));
  }
  m.slide = slides.largest;
  const truthJitter = meanAcceleration(theirs);
  m.jitterRatio = truthJitter > 0 ? meanAcceleration(ours) / truthJitter : null;
  return m;
}

/**
 * The largest slide of a planted foot, as a share of height `h`. With 6 points a foot is planted
 * while the clip's stays still, and ours should not slide from where it was then; with 3, where
 * the avatar planted it (it steps when the body leaves it).
 */
class FootSlides {
  largest = 0;
  /** Per foot: the clip's tip last frame, and ours where the foot was planted (null: in the air). */
  private readonly feet = FEET.map(() => ({
    truth: null as ArrayLike<number> | null,
    planted: null as number[] | null,
  }));

  constructor(
    private readonly points: number,
    private readonly h: number,
  ) {}

  /**
   * One frame: `tipAt(k)` gives effector k's tip (rig units), `input` the tracked poses, `planted`
   * the avatar's planted feet (left and right tips; NaN: in the air).
   */
  frame(tipAt: (k: number) => number[], input: AvatarInput, planted: Float64Array): void {
    FEET.forEach((key, i) => {
      const tip = tipAt(EFFECTOR[key]),
        foot = this.feet[i];
      if (this.points === 3) {
        if (!Number.isNaN(planted[3 * i]))
          this.largest = Math.max(this.largest, distance(tip, planted.subarray(3 * i, 3 * i + 3)) / this.h);
        return;
      }
      const truth = input[key]!.position; // tracked with 6 points: the clip's foot this frame
      const still = foot.truth !== null && distance(truth, foot.truth) < STILL_SHARE * this.h;
      if (!still || foot.planted === null) foot.planted = tip;
      else this.largest = Math.max(this.largest, distance(tip, foot.planted) / this.h);
      foot.truth = truth;
    });
  }
}

function mean(xs: number[]): number {
  return xs.length === 0 ? 0 : xs.reduce((s, x) => s + x, 0) / xs.length;
}

/** The distance between two points (rig units). */
function distance(a: ArrayLike<number>, b: ArrayLike<number>): number {
  return Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

/** The mean size of the second difference of each point over the frames (rig units per frame²); 0 with fewer than 3 frames. */
function meanAcceleration(frames: number[][]): number {
  let sum = 0,
    count = 0;
  for (let f = 1; f + 1 < frames.length; f++)
    for (let i = 0; i < frames[f].length; i += 3) {
      let a2 = 0;
      for (let c = 0; c < 3; c++) a2 += (frames[f + 1][i + c] - 2 * frames[f][i + c] + frames[f - 1][i + c]) ** 2;
      sum += Math.sqrt(a2);
      count++;
    }
  return count === 0 ? 0 : sum / count;
}
