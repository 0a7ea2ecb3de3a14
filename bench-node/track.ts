// The track experiment: a humanoid glTF's animation clips drive the avatar solver
// (web/src/avatar/avatar_solver.ts) through the tracked points a headset and two controllers
// give, the head's and the hands' poses, frame by frame at the clip's own rate, each frame solved
// from the last one's result; the whole body is compared with the clip's.
//
// 3 points: the head and hands; 6: the hips and feet as well.
// Per clip, one row:
// - success: frames with the tracked points within δ (0.1% of the height) and 0.5° of the clip's;
// - reachable, success_reachable: the share of frames whose clip pose keeps every moving bone
//   within the avatar's limits (to 0.05°: the clip's pose itself is then one the solver may
//   find), and the success over those frames (clip_limits.ts);
// - mpjpe, mpjpe_upper: the mean distance of every joint (bone head), and of the spine, neck, head,
//   shoulders and arms only, from the clip's, as fractions of the height;
// - jitter_ratio: the joints' mean acceleration (second difference per frame) over the clip's own;
// - flips: frames where an elbow or knee bends against its anatomical direction or its bend plane
//   turns more than 90 degrees (flips.ts);
// - foot_slide: the farthest our foot moved from where it was planted, as a fraction of the
//   height: with 3 points where the avatar planted it (between its steps), with 6 while the clip's
//   foot stays still (moves less than 0.01% of the height a frame);
// - median_us, p99_us: the time of update() per frame, microseconds, WebAssembly in Node, after
//   every clip has run once untimed (V8's warm-up); each frame's time is its median over
//   TIMED_RUNS runs of the clip.
import v8 from 'node:v8';
import { runInNewContext } from 'node:vm';

import { Matrix4, Quaternion } from 'three';

import { AvatarSolver, type AvatarInput, type TrackedPose } from '#avatar/avatar_solver.js';
import { rotationAngleDeg } from '#ik/goals.js';
import type { IkCoreModule } from '#ik/module.js';
import type { RigSpec } from '#ik/rig_arrays.js';
import type { HumanoidMap, HumanoidRole } from '#rig/humanoid/humanoid_roles.js';
import { transformPoint } from '#rig/mat4.js';
import { fromRowMajor } from '#view/row_major.js';
import { ClipFrames } from './clip_frames.js';
import { limitExcessDeg } from './clip_limits.js';
import { BenchError } from './errors.js';
import { flipLimbs, isFlip } from './flips.js';
import { restBase } from './reach.js';

export interface TrackRow {
  rig: string;
  experiment: 'track';
  method: 'avatar';
  clip: string;
  frames: number;
  points: number;
  success_rate: number;
  reachable: number;
  success_reachable: number | null;
  mpjpe: number;
  mpjpe_upper: number;
  jitter_ratio: number | null;
  flips: number;
  foot_slide: number;
  median_us: number;
  p99_us: number;
}

/** The bones mpjpe_upper averages over. */
const UPPER_ROLES: readonly HumanoidRole[] = [
  'spine',
  'chest',
  'upperChest',
  'neck',
  'head',
  'leftShoulder',
  'leftUpperArm',
  'leftLowerArm',
  'leftHand',
  'rightShoulder',
  'rightUpperArm',
  'rightLowerArm',
  'rightHand',
];

/** The effector index of each input in AvatarSolver.bones' order, and the inputs of 3 and 6 tracked points. */
const EFFECTOR: Record<keyof AvatarInput, number> = {
  head: 0,
  leftHand: 1,
  rightHand: 2,
  leftFoot: 3,
  rightFoot: 4,
  hips: 5,
};
const POINTS: Record<number, Array<keyof AvatarInput>> = {
  3: ['head', 'leftHand', 'rightHand'],
  6: ['head', 'leftHand', 'rightHand', 'hips', 'leftFoot', 'rightFoot'],
};
const FEET: Array<keyof AvatarInput> = ['leftFoot', 'rightFoot'];
/** Timed runs of each clip (median_us and p99_us take each frame's median over them). */
const TIMED_RUNS = 3;

/** A clip's foot that moved less than this share of the height since the last frame is planted. */
const STILL_SHARE = 1e-4;

/** A clip's bone this many degrees past the avatar's limits still counts as within them. */
const REACH_TOLERANCE_DEG = 0.05;

/** The tracked points' orientation tolerance, degrees. */
const TRACK_TOLERANCE_DEG = 0.5;

export interface TrackRig {
  name: string;
  path: string;
  spec: RigSpec;
  humanoid: HumanoidMap;
  boneNodes: Int32Array;
}

/**
 * Runs the clips named in `clips` ('all': every one) of `rig`'s file through the avatar solver with
 * `points` tracked points (3: head and hands); one row per clip. Throws BenchError naming a clip
 * the file lacks, or a file without clips.
 */
