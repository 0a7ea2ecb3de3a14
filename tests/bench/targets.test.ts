// Target sets against PROTOCOL.md: limits, step sizes, reachability by construction, starts, and
// the drag experiment's pinned effectors. FK is checked with the reference composition in plain JS.
import { createHash } from 'node:crypto';

import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { draggableEffectors, exclusiveAngles } from '../../bench-node/effectors.js';
import { independentRanges, prefix, type Experiment, type TargetSet } from '../../bench-node/target_set.js';
import { DRAG_PATH_STEPS, generateTargets, INCREMENTAL_STEP_DEG } from '../../bench-node/targets.js';
import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import { loadTestRig, maxAbsDiff, referenceTips, rigsLike, testRigs, type TestRig } from '../helpers/a7.js';
import { sketchRig } from '../../scripts/rig_files/rig_builder.js';

let ik: IkCoreModule;
const rigs: IkRig[] = [];

beforeAll(async () => {
  ik = await loadIkNode();
});
afterAll(() => rigs.forEach((r) => r.dispose()));

function setOf(testRig: TestRig, experiment: Experiment, count: number, seed = 7): { spec: RigSpec; set: TargetSet } {
  const spec = loadTestRig(testRig);
  const rig = new IkRig(ik, spec);
  rigs.push(rig);
  return { spec, set: generateTargets(spec, experiment, count, seed, (a) => rig.tips(a)) };
}

const row = (a: Float64Array, k: number, width: number): Float64Array => a.subarray(k * width, (k + 1) * width);

function expectInsideLimits(spec: RigSpec, angles: Float64Array): void {
  const m = spec.lower.length;
  expect(angles.filter((a, i) => !(a >= spec.lower[i % m] && a <= spec.upper[i % m]))).toEqual(new Float64Array(0));
}

function expectReachable(spec: RigSpec, set: TargetSet): void {
  const m = set.numAngles,
    r = set.numResiduals;
  expect(set.reachable.every((v) => v === 1)).toBe(true);
  for (let k = 0; k < set.count; k++) {
    const x = referenceTips(spec, row(set.targetAngles!, k, m));
    expect(maxAbsDiff(x, row(set.targets, k, r))).toBeLessThan(1e-9 * Math.max(1, ...Array.from(x, Math.abs)));
  }
}

describe.each(testRigs)('$label', (testRig) => {
  it('random: A_k = P(360 U(-1,1)) inside the limits, x_b = x(A_k), starts at the rest pose', () => {
    const { spec, set } = setOf(testRig, 'random', 40);
    expectInsideLimits(spec, set.targetAngles!);
    expectReachable(spec, set);
    const rest = Float64Array.from(spec.lower, (lo, i) => Math.min(spec.upper[i], Math.max(lo, 0)));
    for (let k = 0; k < set.count; k++) expect(Array.from(row(set.starts, k, set.numAngles))).toEqual(Array.from(rest));
    expect(set.chained.every((c) => c === 0)).toBe(true);
    // The draws span the limits: some angle of a wide joint reaches far from 0.
    expect(Math.max(...Array.from(set.targetAngles!, Math.abs))).toBeGreaterThan(20);
  });

  it('incremental: steps of at most 5 degrees per angle, start k = A_(k-1), A_0 = rest', () => {
    const { spec, set } = setOf(testRig, 'incremental', 200);
    const m = set.numAngles;
    expectInsideLimits(spec, set.targetAngles!);
    expectReachable(spec, set);
    expect(Array.from(row(set.starts, 0, m))).toEqual(
      Array.from(spec.lower, (lo, i) => Math.min(spec.upper[i], Math.max(lo, 0))),
    );
    let largest = 0;
    for (let k = 1; k < set.count; k++) {
      expect(Array.from(row(set.starts, k, m))).toEqual(Array.from(row(set.targetAngles!, k - 1, m)));
      largest = Math.max(largest, maxAbsDiff(row(set.targetAngles!, k, m), row(set.starts, k, m)));
    }
    expect(largest).toBeLessThanOrEqual(INCREMENTAL_STEP_DEG);
    expect(largest).toBeGreaterThan(INCREMENTAL_STEP_DEG * 0.8);
  });

  it('drag: one effector moves along a path, every other target stays where it was', () => {
    const { spec, set } = setOf(testRig, 'drag', 2 * DRAG_PATH_STEPS + 5);
    const m = set.numAngles,
      r = set.numResiduals;
    expectInsideLimits(spec, set.targetAngles!);
    expectReachable(spec, set);
    const ranges = independentRanges(set);
    expect(ranges.map(([b, e]) => e - b)).toEqual([DRAG_PATH_STEPS, DRAG_PATH_STEPS, 5]);
    const exclusive = exclusiveAngles(spec);
    for (const [begin, end] of ranges) {
      const dragged = set.dragged[begin];
      expect(draggableEffectors(spec)).toContain(dragged);
      const base = referenceTips(spec, row(set.starts, begin, m));
      for (let k = begin; k < end; k++) {
        expect(set.dragged[k]).toBe(dragged);
        expect(set.chained[k]).toBe(k > begin ? 1 : 0);
        // Only the dragged effector's exclusive angles change, by at most 5 degrees a step.
        const a = row(set.targetAngles!, k, m),
          before = row(set.starts, k, m);
        for (let i = 0; i < m; i++) if (!exclusive[dragged].includes(i)) expect(a[i]).toBe(before[i]);
        expect(maxAbsDiff(a, before)).toBeLessThanOrEqual(INCREMENTAL_STEP_DEG);
        const x = row(set.targets, k, r);
        for (let e = 0; e < spec.effectors.length; e++)
          if (e !== dragged)
            expect(maxAbsDiff(x.subarray(3 * e, 3 * e + 3), base.subarray(3 * e, 3 * e + 3))).toBeLessThan(1e-9);
      }
      // The dragged effector does move.
      const first = row(set.targets, begin, r).subarray(3 * dragged, 3 * dragged + 3);
      const last = row(set.targets, end - 1, r).subarray(3 * dragged, 3 * dragged + 3);
      if (end - begin === DRAG_PATH_STEPS) expect(maxAbsDiff(first, last)).toBeGreaterThan(0);
    }
  });
});

