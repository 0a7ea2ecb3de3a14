// Turning 180 degrees to the left in place, by steps (turn_in_place, stress): the feet take turns,
// the left first, each step putting the foot 22.5 degrees past the other one (the last closes up),
// so a foot is never more than 11.25 degrees from the hips, which face midway between the feet
// (a leg twists 12 at most: 9 at the hip, 3 at the knee, planted_legs.ts). A step lifts the foot
// 8 cm, moves it round only while it is up, and puts it down. Degrees; cm; seconds.
import { ease } from './character_body.js';
import type { Foot, Side } from './planted_legs.js';

/** Each step: the foot and its yaw once put down. */
const STEPS: readonly [Side, number][] = [
  ['Left', 22.5],
  ['Right', 45],
  ['Left', 67.5],
  ['Right', 90],
  ['Left', 112.5],
  ['Right', 135],
  ['Left', 157.5],
  ['Right', 180],
  ['Left', 180],
];
const STEP_SECONDS = 0.5;
const LIFT = 8;
/** Within a step (0..1): the foot is up until UP_UNTIL and moves round between MOVE[0] and MOVE[1]. */
const UP_UNTIL = 0.8;
const MOVE = [0.15, 0.65] as const;

/** How long the turn takes. */
export const TURN_SECONDS = STEPS.length * STEP_SECONDS;

export interface Stepping {
  /** The hips' yaw: midway between the feet. */
  yaw: number;
  feet: Record<Side, Foot>;
}

/** The feet and the hips' yaw `t` seconds into the turn (0 before it, 180 after). */
export function stepping(t: number): Stepping {
  const feet: Record<Side, Foot> = { Left: { yaw: 0, lift: 0 }, Right: { yaw: 0, lift: 0 } };
  STEPS.forEach(([side, to], k) => {
    const u = t / STEP_SECONDS - k;
    if (u <= 0) return;
    const from = feet[side].yaw;
    feet[side] = {
      yaw: from + (to - from) * ease(u, MOVE[0], MOVE[1]),
      lift: u < UP_UNTIL ? LIFT * Math.sin((Math.PI * u) / UP_UNTIL) : 0,
    };
  });
  return { yaw: (feet.Left.yaw + feet.Right.yaw) / 2, feet };
}