export async function runTrack(
  ik: IkCoreModule,
  rig: TrackRig,
  clips: string[] | 'all',
  points: number,
): Promise<TrackRow[]> {
  const frames = await ClipFrames.read(rig.path, rig.boneNodes);
  const names = frames.clips.map((c) => c.name);
  if (names.length === 0) throw new BenchError(`track: ${rig.name} has no animation clips`, 2);
  const chosen =
    clips === 'all'
      ? names.map((_, i) => i)
      : clips.map((name) => {
          const i = names.indexOf(name);
          if (i < 0) throw new BenchError(`track: ${rig.name} has no clip "${name}" (it has: ${names.join(', ')})`, 2);
          return i;
        });
  // Warm-up (warm_up.ts): every clip once, untimed, so that V8 has optimised the avatar's
  // JavaScript and WebAssembly on each of its paths (steps, poles, given-up goals) before any
  // frame is timed. Cold, the first clip's median read 2x; warmed on the first clip alone, a
  // later clip's first steps cost 4-7 ms a frame (its p99).
  for (const clip of chosen) trackClip(ik, rig, frames, clip, points);
  return chosen.map((clip) => trackClip(ik, rig, frames, clip, points));
}

function trackClip(ik: IkCoreModule, rig: TrackRig, clips: ClipFrames, clip: number, points: number): TrackRow {
  const avatar = new AvatarSolver(ik, rig.spec, rig.humanoid);
  try {
    const spec = avatar.rig.spec,
      h = avatar.height,
      delta = 1e-3 * h;
    const numBones = spec.parents.length;
    const heads = Array.from({ length: numBones }, (_, i) => restBase(spec, i));
    const restRotations = avatar.tipRotations();
    const restTips = avatar.tips();
    const upper = UPPER_ROLES.map((r) => rig.humanoid.bones[r]).filter((b): b is number => b !== undefined);
    const limbs = flipLimbs(spec, rig.humanoid);
    const effectors = Array.from(avatar.bones);
    const { frames, name } = clips.clips[clip];
    const tracked = POINTS[points];
    const moving = Array.from(avatar.movingBones);
    const g = new Matrix4(),
      q = new Quaternion(),
      rest = new Quaternion();
    // The clip's pose of effector k at frame `motion`: its tip and its bone frame.
    const truthOf = (motion: Float64Array, k: number): TrackedPose & { position: number[]; orientation: number[] } => {
      const m = motion.subarray(16 * effectors[k], 16 * effectors[k] + 16);
      const position = transformPoint(m, restTips.subarray(3 * k, 3 * k + 3));
      fromRowMajor(g, m, 0); // its rotation part: the bone's turn from rest
      rest.fromArray(restRotations, 4 * k);
      q.setFromRotationMatrix(g).multiply(rest);
      return { position, orientation: q.toArray() };
    };
    const inputs = Array.from({ length: frames }, (_, f) => {
      const motion = clips.motion(clip, f);
      const input = {} as AvatarInput;
      for (const key of tracked) input[key] = truthOf(motion, EFFECTOR[key]);
      return input;
    });
    // The timed runs: update() and nothing else that allocates between the frames (the poses and
    // planted feet go into arrays made beforehand), so that the times are the avatar's own. The
    // clip runs TIMED_RUNS times, each from a new avatar; a frame's time is its median over them
    // (one run's frame can lose a 4 ms slice of the CPU to another thread on a shared machine).
    // The avatar is deterministic: every run must give the same poses.
    const numAngles = avatar.angles.length;
    const solved = new Float64Array(frames * numAngles);
    const plantedLog = new Float64Array(frames * 6);
    const runTimes = Array.from({ length: TIMED_RUNS }, () => new Float64Array(frames));
    for (let run = 0; run < TIMED_RUNS; run++) {
      const runner = run === 0 ? avatar : new AvatarSolver(ik, rig.spec, rig.humanoid);
      try {
        collectGarbage();
        for (let f = 0; f < frames; f++) {
          const t0 = performance.now();
          runner.update(inputs[f]);
          runTimes[run][f] = (performance.now() - t0) * 1000;
          const at = f * numAngles;
          if (run === 0) {
            solved.set(runner.angles, at);
            runner.plantedFeet().forEach((p, i) => plantedLog.set(p ?? [NaN, NaN, NaN], 6 * f + 3 * i));
          } else if (!runner.angles.every((a, i) => a === solved[at + i]))
            throw new BenchError(
              `track: ${name} frame ${f} gave another pose on run ${run + 1} (the avatar is not deterministic)`,
              1,
            );
        }
      } finally {
        if (runner !== avatar) runner.dispose();
      }
    }
    const times = Float64Array.from({ length: frames }, (_, f) => median(runTimes.map((t) => t[f])));
    let onTarget = 0,
      reachable = 0,
      onTargetReachable = 0,
      mpjpe = 0,
      mpjpeUpper = 0,
      flips = 0,
      slide = 0;
    const ours: number[][] = [],
      theirs: number[][] = [];
    let previousPoses: Float64Array | null = null;
    // Per foot: the clip's tip last frame, and ours where the foot was planted (null: in the air).
    const feet = FEET.map(() => ({ truth: null as ArrayLike<number> | null, planted: null as number[] | null }));
    for (let f = 0; f < frames; f++) {
      const motion = clips.motion(clip, f),
        input = inputs[f];
      const angles = solved.subarray(f * numAngles, (f + 1) * numAngles);
      const truthHeads = heads.map((p, i) => transformPoint(motion.subarray(16 * i, 16 * i + 16), p));
      const given = tracked.map((key) => ({ k: EFFECTOR[key], ...input[key]! }));
      const tips = avatar.rig.tips(angles),
        turns = avatar.rig.tipRotations(angles),
        poses = avatar.rig.poses(angles);
      const tipAt = (k: number): number[] => [tips[3 * k], tips[3 * k + 1], tips[3 * k + 2]];
      const within = given.every(
        ({ k, position, orientation }) =>
          distance(tipAt(k), position) < delta &&
          rotationAngleDeg(turns.subarray(4 * k, 4 * k + 4), orientation) < TRACK_TOLERANCE_DEG,
      );
      if (within) onTarget++;
      if (moving.every((b) => limitExcessDeg(spec, motion, b) <= REACH_TOLERANCE_DEG)) {
        reachable++;
        if (within) onTargetReachable++;
      }
      const mine = heads.map((p, i) => transformPoint(poses.subarray(16 * i, 16 * i + 16), p));
      const error = (b: number): number => distance(mine[b], truthHeads[b]);
      mpjpe += mean(heads.map((_, b) => error(b))) / h;
      mpjpeUpper += mean(upper.map(error)) / h;
      ours.push(mine.flat());
      theirs.push(truthHeads.flat());
      if (previousPoses && isFlip(spec, limbs, previousPoses, poses)) flips++;
      previousPoses = poses;
      // With 6 points a foot is planted while the clip's stays still, and ours should not slide from
      // where it was then; with 3, where the avatar planted it (it steps when the body leaves it).
      const planted = [0, 1].map((i) =>
        Number.isNaN(plantedLog[6 * f + 3 * i]) ? null : plantedLog.subarray(6 * f + 3 * i, 6 * f + 3 * i + 3),
      );
      FEET.forEach((key, i) => {
        const tip = tipAt(EFFECTOR[key]),
          foot = feet[i];
        if (points === 3) {
          if (planted[i]) slide = Math.max(slide, distance(tip, planted[i]!) / h);
          return;
        }
        const truth = input[key]!.position; // tracked with 6 points: the clip's foot this frame
        const still = foot.truth !== null && distance(truth, foot.truth) < STILL_SHARE * h;
        if (!still || foot.planted === null) foot.planted = tip;
        else slide = Math.max(slide, distance(tip, foot.planted) / h);
        foot.truth = truth;
      });
    }
    times.sort((a, b) => a - b);
    const truthJitter = meanAcceleration(theirs),
      ourJitter = meanAcceleration(ours);
    return {
      rig: rig.name,
      experiment: 'track',
      method: 'avatar',
      clip: name,
      frames,
      points,
      success_rate: onTarget / frames,
      reachable: reachable / frames,
      success_reachable: reachable > 0 ? onTargetReachable / reachable : null,
      mpjpe: mpjpe / frames,
      mpjpe_upper: mpjpeUpper / frames,
      jitter_ratio: truthJitter > 0 ? ourJitter / truthJitter : null,
      flips,
      foot_slide: slide,
      median_us: times[Math.floor((times.length - 1) / 2)],
      p99_us: times[Math.min(times.length - 1, Math.floor(0.99 * times.length))],
    };
  } finally {
    avatar.dispose();
  }
}

/**
 * A full garbage collection now, so that the clip's inputs and the last clip's measures, made
 * before the timed run, are not collected inside it (V8's collector pauses 0.5-8 ms: one in a
 * clip of 181 frames is its p99). What update() itself allocates is still collected in the run.
 */
let gc: (() => void) | null = null;
function collectGarbage(): void {
  if (!gc) {
    v8.setFlagsFromString('--expose-gc');
    gc = runInNewContext('gc') as () => void;
  }
  gc();
}

function median(xs: number[]): number {
  const sorted = [...xs].sort((a, b) => a - b);
  return sorted[(sorted.length - 1) >> 1];
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
