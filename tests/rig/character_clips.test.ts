// The character's own animation clips (scripts/models/character_clips.ts, turn_clip.ts,
// stress_clip.ts), read back from web/public/models/character.glb as the track experiment reads
// them (bench-node/clip_frames.ts): six clips at 30 frames per second, each starting in the rest
// pose; in every frame every joint within the humanoid limits and no elbow or knee bent against
// its anatomy; no foot below the floor, no planted foot sliding; and what each clip is for: the
// crouch lowers the hips by a quarter of the height, turn_in_place turns the body round on stepping
// feet, stress leans, looks up and down, crouches to half the height and turns.
import { resolve } from 'node:path';

import { beforeAll, describe, expect, it } from 'vitest';

import { ClipFrames } from '../../bench-node/clip_frames.js';
import { bentAgainst, flipLimbs } from '../../bench-node/flips.js';
import { limitExcessDeg } from '../../bench-node/clip_limits.js';
import { restBase } from '../../bench-node/reach.js';
import { loadBenchRig, type BenchRig } from '../../bench-node/rigs.js';
import { transformPoint } from '../../web/src/rig/mat4.js';

let rig: BenchRig;
let clips: ClipFrames;
beforeAll(async () => {
  rig = await loadBenchRig(resolve(import.meta.dirname, '../../web/public/models/character.glb'));
  clips = await ClipFrames.read(rig.path, rig.boneNodes!);
});

/** 185 cm under the Armature's 0.01 scale: the top of the head at rest, over the floor at 0. */
const height = 1.85;
/** The top of the head at rest (the file stores no leaf bone's length, so not the HeadTop_End's tip). */
const topOfHead = [0, height, 0];

/** Where the point `p` of the rest pose moves with bone `bone` at `motion` (rig units). */
function moved(motion: Float64Array, bone: number, p: ArrayLike<number>): number[] {
  return transformPoint(motion.subarray(16 * bone, 16 * bone + 16), p);
}
function head(motion: Float64Array, bone: number): number[] {
  return moved(motion, bone, restBase(rig.spec, bone));
}
const distance = (a: number[], b: number[]): number => Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
const degrees = (radians: number): number => (radians * 180) / Math.PI;

/** Every frame of clip `name`, as bone motions. */
function framesOf(name: string): Float64Array[] {
  const c = clips.clips.findIndex((x) => x.name === name);
  return Array.from({ length: clips.clips[c].frames }, (_, f) => clips.motion(c, f));
}

/**
 * Every clip stays within the humanoid limits to this (degrees): the keyframe reduction of
 * turn_in_place and stress (0.01), and the rest pose's knees, bent 0.008 degrees outwards, which the
 * legs' closed form bends forwards.
 */
const LIMIT_SLACK_DEG = 0.03;

/** A foot's sole: its heel (under the ankle, at the toes' height) and ball moving with the foot, its toe tip with the toes; rig units. */
function soles(): { foot: number; toes: number; heel: number[]; ball: number[]; tip: number[] }[] {
  const spec = rig.spec,
    bones = rig.humanoid!.bones;
  return [
    [bones.leftFoot!, bones.leftToes!],
    [bones.rightFoot!, bones.rightToes!],
  ].map(([foot, toes]) => {
    const ankle = restBase(spec, foot),
      ball = restBase(spec, toes);
    const tip = transformPoint(spec.rest.subarray(16 * toes, 16 * toes + 16), [spec.lengths[toes], 0, 0]);
    return { foot, toes, heel: [ankle[0], ball[1], ankle[2]], ball, tip };
  });
}

