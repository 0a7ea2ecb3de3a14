// The character's animation clips: the motions a tracked avatar must follow, made from
// the skeleton alone so that `npm run models` gives the same bytes every time. Each clip starts in
// the T-pose (the rig's rest) and eases into a relaxed stance (arms down, elbows a little bent)
// over its first second, as a user puts on a headset and lets the arms fall:
// - idle: the spine sways forward and back and twists, the head turns a little;
// - reach_wave: the right arm reaches forward and up, then waves with the elbow and the wrist;
// - crouch: the hips go down a quarter of the height (going back and tilting forward) and up
//   again, the knees bend forward, the feet stay flat on the floor (the legs in closed form,
//   planted_legs.ts), the spine leans forward, the arms come forward;
// - look_around: the head and neck turn 45 degrees each way and nod, the chest turns with them;
// - turn_in_place (turn_clip.ts): the body turns 180 degrees on stepping feet, then stands;
// - stress (stress_clip.ts): what users of full-body IK in VR complain about, one after another:
//   hands behind the back and over the head, leaning, looking up and down, a deep crouch, a turn.
// Every clip keeps every joint within the humanoid limits (anatomy_ranges.ts). The first four keep
// every frame; the last two only the keyframes interpolation cannot rebuild within KEY_TOLERANCE.
import { type Body, P, characterBody, ease, fwd } from './character_body.js';
import { type ClipDef, type ClipPose, type Quat, mul, turnAbout } from './clips.js';
import type { JointDef } from './model.js';
import { type Hips, STANDING, plantLegs } from './planted_legs.js';
import { stressClip } from './stress_clip.js';
import { turnInPlace } from './turn_clip.js';
import { type Vec3, add, normalize, scale } from './vec.js';

const FPS = 30;
const SECONDS = 6;
/** The character's left, and down. */
const LEFT: Vec3 = [1, 0, 0];
const DOWN: Vec3 = [0, -1, 0];

export function characterClips(joints: readonly JointDef[]): ClipDef[] {
  const body: Body = characterBody(joints);
  const { bend, twist, aim, stance } = body;

  const clip = (name: string, pose: (t: number, w: number) => ClipPose): ClipDef => ({
    name,
    seconds: SECONDS,
    fps: FPS,
    pose: (t) => pose(t, ease(t, 0, 1)),
  });

  const sine = (t: number, period: number, phase = 0): number => Math.sin((2 * Math.PI * t) / period + phase);

  return [
    clip('idle', (t, w) => ({
      turns: stance(w, {
        // Forward and back and twisting, not sideways: a spine bone bends sideways only by turning
        // its bend plane, at most 15 degrees from straight ahead.
        [P + 'Spine']: mul(bend('Spine', fwd, 3 * w * sine(t, 3)), twist('Spine', 3 * w * sine(t, 4))),
        [P + 'Spine1']: bend('Spine1', fwd, 2 * w * sine(t, 3, 0.5)),
        [P + 'Head']: twist('Head', 10 * w * sine(t, 5)),
      }),
    })),
    clip('reach_wave', (t, w) => {
      const reach = ease(t, 1, 2.5),
        wave = ease(t, 2.5, 3);
      const hang = normalize([-0.25, -1, 0.15]),
        raised = normalize([-0.2, 0.8, 0.6]);
      return {
        turns: stance(w, {
          [P + 'RightArm']: aim('RightArm', add(scale(hang, 1 - reach), scale(raised, reach)), w),
          [P + 'RightForeArm']: bend('RightForeArm', fwd, w * (20 + wave * (25 + 25 * sine(t, 0.8)))),
          // The wrist flexes towards the palm (down at rest) and back, not sideways: a hand bends
          // only in planes within 20 degrees of its flexion's.
          [P + 'RightHand']: bend('RightHand', DOWN, wave * 20 * sine(t, 0.8, 1)),
        }),
      };
    }),
    clip('crouch', (t, w) => {
      // The hips go down a quarter of the 185 height and back up (depth: 0 to 1 and back to 0),
      // tilting forward 10 degrees and going back 25 cm, most of it early (back: ahead of depth), so
      // that the shins never lean more than 23 degrees over the flat feet (the ankles allow 30).
      const depth = ease(t, 1, 3) - ease(t, 4, 6),
        back = depth * (2 - depth);
      const hips: Hips = { turn: turnAbout(LEFT, 10 * depth), shift: [0, -46 * depth, -25 * back] };
      const turns: Record<string, Quat> = {
        [P + 'Hips']: hips.turn,
        [P + 'Spine']: bend('Spine', fwd, 12 * depth),
        [P + 'Spine1']: bend('Spine1', fwd, 8 * depth),
        [P + 'Head']: bend('Head', fwd, -12 * depth),
        [P + 'LeftArm']: aim('LeftArm', add(scale([0.25, -1, 0.15], 1 - depth), scale([0.2, -0.2, 1], depth)), w),
        [P + 'RightArm']: aim('RightArm', add(scale([-0.25, -1, 0.15], 1 - depth), scale([-0.2, -0.2, 1], depth)), w),
      };
      // At rest the legs stay as they are (the closed form's knees differ by 1e-4 rad).
      if (depth > 0) plantLegs(body, hips, STANDING, turns);
      return { turns: stance(w, turns), shift: hips.shift };
    }),
    clip('look_around', (t, w) => ({
      turns: stance(w, {
        [P + 'Head']: mul(twist('Head', 30 * w * sine(t, 3)), bend('Head', fwd, 15 * w * sine(t, 2.5))),
        [P + 'Neck']: twist('Neck', 15 * w * sine(t, 3)),
        [P + 'Spine2']: twist('Spine2', 10 * w * sine(t, 3)),
      }),
    })),
    turnInPlace(body),
    stressClip(body),
  ];
}
