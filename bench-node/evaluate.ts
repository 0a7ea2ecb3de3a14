// E, tip distances, the on-target test, wobble and jumps from end-effector positions and angles,
// the same for every method and engine.
import { largestTipDistance } from '#ik/tip_distance.js';

/** E = 1/2 |tips - target|^2 (tips and target: 3 per end effector). */
export function errorOf(tips: ArrayLike<number>, target: ArrayLike<number>): number {
  let s = 0;
  for (let i = 0; i < target.length; i++) {
    const d = tips[i] - target[i];
    s += d * d;
  }
  return 0.5 * s;
}

/** The largest distance (rig units) of any end effector's tip from its target. */
export function tipDistance(tips: ArrayLike<number>, target: ArrayLike<number>): number {
  return largestTipDistance(tips, target);
}

/**
 * The largest distance of a pinned end effector (every effector but `dragged`) from its target.
 * NaN when nothing is pinned (no drag, or a single end effector).
 */
export function pinnedDeviation(tips: ArrayLike<number>, target: ArrayLike<number>, dragged: number): number {
  if (dragged < 0 || target.length < 6) return NaN;
  return largestTipDistance(tips, target, dragged);
}

/** What "on target" means in a run. */
export interface OnTargetTest {
  /** E threshold, rig units^2: the test when tipTolerance is 0. */
  errorTolerance: number;
  /** Rig units; > 0: every tip within this distance of its target (the solvers' tipTolerance). */
  tipTolerance: number;
  /** Degrees; set (--goals pose): also every effector's orientation within this angle of its target. */
  orientationToleranceDeg?: number;
}

/**
 * Whether a pose with error E (of the positions), largest tip distance `tip` (rig units) and
 * largest orientation error `rotationDeg` (degrees; read only when the test has an orientation
 * tolerance) is on target.
 */
export function isOnTarget(test: OnTargetTest, E: number, tip: number, rotationDeg = NaN): boolean {
  const position = test.tipTolerance > 0 ? tip < test.tipTolerance : E < test.errorTolerance;
  return test.orientationToleranceDeg === undefined ? position : position && rotationDeg < test.orientationToleranceDeg;
}

/**
 * The largest single-angle change from `from` to `to` (degrees, same lengths): a step's jump.
 * `lower`, `upper`: the angles' limits (degrees). An angle whose limits span a full turn or more
 * (upper - lower >= 360) changes the shortest way round, min(|d| mod 360, 360 - |d| mod 360): a
 * turn of 350 is one of 10 degrees the other way. A limited angle changes by |d|.
 */
export function largestChange(
  from: ArrayLike<number>,
  to: ArrayLike<number>,
  lower: ArrayLike<number>,
  upper: ArrayLike<number>,
): number {
  let worst = 0;
  for (let i = 0; i < from.length; i++) {
    const d = Math.abs(to[i] - from[i]);
    worst = Math.max(worst, upper[i] - lower[i] >= 360 ? shortestTurn(d) : d);
  }
  return worst;
}

/** The shortest turn (degrees, 0..180) equal to a turn of `d` degrees (d >= 0). */
export function shortestTurn(d: number): number {
  const r = d % 360;
  return Math.min(r, 360 - r);
}
