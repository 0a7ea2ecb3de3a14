// A ball joint's swing plane where its swing is 0. The XZX angles of a bone (twist a0 about the
// bone, swing a1 about z, twist a2) lose a degree of freedom at a1 = 0: a0 and a2 then both turn
// the bone about itself, and a0 alone decides which way a swing of a1 moves it. A humanoid's
// T-pose has the upper arms there, their plane wherever the angles' zero puts it; when the first
// tracked frame asked the hands down, no angle lowered them at first order, so the solves lowered
// them with the clavicles and the spine until the clavicles met their limits and the arms took
// over in one frame (a jolt of the whole upper body, the track experiment's worst frames on every
// clip). At a1 = 0, a0 + c and a2 - c give the same rotation for any c: the plane is chosen from
// the target before the solve that leaves the T-pose, and, while the arm leaves it, chosen again
// until the swing is SEAT_SWING_DEG: a tracker's noise on the first frames does not decide it. No
// three.js; angles in degrees, rig units.
import type { IkRig } from '../ik/rig.js';

/**
 * The swing the slopes are measured with, degrees: small beside how far a frame's target moves
 * (a frame's first move from the T-pose is a fraction of a millimetre).
 */
const TRIAL_SWING_DEG = 1e-3;
/**
 * A swing this small (degrees) counts as 0: the first solves from the rest pose move the angles a
 * little (a tracked frame given to 1e-8 of a unit), and turning the plane of so small a swing
 * turns the bone by at most twice that.
 */
const ZERO_SWING_DEG = 1e-3;
/**
 * While an arm leaves the rest pose, its plane is chosen again at every frame until its swing is
 * this large (degrees): the swing keeps its size and takes the new plane's way towards the target
 * (the bone turns by at most twice the swing, towards the target). The first frames that leave the
 * T-pose move a hand a fraction of a millimetre, less than a tracker's noise: chosen from the first
 * frame alone, the plane followed the noise, and on the project's clips tracked with noise of up to
 * 0.05% of the height on each coordinate the arms twisted into their limits within 22 frames, every
 * later frame missed (4 of 6 noise draws on each clip). By 3 degrees the character's hand is about
 * 2.6 cm from where the zero swing holds it.
 */
export const SEAT_SWING_DEG = 3;
/**
 * A swing under way whose plane brings the hand towards the target at this share of the best
 * plane's rate or more (its plane within about 8 degrees of the best) keeps its plane: turned to
 * the best at every frame, the small turns of a plane the solves were following cost a hand 1.5 δ
 * on the arms' fall from the T-pose (tests/avatar).
 */
const KEEP_SHARE = 0.99;
/**
 * A target too near to show a way weighs each way by its room, up to this many degrees (90 makes a
 * hand hang): seated by the noise the short way (the upper arm's a1 stops at -45 and goes to 130),
 * an arm kept that way when the other plane moved the hand as fast met its limit (2 draws of 10 on
 * every clip). Weighed so for every target, ten avatars whose first frame asks an arbitrary pose
 * (tests/browser/avatars.test.ts) took the long way where their motion took the short one, and
 * one stayed off target for 34 frames (48 of 240 frames over 2 ms).
 */
const ROOM_DEG = 90;
/** The target must be this many trial swings' moves away: nearer, the slopes are round-off. */
const NEAR_TRIALS = 10;

/** Radians per degree. */
const RAD = Math.PI / 180;

const scratch = {
  trial: new Float64Array(0),
  tips: new Float64Array(0),
  at: new Float64Array(3),
  towards: new Float64Array(3),
  /** How far the last trial swing moved the tip (rig units). */
  step: 0,
};

/**
 * Turns the swing plane of `bone` of `rig` in `angles` (3 per bone, degrees; the pose) when its
 * swing a1 is 0 (within ZERO_SWING_DEG), keeping its rotation (a1 and a0 + a2 unchanged, a0 and a2
 * within their limits): to the plane in which a swing its limits allow brings effector
 * `effector`'s tip fastest towards `target` (rig units); a target nearer than a swing of
 * SEAT_SWING_DEG takes the tip weighs each way by its room (up to ROOM_DEG). Left as it is when no
 * swing does. With `leaving` (the arm has not yet swung SEAT_SWING_DEG since the rest pose), a
 * swing smaller than that is turned too, from where the swing 0 puts the tip, unless its plane is
 * nearly the best (KEEP_SHARE). Three forward passes: the slope towards the target of a swing in
 * plane a0 is A cos a0 + B sin a0. No allocation (it runs every frame, most often to its first
 * test).
 */