describe('seeds', () => {
  it.each(rigsLike('knight'))('the same seed gives the same set; another seed another set ($label)', (knight) => {
    const a = setOf(knight, 'random', 10, 3).set;
    const b = setOf(knight, 'random', 10, 3).set;
    const c = setOf(knight, 'random', 10, 4).set;
    expect(Array.from(b.targets)).toEqual(Array.from(a.targets));
    expect(Array.from(c.targets)).not.toEqual(Array.from(a.targets));
  });

  it.each(rigsLike('beast'))(
    'a shorter run is a prefix of a longer one (a method with fewer samples gets the first ones) ($label)',
    (beast) => {
      for (const experiment of ['random', 'incremental', 'drag', 'reach'] as const) {
        const long = setOf(beast, experiment, 90).set;
        const short = setOf(beast, experiment, 50).set;
        const head = prefix(long, 50);
        expect(Array.from(short.targets)).toEqual(Array.from(head.targets));
        expect(Array.from(short.starts)).toEqual(Array.from(head.starts));
        expect(Array.from(short.chained)).toEqual(Array.from(head.chained));
      }
    },
  );

  it.each(rigsLike('knight'))(
    'each experiment has its own stream: random targets do not depend on which experiments run ($label)',
    (knight) => {
      // generateTargets takes no state but (spec, experiment, count, seed): generating another
      // experiment in between changes nothing.
      const first = setOf(knight, 'random', 10).set;
      setOf(knight, 'incremental', 10);
      const again = setOf(knight, 'random', 10).set;
      expect(Array.from(again.targets)).toEqual(Array.from(first.targets));
      expect(Array.from(setOf(knight, 'incremental', 10).set.targetAngles!)).not.toEqual(
        Array.from(first.targetAngles!),
      );
    },
  );

  it('seed 1 still gives the sets of the published benchmarks, bit for bit', () => {
    // A Y of two limbs with limits; digests of the angles only (starts, target angles) and the
    // path layout, so a change to forward kinematics does not show here but one to the draws does.
    const limb = { lower: [-90, -45, -120], upper: [90, 45, 120] } as const;
    const spec = sketchRig(
      [
        { parent: -1, at: [0, 0, 0], length: 1, lower: [0, 0, 0], upper: [0, 0, 0] },
        { parent: 0, at: [1, 0, 0], length: 1, lower: [...limb.lower], upper: [...limb.upper] },
        { parent: 1, at: [2, 0, 0], length: 0.5 },
        { parent: 0, at: [1, 0, 0], length: 1, lower: [...limb.lower], upper: [...limb.upper] },
        { parent: 3, at: [2, 0, 0], length: 0.5 },
      ],
      [2, 4],
    );
    const rig = new IkRig(ik, spec);
    rigs.push(rig);
    const digest = (experiment: Experiment): string => {
      const set = generateTargets(spec, experiment, 100, 1, (a) => rig.tips(a));
      const hash = createHash('sha256');
      for (const a of [set.starts, set.targetAngles ?? new Float64Array(0), set.chained, set.dragged])
        hash.update(new Uint8Array(a.buffer, a.byteOffset, a.byteLength));
      return hash.digest('hex').slice(0, 16);
    };
    expect(
      Object.fromEntries((['random', 'incremental', 'drag', 'reach'] as const).map((e) => [e, digest(e)])),
    ).toEqual({
      random: 'c5dbd27d98746dd5',
      incremental: '249a20d49fb849c7',
      drag: '6a58f98566cb9c20',
      reach: '35f32ed842ddf0ca',
    });
  });
});
