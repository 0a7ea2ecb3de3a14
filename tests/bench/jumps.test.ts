// Jumps by where the joints go (jumps.ts, step_measures.ts) and jump_max_deg taken the shortest
// way round for angles without limits (evaluate.ts largestChange): on hand-made poses of a
// two-bone limb of size 1, so that a share of the rig size is a length.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { largestChange } from '../../bench-node/evaluate.js';
import { countJumps, draggedTargetMoves, isJump, jointPositions } from '../../bench-node/jumps.js';
import { summarize, type SolveResult } from '../../bench-node/metrics.js';
import { REACH_PATH_STEPS } from '../../bench-node/reach.js';
import { runNative } from '../../bench-node/run_native.js';
import { StepMeasurer } from '../../bench-node/step_measures.js';
import { generateTargets } from '../../bench-node/targets.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { rigSize } from '../../web/src/rig/tolerances.js';
import { loadTestRig, maxAbsDiff, rigsLike } from '../helpers/a7.js';
import { straightLimb } from '../../scripts/rig_files/rig_builder.js';

const ik = await loadIkNode();
// Two bones of length 1 along +x from the origin: tips (1,0,0) and (2,0,0) at rest, size 1.
const limb = straightLimb();
let rig: IkRig;
beforeAll(() => {
  rig = new IkRig(ik, limb);
});
afterAll(() => rig.dispose());

/** The lower bone turned by `deg` about its joint (the middle XZX angle, about z). */
const bent = (deg: number): Float64Array => Float64Array.of(0, 0, 0, 0, deg, 0);
/** The angle (degrees) that moves the lower bone's tip (length 1) by `chord`. */
const turnFor = (chord: number): number => (2 * Math.asin(chord / 2) * 180) / Math.PI;

describe('joint positions', () => {
  it('are every bone head and tip, as the core poses them', () => {
    const angles = Float64Array.of(10, 20, 30, -40, 50, 60);
    const joints = jointPositions(limb, rig.poses(angles));
    const tips = rig.boneTips(angles);
    expect(maxAbsDiff(joints.subarray(3, 6), tips.subarray(0, 3))).toBeLessThan(1e-12);
    expect(maxAbsDiff(joints.subarray(9, 12), tips.subarray(3, 6))).toBeLessThan(1e-12);
    expect(maxAbsDiff(joints.subarray(0, 3), [0, 0, 0])).toBeLessThan(1e-12); // the root's head stays
    expect(maxAbsDiff(joints.subarray(6, 9), tips.subarray(0, 3))).toBeLessThan(1e-12); // head of 1 = tip of 0
  });
});

