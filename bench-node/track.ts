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
//   TIMED_RUNS runs of the clip, interleaved with the other clips' (track_timing.ts).
// With noise > 0 (a share of the height), every tracked position is moved by up to half that on
// each coordinate, drawn uniformly from a stream seeded by the run's seed and the clip's name (a
// tracker's jitter); success is then against the positions given, the joints against the clip's.
import { Matrix4, Quaternion } from 'three';

import { AvatarSolver, type AvatarInput, type TrackedPose } from '#avatar/avatar_solver.js';
import type { IkCoreModule } from '#ik/module.js';
import type { RigSpec } from '#ik/rig_arrays.js';
import type { HumanoidMap } from '#rig/humanoid/humanoid_roles.js';
import { transformPoint } from '#rig/mat4.js';
import { fromRowMajor } from '#view/row_major.js';
import { ClipFrames } from './clip_frames.js';
import { BenchError } from './errors.js';
import { streamFor } from './prng.js';
import { EFFECTOR, measureClip, POINTS } from './track_measures.js';
import { ClipTiming, TIMED_RUNS } from './track_timing.js';

export interface TrackRow {
  rig: string;
  experiment: 'track';
  method: 'avatar';
  clip: string;
  frames: number;
  points: number;
  /** The tracked positions' jitter, a share of the height (0: the clip's own). */
  noise: number;
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

export interface TrackRig {
  name: string;
  path: string;
  spec: RigSpec;
  humanoid: HumanoidMap;
  boneNodes: Int32Array;
}

/** How the tracked points are made: how many (3: head and hands; 6: and hips and feet), and their jitter. */
export interface TrackInputs {
  points: number;
  /** Each tracked position moves by up to half this share of the height on each coordinate; 0: none. */
  noise: number;
  /** The jitter's seed (with the clip's name). */
  seed: number;
}

/**
 * Runs the clips named in `clips` ('all': every one) of `rig`'s file through the avatar solver with
 * the tracked points of `how`; one row per clip. Throws BenchError naming a clip the file lacks,
 * or a file without clips.
 */
export async function runTrack(
  ik: IkCoreModule,
  rig: TrackRig,
  clips: string[] | 'all',
  how: TrackInputs,
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
  for (const clip of chosen) warmUpClip(ik, rig, frames, clip, how);
  const timings: Array<{ clip: number; avatar: AvatarSolver; inputs: AvatarInput[]; timing: ClipTiming }> = [];
  try {
    for (const clip of chosen) {
      const avatar = new AvatarSolver(ik, rig.spec, rig.humanoid);
      const inputs = trackedInputs(avatar, frames, clip, how);
      timings.push({ clip, avatar, inputs, timing: new ClipTiming(ik, rig, avatar, inputs, frames.clips[clip].name) });
    }
    // Run by run over the clips (track_timing.ts: a slow spell of the machine slows one run).
    for (let run = 0; run < TIMED_RUNS; run++) for (const t of timings) t.timing.run();
    return timings.map((t) => clipRow(rig, frames, t.clip, how, t.avatar, t.inputs, t.timing));
  } finally {
    for (const t of timings) t.avatar.dispose();
  }
}

/** Clip `clip` once through a new avatar, untimed. */
function warmUpClip(ik: IkCoreModule, rig: TrackRig, clips: ClipFrames, clip: number, how: TrackInputs): void {
  const avatar = new AvatarSolver(ik, rig.spec, rig.humanoid);
  try {
    for (const input of trackedInputs(avatar, clips, clip, how)) avatar.update(input);
  } finally {
    avatar.dispose();
  }
}

/** Clip `clip`'s row: the measures of `avatar`'s poses (its first timed run) and the times of `timing`. */
function clipRow(
  rig: TrackRig,
  clips: ClipFrames,
  clip: number,
  how: TrackInputs,
  avatar: AvatarSolver,
  inputs: readonly AvatarInput[],
  timing: ClipTiming,
): TrackRow {
  const { frames, name } = clips.clips[clip];
  const { points, noise } = how;
  const run = timing.result();
  const m = measureClip(avatar, rig.humanoid, clips, clip, points, inputs, run);
  const times = run.times.sort();
  return {
    rig: rig.name,
    experiment: 'track',
    method: 'avatar',
    clip: name,
    frames,
    points,
    noise,
    success_rate: m.onTarget / frames,
    reachable: m.reachable / frames,
    success_reachable: m.reachable > 0 ? m.onTargetReachable / m.reachable : null,
    mpjpe: m.mpjpe / frames,
    mpjpe_upper: m.mpjpeUpper / frames,
    jitter_ratio: m.jitterRatio,
    flips: m.flips,
    foot_slide: m.slide,
    median_us: times[Math.floor((times.length - 1) / 2)],
    p99_us: times[Math.min(times.length - 1, Math.floor(0.99 * times.length))],
  };
}

/**
 * The tracked points' poses at each frame of clip `clip` (`how.points` of them: POINTS), each the
 * clip's tip of its effector (rig units), jittered by `how.noise` (see the header), and the clip's
 * bone frame, for `avatar` at rest.
 */
function trackedInputs(avatar: AvatarSolver, clips: ClipFrames, clip: number, how: TrackInputs): AvatarInput[] {
  const jitter = streamFor(how.seed, `track:${clips.clips[clip].name}`),
    amplitude = how.noise * avatar.height;
  const restRotations = avatar.tipRotations();
  const restTips = avatar.tips();
  const effectors = Array.from(avatar.bones);
  const g = new Matrix4(),
    q = new Quaternion(),
    rest = new Quaternion();
  // The clip's pose of effector k at frame `motion`: its tip and its bone frame.
  const truthOf = (motion: Float64Array, k: number): TrackedPose & { position: number[]; orientation: number[] } => {
    const m = motion.subarray(16 * effectors[k], 16 * effectors[k] + 16);
    const position = transformPoint(m, restTips.subarray(3 * k, 3 * k + 3));
    if (amplitude > 0) for (let i = 0; i < 3; i++) position[i] += amplitude * (jitter() - 0.5);
    fromRowMajor(g, m, 0); // its rotation part: the bone's turn from rest
    rest.fromArray(restRotations, 4 * k);
    q.setFromRotationMatrix(g).multiply(rest);
    return { position, orientation: q.toArray() };
  };
  return Array.from({ length: clips.clips[clip].frames }, (_, f) => {
    const motion = clips.motion(clip, f);
    const input = {} as AvatarInput;
    for (const key of POINTS[how.points]) input[key] = truthOf(motion, EFFECTOR[key]);
    return input;
  });
}
