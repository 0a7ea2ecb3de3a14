// turn_in_place (7 s): from the T-pose into the stance over the first second, then the character
// turns 180 degrees to its left in place: the hips dip 3 cm (the knees soften), the feet step round
// (turn_steps.ts) while the hips and the whole body turn with them, the hips come back up and it
// stands, facing back. Degrees; armature centimetres; seconds.
import { type Body, KEY_TOLERANCE, P, ease } from './character_body.js';
import { type ClipDef, turnAbout } from './clips.js';
import { type Hips, plantLegs } from './planted_legs.js';
import { TURN_SECONDS, stepping } from './turn_steps.js';

/** When the first step begins (the hips have dipped by then), and how far the hips dip (cm). */
const START = 1.3;
const DIP = 3;

export function turnInPlace(body: Body): ClipDef {
  return {
    name: 'turn_in_place',
    seconds: 7,
    fps: 30,
    tolerance: KEY_TOLERANCE,
    pose: (t) => {
      const step = stepping(t - START);
      const dip = DIP * (ease(t, 1, START) - ease(t, START + TURN_SECONDS, START + TURN_SECONDS + 0.5));
      const hips: Hips = { turn: turnAbout([0, 1, 0], step.yaw), shift: [0, -dip, 0] };
      const turns = body.stance(ease(t, 0, 1), { [P + 'Hips']: hips.turn });
      // The first frame is the rest pose itself (whose knees bend 1e-4 rad outwards, the closed form's forwards).
      if (t > 0) plantLegs(body, hips, step.feet, turns);
      return { turns, shift: hips.shift };
    },
  };
}
