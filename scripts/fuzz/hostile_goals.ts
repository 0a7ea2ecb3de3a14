// Goals past sane for solve(angles, goals): weights of 1e10..1e308 on goals, poles and stiffness
// (with a rest pull of the same size), thousands of poles, thousands of goal entries, positions at
// 1e150. Finite values within the documented ranges must be accepted or refused with a clear
// error; a solve that runs must stay clean and within its time budget.
import type { Goals } from '#ik/goals.js';
import type { ApiState } from './api_state.js';
import type { Acceptance } from './hostile_args.js';
import type { Rand } from './random.js';
import { randomAngles } from './random_rig.js';
import { referenceTips } from './result_checks.js';

export interface GoalsArg {
  value: Goals;
  text: string;
  accept: Acceptance;
  /** A rest pull to set (solver option restWeight) before the solve, so that stiffness acts. */
  restWeight?: number;
}

/** Weights far past any sane one, all finite (packGoals takes any finite weight >= 0). */
const HUGE_WEIGHTS = [1e10, 1e50, 1e100, 1e150, 1e200, 1e300, 1e308];

/** Positions (and pole points) this far out: their squares still fit a double, their sums may not. */
const FAR = 1e150;

/** Reachable tip positions of the rig's effectors, 3 per effector. */
function reachable(r: Rand, s: ApiState): Float64Array {
  return referenceTips(s.spec, randomAngles(r, s.spec));
}

/** One position goal per effector at `tips`, each with `extra` fields. */
function positionGoals(
  s: ApiState,
  tips: ArrayLike<number>,
  extra: (e: number) => Record<string, number> = () => ({}),
): Goals['effectors'] {
  return Array.from(s.spec.effectors, (bone, e) => ({
    bone,
    position: [tips[3 * e], tips[3 * e + 1], tips[3 * e + 2]],
    ...extra(e),
  }));
}

/** Bones that have a parent (a pole needs one), or none on a one-bone rig. */
function limbBones(s: ApiState): number[] {
  return [...s.spec.parents.keys()].filter((b) => s.spec.parents[b] >= 0);
}

function randomPoles(r: Rand, s: ApiState, count: number, weight: () => number): NonNullable<Goals['poles']> {
  const bones = limbBones(s);
  return Array.from({ length: bones.length ? count : 0 }, () => ({
    bone: r.pick(bones),
    point: [r.range(-3, 3), r.range(-3, 3), r.range(-3, 3)],
    weight: weight(),
  }));
}

/** A goals argument past sane for the rig and solver of `s`. */
export function goalsArg(r: Rand, s: ApiState): GoalsArg {
  return r.weighted<() => GoalsArg>([
    [
      3,
      () => {
        const w = r.pick(HUGE_WEIGHTS);
        const key = r.pick(['weight', 'positionWeight']);
        return {
          value: { effectors: positionGoals(s, reachable(r, s), () => ({ [key]: w })) },
          text: `every goal's ${key} ${w}`,
          accept: 'must',
        };
      },
    ],
    [
      2,
      () => {
        const w = r.pick(HUGE_WEIGHTS);
        const effectors = positionGoals(s, reachable(r, s), (e): Record<string, number> =>
          e === 0 ? { weight: w } : {},
        );
        return { value: { effectors }, text: `the first goal's weight ${w}, the others 1`, accept: 'must' };
      },
    ],
    [
      2,
      () => {
        const w = r.pick(HUGE_WEIGHTS);
        const effectors = positionGoals(s, reachable(r, s)).map((g) => ({
          ...g,
          orientation: [0, 0, 0, 1],
          orientationWeight: w,
        }));
        return { value: { effectors }, text: `orientation goals of weight ${w}`, accept: 'must' };
      },
    ],
    [
      3,
      () => {
        const count = r.pick([64, 65, 1000, 20_000]); // the core takes 64 (kMaxPoles)
        const poles = randomPoles(r, s, count, () => 1);
        // A pole cap may refuse them with a clear error; a solve that runs must be clean and in budget.
        return {
          value: { effectors: positionGoals(s, reachable(r, s)), poles },
          text: `${poles.length} poles`,
          accept: 'either',
        };
      },
    ],
    [
      2,
      () => {
        const w = r.pick(HUGE_WEIGHTS);
        const poles = randomPoles(r, s, r.intIn(1, 4), () => w);
        return {
          value: { effectors: positionGoals(s, reachable(r, s)), poles },
          text: `${poles.length} poles of weight ${w}`,
          accept: 'must',
        };
      },
    ],
    [
      3,
      () => {
        const factor = r.pick(HUGE_WEIGHTS),
          restWeight = r.pick([1, ...HUGE_WEIGHTS]);
        const stiffness = Object.fromEntries(s.spec.names!.filter(() => r.chance(0.5)).map((name) => [name, factor]));
        return {
          value: { effectors: positionGoals(s, reachable(r, s)), stiffness },
          text: `stiffness ${factor} on ${Object.keys(stiffness).length} bones, restWeight ${restWeight}`,
          accept: 'must',
          restWeight,
        };
      },
    ],
    [
      2,
      () => {
        const count = r.pick([1000, 5000, 100_000]);
        const effectors = Array.from({ length: count }, (_, k) => ({
          bone: s.spec.effectors[k % s.spec.effectors.length],
          position: [0, 0, 0],
        }));
        return {
          value: { effectors },
          text: `${count} goal entries on ${s.spec.effectors.length} effectors`,
          accept: 'mustNot',
        };
      },
    ],
    [
      2,
      () => {
        const sign = () => (r.chance(0.5) ? FAR : -FAR);
        const far = Array.from({ length: 3 * s.spec.effectors.length }, sign);
        const poles = r.chance(0.5)
          ? randomPoles(r, s, 2, () => 1).map((p) => ({ ...p, point: [sign(), sign(), sign()] }))
          : undefined;
        return {
          value: { effectors: positionGoals(s, far), ...(poles && { poles }) },
          text: `goal positions${poles ? ' and pole points' : ''} at +-${FAR}`,
          accept: 'either',
        };
      },
    ],
  ])();
}
