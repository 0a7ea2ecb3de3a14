// The character's animation clips (issue 29): the motions a tracked avatar must follow, made from
// the skeleton alone so that `npm run models` gives the same bytes every time. Each clip starts in
// the T-pose (the rig's rest) and eases into a relaxed stance (arms down, elbows a little bent)
// over its first second, as a user puts on a headset and lets the arms fall:
// - idle: the spine sways and the head turns a little;
// - reach_wave: the right arm reaches forward and up, then waves;
// - crouch: the hips go down a quarter of the height and back, the knees bend forward, the feet stay
//   on the floor (the legs solved in closed form), the spine leans forward, the arms come forward;
// - look_around: the head and neck turn 45 degrees each way and nod, the chest turns with them;
// - turn_in_place (turn_clip.ts): the body turns 180 degrees on stepping feet, then stands;
// - stress (stress_clip.ts): what users of full-body IK in VR complain about, one after another:
//   hands behind the back and over the head, leaning, looking up and down, a deep crouch, a turn.
// The first four keep every frame; the last two only the keyframes interpolation cannot rebuild
// within KEY_TOLERANCE, and keep every joint within the humanoid limits (anatomy_ranges.ts).
import { type Body, P, characterBody, ease, fwd } from './character_body.js';
import { type ClipDef, type ClipPose, type Quat, between, inverse, mul, rotate } from './clips.js';
import type { JointDef } from './model.js';
import { stressClip } from './stress_clip.js';
import { turnInPlace } from './turn_clip.js';
import { type Vec3, add, dot, length, normalize, scale, sub } from './vec.js';

const FPS = 30;
const SECONDS = 6;

export function characterClips(joints: readonly JointDef[]): ClipDef[] {
  const body: Body = characterBody(joints);
  const { joint, dir, bend, twist, aim, stance } = body;

  /**
   * Both legs for the hips shifted by `shift` (armature units) with the feet where they stand at
   * rest: each thigh and shin in the plane of the hip-ankle line and the knee's forward direction
   * (law of cosines), the foot turned back to its rest orientation.
   */
  const legs = (shift: Vec3, turns: Record<string, Quat>): void => {
    for (const s of ['Left', 'Right']) {
      const hip = add(joint(`${s}UpLeg`).head, shift), knee0 = joint(`${s}Leg`).head, ankle = joint(`${s}Foot`).head;
      const l1 = length(sub(knee0, joint(`${s}UpLeg`).head)), l2 = length(sub(ankle, knee0));
      const d = sub(ankle, hip), dist = Math.min(length(d), l1 + l2 - 1e-9);
      const u = normalize(d);
      const across = normalize(sub(fwd, scale(u, dot(fwd, u))));
      const cosA = (l1 * l1 + dist * dist - l2 * l2) / (2 * l1 * dist);
      const knee = add(hip, scale(add(scale(u, cosA), scale(across, Math.sqrt(Math.max(0, 1 - cosA * cosA)))), l1));
      const thigh = between(dir(`${s}UpLeg`), sub(knee, hip));
      const shin = between(dir(`${s}Leg`), rotate(inverse(thigh), sub(ankle, knee)));
      turns[P + `${s}UpLeg`] = thigh;
      turns[P + `${s}Leg`] = shin;
      turns[P + `${s}Foot`] = inverse(mul(thigh, shin));
    }
  };

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
        [P + 'Spine']: mul(bend('Spine', fwd, 3 * w * sine(t, 3)), bend('Spine', [1, 0, 0], 3 * w * sine(t, 4))),
        [P + 'Spine1']: bend('Spine1', fwd, 2 * w * sine(t, 3, 0.5)),
        [P + 'Head']: twist('Head', 10 * w * sine(t, 5)),
      }),
    })),
    clip('reach_wave', (t, w) => {
      const reach = ease(t, 1, 2.5), wave = ease(t, 2.5, 3);
      const hang = normalize([-0.25, -1, 0.15]), raised = normalize([-0.2, 0.8, 0.6]);
      return {
        turns: stance(w, {
          [P + 'RightArm']: aim('RightArm', add(scale(hang, 1 - reach), scale(raised, reach)), w),
          [P + 'RightForeArm']: bend('RightForeArm', fwd, w * (20 + wave * (25 + 25 * sine(t, 0.8)))),
          [P + 'RightHand']: bend('RightHand', fwd, wave * 20 * sine(t, 0.8, 1)),
        }),
      };
    }),
    clip('crouch', (t, w) => {
      const depth = 46 * (ease(t, 1, 3) - ease(t, 4, 6)); // a quarter of the 185 height, then back up
      const shift: Vec3 = [0, -depth, -0.35 * depth];
      const lean = depth / 46;
      const turns: Record<string, Quat> = {
        [P + 'Spine']: bend('Spine', fwd, 12 * lean),
        [P + 'Spine1']: bend('Spine1', fwd, 8 * lean),
        [P + 'Head']: bend('Head', fwd, -12 * lean),
        [P + 'LeftArm']: aim('LeftArm', add(scale([0.25, -1, 0.15], 1 - lean), scale([0.2, -0.2, 1], lean)), w),
        [P + 'RightArm']: aim('RightArm', add(scale([-0.25, -1, 0.15], 1 - lean), scale([-0.2, -0.2, 1], lean)), w),
      };
      if (depth > 0) legs(shift, turns); // at rest the legs stay as they are (the solution differs by 1e-4 rad)
      return { turns: stance(w, turns), shift };
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
