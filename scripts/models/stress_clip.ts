// stress (21 s): what users of full-body IK in VR complain about, one segment after another, each
// easing in from the stance, holding, and easing back:
// - 1-3 s, hands behind the back: the arms turn in with the elbows straight, then the elbows bend
//   and the hands meet behind the back (the upper arms hang beside the body, not behind it: the
//   limits let an upper arm back only 45 degrees from the T-pose);
// - 3-5 s, hands over the head: the arms rise sideways, then the elbows bend and the hands meet
//   above the head;
// - 5-7 s, leaning 30 degrees forward: the hips tilt 12 and each of the three spine bones bends 6
//   (the chest turns 30), the hips go back 4 cm and down 1, the feet stay planted;
// - 7-9 s, leaning sideways to the left as far as the humanoid limits let the spine (12 degrees: a
//   spine bone bends sideways only by turning its bend plane, at most 15 degrees from straight
//   ahead, and a leg's hip by 10, so the hips cannot tilt over planted feet), the neck and head
//   adding theirs so the head tilts 30;
// - 9-10.6 s looking 60 degrees up (the neck and head 29 each, the upper spine 2), 10.6-12.2 s 60
//   down (the neck 25, the head 35);
// - 12.2-15 s, a crouch until the top of the head is at half the height: the hips go down 55 cm and
//   back 23 (most of it early, so that the shins never lean more than 28 degrees over the flat
//   feet: the ankles allow 30), tilting 10, the knees bend forward, the spine bends 45, the head
//   bows, the arms come forward;
// - 15-20.3 s, a 180-degree turn in place, the feet stepping (turn_steps.ts); then it stands.
// Degrees; armature centimetres; seconds.
import { type Body, KEY_TOLERANCE, P, ease, fwd } from './character_body.js';
import { type ClipDef, type Quat, mul, turnAbout } from './clips.js';
import { type Hips, plantLegs, SIDES } from './planted_legs.js';
import { TURN_SECONDS, stepping } from './turn_steps.js';
import { type Vec3, add, scale, sub } from './vec.js';

const UP: Vec3 = [0, 1, 0];
/** The character's left. */
const LEFT: Vec3 = [1, 0, 0];

/** 0 before `start`, easing to 1 over `ramp` seconds, held `hold` seconds, easing back to 0 over `ramp`. */
function segment(t: number, start: number, ramp: number, hold: number): number {
  return ease(t, start, start + ramp) - ease(t, start + ramp + hold, start + 2 * ramp + hold);
}

/** The left arm (the right is its mirror): the upper arm pointed along `to`, turned `twist` about itself, the elbow bent `elbow`. */
interface Arm {
  to: Vec3;
  twist: number;
  elbow: number;
}
const STANCE: Arm = { to: [0.25, -1, 0.15], twist: 0, elbow: 20 };
const BEHIND: Arm = { to: [0.34, -0.94, 0.02], twist: 125, elbow: 85 };
const OVER: Arm = { to: [0.2, 0.97, 0.1], twist: -90, elbow: 55 };
const FORWARD: Arm = { to: [0.2, -0.2, 1], twist: 0, elbow: 20 };

/**
 * Per trunk bone, its bend forward (negative: back) at the height of each segment, and in the
 * sideways lean its bend in its plane turned `plane` degrees to the left from straight ahead.
 */
const TRUNK: Record<
  string,
  { forward: number; crouch: number; up: number; down: number; side: number; plane: number }
> = {
  Spine: { forward: 6, crouch: 15, up: 0, down: 0, side: 25, plane: 14.5 },
  Spine1: { forward: 6, crouch: 15, up: 0, down: 0, side: -15, plane: -14.5 },
  Spine2: { forward: 6, crouch: 15, up: -2, down: 0, side: -10, plane: -14.5 },
  Neck: { forward: 0, crouch: 12.25, up: -29, down: 25, side: 20.5, plane: 24 },
  Head: { forward: -10, crouch: 12.25, up: -29, down: 35, side: -20.5, plane: -29 },
};