describe('a jump', () => {
  const measurer = (): StepMeasurer => new StepMeasurer(limb, rig, []);

  it('is a joint moving more than 5% of the rig size while the target moved less than 1%', () => {
    expect(rigSize(rig.boneTips(new Float64Array(6)))).toBeCloseTo(1, 12);
    const m = measurer();
    const six = m.measure(bent(0), bent(turnFor(0.06))).jointMove;
    const four = m.measure(bent(0), bent(turnFor(0.04))).jointMove;
    expect(six).toBeCloseTo(0.06, 12);
    expect(four).toBeCloseTo(0.04, 12);
    expect(isJump(six, 0.005, 1)).toBe(true); // joint 6%, target 0.5%
    expect(isJump(four, 0.005, 1)).toBe(false); // joint 4%
    expect(isJump(six, 0.02, 1)).toBe(false); // target 2%: the joint may follow it
    expect(isJump(six, NaN, 1)).toBe(false); // nothing dragged
    // The rule scales with the rig: the same moves on a rig of size 2 are no jump.
    expect(isJump(six, 0.005, 2)).toBe(false);
    expect(m.measure(bent(0), bent(0)).flip).toBeNaN(); // no limbs given: flips not measured
  });

  it('is counted per step in the row: jumps', () => {
    const m = measurer();
    const steps: [number, number][] = [
      [0.06, 0.005],
      [0.04, 0.005],
      [0.06, 0.02],
      [0.08, 0.001],
    ];
    const results: SolveResult[] = steps.map(([chord]) => ({
      E: 0,
      tipDistance: 0,
      iterations: 1,
      seconds: 1e-5,
      stopReason: 'converged_E',
      wobbleDuring: NaN,
      wobbleAfter: NaN,
      jumpDeg: 0,
      jointMove: m.measure(bent(0), bent(turnFor(chord))).jointMove,
    }));
    const targetMoves = steps.map(([, target]) => target);
    expect(
      countJumps(
        results.map((r) => r.jointMove!),
        targetMoves,
        1,
      ),
    ).toBe(2);
    const test = { errorTolerance: 1, tipTolerance: 0.001 };
    const key = { rig: 'limb', method: 'lm', engine: 'wasm' };
    const reachable = new Uint8Array(4).fill(1);
    expect(summarize({ ...key, experiment: 'reach' }, results, test, reachable, { targetMoves, size: 1 }).jumps).toBe(
      2,
    );
    expect(
      summarize({ ...key, experiment: 'random' }, results, test, reachable, { targetMoves, size: 1 }).jumps,
    ).toBeNull();
    expect(summarize({ ...key, experiment: 'drag' }, results, test, reachable).jumps).toBeNull(); // no rule: not measured
  });

  it("measures the dragged target's move from the previous step's target, the first from the tip at the start", () => {
    const set = generateTargets(limb, 'reach', 1000, 1, (a) => rig.tips(a));
    const moves = draggedTargetMoves(set, (a) => rig.tips(a));
    // Reach paths: 40 equal steps of 40% of the distance from the tip (2, 0, 0) to the root (0, 0, 0).
    expect(set.count).toBe(3 * REACH_PATH_STEPS);
    for (let k = 0; k < set.count; k++) expect(moves[k], `step ${k}`).toBeCloseTo((0.4 * 2) / REACH_PATH_STEPS, 12);
    // Steps that drag nothing have no move.
    const random = generateTargets(limb, 'random', 3, 1, (a) => rig.tips(a));
    expect(Array.from(draggedTargetMoves(random, (a) => rig.tips(a)))).toEqual([NaN, NaN, NaN]);
  });
});

describe('jump_max_deg', () => {
  const free = { lower: [-180, -180], upper: [180, 180] };
  it('takes an angle without limits the shortest way round, modulo 360', () => {
    expect(largestChange([170, 0], [-170, 0], free.lower, free.upper)).toBeCloseTo(20, 12);
    expect(largestChange([0, 5], [0, 5 + 730], [-1000, -1000], [1000, 1000])).toBeCloseTo(10, 12);
    expect(largestChange([0, 0], [0, -181], [-360, -360], [0, 0])).toBeCloseTo(179, 12); // a span of exactly 360
    expect(largestChange([-90, 0], [90, 0], free.lower, free.upper)).toBe(180);
  });

  it('takes a limited angle (limits spanning less than 360) as it is', () => {
    expect(largestChange([170, 0], [-170, 0], [-175, -175], [175, 175])).toBe(340);
    expect(largestChange([0, 10], [0, -20], [-30, -30], [30, 30])).toBe(30);
  });
});

describe.each(rigsLike('knight'))('the native engine on $label', (knight) => {
  it('writes the joint move and the solution of each dragged step, as the step measures compute them', async () => {
    const spec = loadTestRig(knight);
    const core = new IkRig(ik, spec);
    try {
      const set = generateTargets(spec, 'reach', 12, 1, (a) => core.tips(a));
      const size = rigSize(core.boneTips(new Float64Array(core.numAngles)));
      const settings = {
        method: 'lm',
        gradientTolerance: 1e-9,
        errorTolerance: 2e-4,
        tipTolerance: 0.001 * size,
        timeBudgetSeconds: 0.2,
        paper: false,
        rigSize: size,
        restarts: 0,
      };
      const results = await runNative(spec, settings, set, 1, () => {});
      const measurer = new StepMeasurer(spec, core, []);
      let from: Float64Array = set.starts.slice(0, core.numAngles),
        largest = 0;
      for (const r of results) {
        expect(r.angles).toHaveLength(core.numAngles);
        expect(r.jointMove).toBeCloseTo(measurer.measure(from, r.angles!).jointMove, 9);
        largest = Math.max(largest, r.jointMove!);
        from = r.angles!;
      }
      expect(largest).toBeGreaterThan(0);
    } finally {
      core.dispose();
    }
  });
});
