// The character's own animation clips (scripts/models/character_clips.ts), read back from
// web/public/models/character.glb as the track experiment reads them (bench-node/clip_frames.ts):
// the four clips at 30 frames per second for 6 s; each starts in the rest pose; the feet stay on
// the floor in every frame of every clip (the crouch's legs are solved in closed form); the crouch
// lowers the hips by a quarter of the height; no elbow or knee bends against its anatomy.
import { resolve } from 'node:path';

import { beforeAll, describe, expect, it } from 'vitest';

import { ClipFrames } from '../../bench-node/clip_frames.js';
import { bentAgainst, flipLimbs } from '../../bench-node/flips.js';
import { restBase } from '../../bench-node/reach.js';
import { loadBenchRig, type BenchRig } from '../../bench-node/rigs.js';
import { transformPoint } from '../../web/src/rig/mat4.js';

let rig: BenchRig;
let clips: ClipFrames;
beforeAll(async () => {
  rig = await loadBenchRig(resolve(import.meta.dirname, '../../web/public/models/character.glb'));
  clips = await ClipFrames.read(rig.path, rig.boneNodes!);
});

/** Where bone `bone`'s head is at `motion` (rig units). */
function head(motion: Float64Array, bone: number): number[] {
  return transformPoint(motion.subarray(16 * bone, 16 * bone + 16), restBase(rig.spec, bone));
}

describe("the character's clips", () => {
  it('are idle, reach_wave, crouch and look_around, 181 frames at 30 fps, from the rest pose', () => {
    expect(clips.clips).toEqual(['idle', 'reach_wave', 'crouch', 'look_around'].map((name) => ({ name, fps: 30, frames: 181 })));
    clips.clips.forEach((_, c) => {
      const first = clips.motion(c, 0);
      for (let i = 0; i < first.length; i++) expect(Math.abs(first[i] - (i % 16 === 0 || i % 16 === 5 || i % 16 === 10 || i % 16 === 15 ? 1 : 0))).toBeLessThan(1e-6);
    });
  });

  it('keep the feet on the floor, bend the knees and elbows the anatomical way, and crouch a quarter of the height', () => {
    const humanoid = rig.humanoid!;
    const feet = [humanoid.bones.leftFoot!, humanoid.bones.rightFoot!], hips = humanoid.bones.hips!;
    const limbs = flipLimbs(rig.spec, humanoid);
    const rest = new Float64Array(16 * rig.spec.parents.length);
    for (let i = 0; i < rest.length; i += 16) rest[i] = rest[i + 5] = rest[i + 10] = rest[i + 15] = 1;
    const height = 1.85; // 185 cm under the Armature's 0.01 scale
    let lowest = Infinity;
    clips.clips.forEach((clip, c) => {
      for (let f = 0; f < clip.frames; f++) {
        const motion = clips.motion(c, f);
        for (const foot of feet) {
          const [a, b] = [head(motion, foot), head(rest, foot)];
          expect(Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]), `${clip.name} frame ${f}`).toBeLessThan(1e-3 * height);
        }
        for (const limb of limbs) expect(bentAgainst(rig.spec, limb, motion), `${clip.name} frame ${f} ${rig.spec.names[limb.bone]}`).toBe(false);
        if (clip.name === 'crouch') lowest = Math.min(lowest, head(motion, hips)[1] - head(rest, hips)[1]);
      }
    });
    expect(lowest / height).toBeCloseTo(-0.25, 2);
  });
});