describe("the character's clips", () => {
  it('are idle, reach_wave, crouch, look_around (6 s each), turn_in_place (7 s) and stress (21 s) at 30 fps, from the rest pose', () => {
    const seconds = { idle: 6, reach_wave: 6, crouch: 6, look_around: 6, turn_in_place: 7, stress: 21 };
    expect(clips.clips).toEqual(Object.entries(seconds).map(([name, s]) => ({ name, fps: 30, frames: 30 * s + 1 })));
    clips.clips.forEach((_, c) => {
      const first = clips.motion(c, 0);
      for (let i = 0; i < first.length; i++)
        expect(
          Math.abs(first[i] - (i % 16 === 0 || i % 16 === 5 || i % 16 === 10 || i % 16 === 15 ? 1 : 0)),
        ).toBeLessThan(1e-6);
    });
  });

  it('keep every joint within the humanoid limits and bend no knee or elbow against its anatomy', () => {
    // The hips bone is the rig's root: its turn is the whole body's, in the world (the avatar's floating root).
    const spec = rig.spec,
      limbs = flipLimbs(spec, rig.humanoid);
    const bones = spec.names.map((_, b) => b).filter((b) => spec.parents[b] >= 0);
    for (const { name } of clips.clips) {
      const worst = new Map<number, number>();
      framesOf(name).forEach((motion, f) => {
        for (const b of bones) worst.set(b, Math.max(worst.get(b) ?? 0, limitExcessDeg(rig.spec, motion, b)));
        for (const limb of limbs)
          expect(bentAgainst(spec, limb, motion), `${name} frame ${f} ${spec.names[limb.bone]}`).toBe(false);
      });
      for (const [b, excess] of worst) expect(excess, `${name}: ${spec.names[b]}`).toBeLessThan(LIMIT_SLACK_DEG);
    }
  });

  it('never put a foot below the floor, and a planted foot (its sole on the floor) does not slide', () => {
    const feet = soles();
    const floor = Math.min(...feet.flatMap((s) => [s.heel[1], s.ball[1], s.tip[1]]));
    for (const { name } of clips.clips) {
      const frames = framesOf(name);
      for (const s of feet) {
        const sole = (m: Float64Array): number[][] => [
          moved(m, s.foot, s.heel),
          moved(m, s.foot, s.ball),
          moved(m, s.toes, s.tip),
        ];
        const planted = (points: number[][]): boolean => points.every((p) => p[1] - floor < 1e-3 * height);
        let before: number[][] | null = null;
        frames.forEach((m, f) => {
          const now = sole(m);
          for (const p of now)
            expect(p[1] - floor, `${name} frame ${f}: ${rig.spec.names[s.foot]} below the floor`).toBeGreaterThan(
              -1e-4 * height,
            );
          if (before && planted(before) && planted(now)) {
            const slide = Math.max(...now.map((p, k) => distance(p, before![k])));
            expect(slide, `${name} frame ${f}: ${rig.spec.names[s.foot]} slides`).toBeLessThan(1e-3 * height);
          }
          before = now;
        });
      }
    }
  });

  it('the first four keep the feet where they stand, and the crouch lowers the hips by a quarter of the height', () => {
    const feet = soles().map((s) => s.foot),
      hips = rig.humanoid!.bones.hips!;
    const rest = head(clips.motion(0, 0), hips);
    for (const name of ['idle', 'reach_wave', 'crouch', 'look_around'])
      framesOf(name).forEach((motion, f) => {
        for (const foot of feet)
          expect(distance(head(motion, foot), restBase(rig.spec, foot)), `${name} frame ${f}`).toBeLessThan(
            1e-3 * height,
          );
      });
    const lowest = Math.min(...framesOf('crouch').map((m) => head(m, hips)[1] - rest[1]));
    expect(lowest / height).toBeCloseTo(-0.25, 2);
  });

  /**
   * Over clip `name`: the body's facing (the hips' forward direction), degrees to the left of +Z
   * counted on past 180, and each foot's highest lift (rig units).
   */
  function turning(name: string): { facing: number[]; lifts: number[] } {
    const hips = rig.humanoid!.bones.hips!,
      frames = framesOf(name);
    const facing: number[] = [];
    for (const m of frames) {
      const angle = degrees(Math.atan2(m[16 * hips + 2], m[16 * hips + 10])),
        last = facing[facing.length - 1] ?? angle;
      facing.push(last + (((angle - last + 540) % 360) - 180));
    }
    const lifts = soles().map((s) => Math.max(...frames.map((m) => moved(m, s.foot, s.heel)[1] - s.heel[1])));
    return { facing, lifts };
  }

  it('turn_in_place turns the body 180 degrees to the left on feet that step, and stands facing back', () => {
    const { facing, lifts } = turning('turn_in_place');
    facing.slice(1).forEach((angle, f) => expect(angle, `frame ${f + 1}`).toBeGreaterThanOrEqual(facing[f] - 1e-6));
    expect(facing[facing.length - 1]).toBeCloseTo(180, 3);
    for (const lift of lifts) expect(lift).toBeGreaterThan(0.05);
    const frames = framesOf('turn_in_place'),
      last = frames[frames.length - 1];
    for (const s of soles())
      expect(distance(moved(last, s.foot, s.heel), [-s.heel[0], s.heel[1], -s.heel[2]])).toBeLessThan(1e-3 * height);
  });

  it('stress leans 30 degrees forward and 12 sideways, tilts the head 30, looks 60 up and 60 down, crouches to half the height and turns round', () => {
    const bones = rig.humanoid!.bones,
      frames = framesOf('stress');
    /** Bone `b`'s up direction at `m`: its tilt forward and to the left, degrees. */
    const tilt = (m: Float64Array, b: number): { forward: number; left: number } => ({
      forward: degrees(Math.atan2(m[16 * b + 9], m[16 * b + 5])),
      left: degrees(Math.atan2(m[16 * b + 1], m[16 * b + 5])),
    });
    /** Frames from `a` to `b` seconds. */
    const during = (a: number, b: number): Float64Array[] => frames.slice(30 * a, 30 * b + 1);
    const chest = bones.upperChest!,
      skull = bones.head!;
    expect(Math.max(...during(5, 7).map((m) => tilt(m, chest).forward))).toBeCloseTo(30, 1);
    expect(Math.max(...during(7, 9).map((m) => tilt(m, chest).left))).toBeGreaterThan(12);
    expect(Math.max(...during(7, 9).map((m) => tilt(m, skull).left))).toBeCloseTo(30, 0);
    const gaze = during(9, 12.2).map((m) => degrees(Math.asin(m[16 * skull + 6])));
    expect(Math.max(...gaze)).toBeCloseTo(60, 1);
    expect(Math.min(...gaze)).toBeCloseTo(-60, 1);
    expect(Math.min(...frames.map((m) => moved(m, skull, topOfHead)[1])) / height).toBeCloseTo(0.5, 2);
    const { facing, lifts } = turning('stress');
    expect(facing[facing.length - 1]).toBeCloseTo(180, 3);
    for (const lift of lifts) expect(lift).toBeGreaterThan(0.05);
  });
});
