// Both legs in closed form under hips that move and turn, over feet that stand, step or are lifted
// (turn_in_place, stress): each leg in the plane of its hip-ankle line and the direction its knee
// points (law of cosines), each foot flat, turned about the vertical by its own yaw. The knee points
// over the toes, but at most KNEE_YAW from where the hips face (the hip turns its bend plane 10
// degrees at most); the shin twists the rest of the way to the foot (the knee twists 3 at most).
// Angles in degrees, lengths in armature centimetres.
import { type Body, P, fwd } from './character_body.js';
import { type Quat, between, inverse, mul, rotate, turnAbout } from './clips.js';
import { type Vec3, add, dot, length, normalize, scale, sub } from './vec.js';

export type Side = 'Left' | 'Right';
export const SIDES: readonly Side[] = ['Left', 'Right'];

const up: Vec3 = [0, 1, 0];
/** The knee points at most this far (degrees) from the hips' facing. */
const KNEE_YAW = 9;

/** The hips' motion: a turn about their rest head, then a shift (cm). */
export interface Hips {
  turn: Quat;
  shift: Vec3;
}

/** A foot's place: where it stands at rest, turned by `yaw` degrees about the vertical through the hips' rest head, raised `lift` cm. */
export interface Foot {
  yaw: number;
  lift: number;
}

/** Both feet where they stand at rest. */
export const STANDING: Readonly<Record<Side, Foot>> = { Left: { yaw: 0, lift: 0 }, Right: { yaw: 0, lift: 0 } };

/** Writes the turns of both legs (UpLeg, Leg, Foot) into `turns`; throws when a foot is beyond its leg's reach. */
export function plantLegs(
  body: Body,
  hips: Hips,
  feet: Readonly<Record<Side, Foot>>,
  turns: Record<string, Quat>,
): void {
  const pivot = body.joint('Hips').head;
  const facing = rotate(hips.turn, fwd),
    hipsYaw = (Math.atan2(facing[0], facing[2]) * 180) / Math.PI;
  for (const s of SIDES) {
    const yaw = turnAbout(up, feet[s].yaw);
    // The foot's yaw from the hips' (in -180..180), and the knee's.
    const off = ((feet[s].yaw - hipsYaw + 540) % 360) - 180,
      kneeOff = Math.max(-KNEE_YAW, Math.min(KNEE_YAW, off));
    const plane = turnAbout(up, hipsYaw + kneeOff);
    const hip0 = body.joint(`${s}UpLeg`).head,
      knee0 = body.joint(`${s}Leg`).head,
      ankle0 = body.joint(`${s}Foot`).head;
    const hip = add(add(pivot, rotate(hips.turn, sub(hip0, pivot))), hips.shift);
    const ankle = add(add(pivot, rotate(yaw, sub(ankle0, pivot))), [0, feet[s].lift, 0]);
    const l1 = length(sub(knee0, hip0)),
      l2 = length(sub(ankle0, knee0));
    const d = sub(ankle, hip),
      dist = length(d);
    if (dist >= l1 + l2)
      throw new Error(`character clips: the ${s} foot is ${dist} cm from its hip, beyond the leg's ${l1 + l2}`);
    const u = scale(d, 1 / dist),
      ahead = rotate(plane, fwd);
    const across = normalize(sub(ahead, scale(u, dot(ahead, u))));
    const cosA = (l1 * l1 + dist * dist - l2 * l2) / (2 * l1 * dist);
    const knee = add(hip, scale(add(scale(u, cosA), scale(across, Math.sqrt(1 - cosA * cosA))), l1));
    // World rotations: the thigh yawed to the leg's plane and swung onto its new direction; the
    // shin twisted on to the foot's yaw, then swung.
    const thigh = mul(between(rotate(plane, body.dir(`${s}UpLeg`)), sub(knee, hip)), plane);
    const shinAxis = rotate(thigh, body.dir(`${s}Leg`));
    const twisted = mul(turnAbout(shinAxis, off - kneeOff), thigh);
    const shin = mul(between(shinAxis, sub(ankle, knee)), twisted);
    turns[P + `${s}UpLeg`] = mul(inverse(hips.turn), thigh);
    turns[P + `${s}Leg`] = mul(inverse(thigh), shin);
    turns[P + `${s}Foot`] = mul(inverse(shin), yaw);
  }
}