/** The hips in the forward lean and at the bottom of the crouch: tilt forward, and shift (cm). */
const LEAN_HIPS = { tilt: 12, shift: [0, -1, -4] as Vec3 };
const CROUCH_HIPS = { tilt: 10, down: 55, back: 23 };
/** How far the hips dip while the feet step round (cm), and when the turn begins. */
const DIP = 3;
const TURN_START = 15.3;

export function stressClip(body: Body): ClipDef {
  return {
    name: 'stress',
    seconds: 21,
    fps: 30,
    tolerance: KEY_TOLERANCE,
    pose: (t) => {
      const w = ease(t, 0, 1);
      const behind = segment(t, 1, 0.8, 0.4),
        over = segment(t, 3, 0.8, 0.4);
      const forward = segment(t, 5, 0.8, 0.4),
        sideways = segment(t, 7, 0.8, 0.4);
      const up = segment(t, 9, 0.6, 0.4),
        down = segment(t, 10.6, 0.6, 0.4),
        crouch = segment(t, 12.2, 1, 0.8);
      const step = stepping(t - TURN_START);
      const dip = DIP * (ease(t, 15, TURN_START) - ease(t, TURN_START + TURN_SECONDS, TURN_START + TURN_SECONDS + 0.5));

      const turns: Record<string, Quat> = {};
      const hips: Hips = {
        turn: mul(turnAbout(UP, step.yaw), turnAbout(LEFT, LEAN_HIPS.tilt * forward + CROUCH_HIPS.tilt * crouch)),
        shift: add(scale(LEAN_HIPS.shift, forward), [
          0,
          -CROUCH_HIPS.down * crouch - dip,
          -CROUCH_HIPS.back * crouch * (2 - crouch),
        ]),
      };
      turns[P + 'Hips'] = hips.turn;
      for (const [name, b] of Object.entries(TRUNK)) {
        const plane: Vec3 = [Math.sin((b.plane * Math.PI) / 180), 0, Math.cos((b.plane * Math.PI) / 180)];
        const ahead = b.forward * forward + b.crouch * crouch + b.up * up + b.down * down;
        turns[P + name] = mul(body.bend(name, fwd, ahead), body.bend(name, plane, b.side * sideways));
      }
      // Behind the back: first the arm turns in with the elbow straight, then the elbow bends. Over
      // the head: first the arm rises, then it turns and the elbow bends (turned while the arm is
      // low, it would twist past its limits).
      const turnIn = ease(behind, 0, 0.5),
        fold = ease(behind, 0.5, 1);
      const rise = ease(over, 0, 0.6),
        reach = ease(over, 0.4, 1);
      const toward = (arm: Arm, k: number): Vec3 => scale(sub(arm.to, STANCE.to), k);
      const arm: Arm = {
        to: add(add(STANCE.to, toward(BEHIND, turnIn)), add(toward(OVER, rise), toward(FORWARD, crouch))),
        twist: BEHIND.twist * turnIn + OVER.twist * reach,
        elbow: STANCE.elbow * (w - turnIn) + BEHIND.elbow * fold + (OVER.elbow - STANCE.elbow) * reach,
      };
      for (const s of SIDES) {
        const side = s === 'Left' ? 1 : -1;
        turns[P + `${s}Arm`] = mul(
          body.aim(`${s}Arm`, [side * arm.to[0], arm.to[1], arm.to[2]], w),
          body.twist(`${s}Arm`, side * arm.twist),
        );
        turns[P + `${s}ForeArm`] = body.bend(`${s}ForeArm`, fwd, arm.elbow);
      }
      // The first frame is the rest pose itself (whose knees bend 1e-4 rad outwards, the closed form's forwards).
      if (t > 0) plantLegs(body, hips, step.feet, turns);
      return { turns, shift: hips.shift };
    },
  };
}