export function seatSwingPlane(
  rig: IkRig,
  angles: Float64Array,
  bone: number,
  effector: number,
  target: ArrayLike<number>,
  leaving = false,
): void {
  const j = 3 * bone;
  const swing = angles[j + 1];
  if (!(Math.abs(swing) <= (leaving ? SEAT_SWING_DEG : ZERO_SWING_DEG))) return;
  const twist = angles[j] + angles[j + 2];
  // a0 within its limits with a2 = twist - a0 within its own.
  const lo = Math.max(rig.lower[j], twist - rig.upper[j + 2]),
    hi = Math.min(rig.upper[j], twist - rig.lower[j + 2]);
  const upRoom = rig.upper[j + 1],
    downRoom = -rig.lower[j + 1];
  if (!(lo < hi) || !(upRoom > 0 || downRoom > 0)) return;
  // Scratch arrays, reused: the seating runs on the frames that leave the T-pose, too few for V8 to
  // optimise it, where each allocation and array method costs (over its first 100 calls a call
  // took 86 us with slice(), map() and spreads, 60 without).
  if (scratch.trial.length !== angles.length) scratch.trial = new Float64Array(angles.length);
  if (scratch.tips.length !== 3 * rig.numEffectors) scratch.tips = new Float64Array(3 * rig.numEffectors);
  const { trial, tips, at, towards } = scratch;
  trial.set(angles);
  trial[j + 1] = 0;
  const e = 3 * effector;
  rig.tips(trial, tips);
  for (let i = 0; i < 3; i++) {
    at[i] = tips[e + i];
    towards[i] = target[i] - at[i];
  }
  const p = lo,
    q = lo + Math.min(90, hi - lo);
  const sp = swingSlope(rig, j, e, twist, p),
    sq = swingSlope(rig, j, e, twist, q);
  const far = Math.hypot(towards[0], towards[1], towards[2]);
  if (!(far > NEAR_TRIALS * scratch.step)) return;
  // Each way's weight: 1 where the limits allow a swing that way (else 0); a target nearer than a
  // swing of SEAT_SWING_DEG would take the tip shows no way yet: each way then weighs its room.
  const near = far < (SEAT_SWING_DEG / TRIAL_SWING_DEG) * scratch.step;
  const room = (r: number) => (r > 0 ? (near ? Math.min(ROOM_DEG, r) / ROOM_DEG : 1) : 0);
  const up = room(upRoom),
    down = room(downRoom);
  // A cos a + B sin a through (p, sp) and (q, sq).
  const det = Math.sin((q - p) * RAD);
  const A = (sp * Math.sin(q * RAD) - sq * Math.sin(p * RAD)) / det,
    B = (sq * Math.cos(p * RAD) - sp * Math.cos(q * RAD)) / det;
  const peak = Math.atan2(B, A) / RAD;
  let best = angles[j],
    bestScore = planeScore(A, B, up, down, best);
  const current = bestScore;
  // The limits, then the peak's turns within them.
  for (let c = 0; c < 7; c++) {
    const a0 = c === 0 ? lo : c === 1 ? hi : Math.min(hi, Math.max(lo, peak + 180 * (c - 4)));
    const score = planeScore(A, B, up, down, a0);
    if (score > bestScore) {
      bestScore = score;
      best = a0;
    }
  }
  if (swing !== 0 && !(current < KEEP_SHARE * bestScore)) return;
  angles[j] = best;
  angles[j + 2] = twist - best;
  if (swing === 0) return;
  // The swing under way, its size kept, the way its new plane's score took.
  const slope = A * Math.cos(best * RAD) + B * Math.sin(best * RAD);
  const way = slope * up >= -slope * down ? 1 : -1;
  angles[j + 1] = Math.min(rig.upper[j + 1], Math.max(rig.lower[j + 1], way * Math.abs(swing)));
}

/**
 * The slope towards scratch.towards of a swing of TRIAL_SWING_DEG of the bone whose angles start
 * at `j` in plane `a0` (degrees; a2 = `twist` - a0), from scratch.trial's pose; writes how far it
 * moved effector tip `e` (its first number's index) into scratch.step.
 */
function swingSlope(rig: IkRig, j: number, e: number, twist: number, a0: number): number {
  const { trial, tips, at, towards } = scratch;
  trial[j] = a0;
  trial[j + 1] = TRIAL_SWING_DEG;
  trial[j + 2] = twist - a0;
  rig.tips(trial, tips);
  const m0 = tips[e] - at[0],
    m1 = tips[e + 1] - at[1],
    m2 = tips[e + 2] - at[2];
  scratch.step = Math.hypot(m0, m1, m2);
  return towards[0] * m0 + towards[1] * m1 + towards[2] * m2;
}

/**
 * How fast a swing in plane a0 (degrees) moves the tip towards the target, the positive way weighed
 * by `up` and the negative by `down` (each its room's share, 0..1).
 */
function planeScore(A: number, B: number, up: number, down: number, a0: number): number {
  const s = A * Math.cos(a0 * RAD) + B * Math.sin(a0 * RAD);
  return Math.max(up * s, -down * s, 0);
}
