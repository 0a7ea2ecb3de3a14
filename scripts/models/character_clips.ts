// The character's animation clips (issue 29): the motions a tracked avatar must follow, made from
// the skeleton alone so that `npm run models` gives the same bytes every time. Each clip starts in
// the T-pose (the rig's rest) and eases into a relaxed stance (arms down, elbows a little bent)
// over its first second, as a user puts on a headset and lets the arms fall:
// - idle: the spine sways and the head turns a little;
// - reach_wave: the right arm reaches forward and up, then waves;
// - crouch: the hips go down a quarter of the height and back, the knees bend forward, the feet stay
//   on the floor (the legs solved in closed form), the spine leans forward, the arms come forward;
// - look_around: the head and neck turn 45 degrees each way and nod, the chest turns with them.
// Turning in place and the stress clip (hands behind the back, over the head...) are not made yet.
import { type ClipDef, type ClipPose, type Quat, between, inverse, mul, rotate, turnAbout } from './clips.js';
import type { JointDef } from './model.js';
import { type Vec3, add, cross, dot, length, normalize, scale, sub } from './vec.js';

const P = 'mixamorig:';
const FPS = 30;
const SECONDS = 6;
const fwd: Vec3 = [0, 0, 1];

/** 0 before `a`, 1 after `b`, smooth between. */
function ease(t: number, a: number, b: number): number {
  const u = Math.min(1, Math.max(0, (t - a) / (b - a)));
  return u * u * (3 - 2 * u);
}

export function characterClips(joints: readonly JointDef[]): ClipDef[] {
  const joint = (name: string): JointDef => {
    const j = joints.find((x) => x.name === P + name);
    if (!j) throw new Error(`character clips: no joint ${name}`);
    return j;
  };
  const dir = (name: string): Vec3 => normalize(sub(joint(name).tail, joint(name).head));
  /** Turns bone `name` towards `towards` (armature coordinates, across the bone) by `degrees`. */
  const bend = (name: string, towards: Vec3, degrees: number): Quat => turnAbout(cross(dir(name), towards), degrees);
  const twist = (name: string, degrees: number): Quat => turnAbout(dir(name), degrees);
  /** The turn that points bone `name` along `to` (the smallest one), eased in by `w`. */
  const aim = (name: string, to: Vec3, w: number): Quat => {
    const d = dir(name);
    return between(d, normalize(add(scale(d, 1 - w), scale(normalize(to), w))));
  };

  /** The relaxed stance at weight w (0: T-pose): arms down and a little forward, elbows bent 20 degrees. */
  const stance = (w: number, turns: Record<string, Quat> = {}): Record<string, Quat> => {
    for (const s of ['Left', 'Right']) {
      const side = s === 'Left' ? 1 : -1;
      turns[P + `${s}Arm`] ??= aim(`${s}Arm`, [0.25 * side, -1, 0.15], w);
      turns[P + `${s}ForeArm`] ??= bend(`${s}ForeArm`, fwd, 20 * w);
    }
    return turns;
  };

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
  ];
}
