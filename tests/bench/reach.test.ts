// The reach experiment's paths (reach.ts) and the chain-root rule (effectors.ts), on rigs made here
// and on the report's A7 rigs; rest tips come from the reference composition in plain JS.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { chainRootBone, draggableEffectors } from '../../bench-node/effectors.js';
import {
  orthonormalFrame,
  REACH_PATH_STEPS,
  REACH_SHARE,
  reachPaths,
  restBase,
  type Vec3,
} from '../../bench-node/reach.js';
import { independentRanges, project } from '../../bench-node/target_set.js';
import { generateTargets } from '../../bench-node/targets.js';
import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import { loadTestRig, maxAbsDiff, referenceTips, seeded, testRigs } from '../helpers/a7.js';
import { sketchRig, straightLimb } from '../../scripts/rig_files/rig_builder.js';

let ik: IkCoreModule;
const rigs: IkRig[] = [];
beforeAll(async () => {
  ik = await loadIkNode();
});
afterAll(() => rigs.forEach((r) => r.dispose()));

const dot = (a: ArrayLike<number>, b: ArrayLike<number>): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const norm = (a: ArrayLike<number>): number => Math.sqrt(dot(a, a));
const sub = (a: ArrayLike<number>, b: ArrayLike<number>): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];

/**
 * Bone 0 (root) has children 1 and 6; bone 1 has children 2, 4 and 7. Effectors: the tips of
 * 3 (the chain 2-3), 5 (4-5), 6 (a leaf under the root) and 7 (length 0: its tip is its base).
 */
function branchedRig(): RigSpec {
  return sketchRig(
    [
      { parent: -1, at: [0, 0, 0], length: 1 },
      { parent: 0, at: [1, 0, 0], length: 1 },
      { parent: 1, at: [2, 0, 0], length: 1 },
      { parent: 2, at: [3, 0, 0], length: 1 },
      { parent: 1, at: [2, 1, 0], length: 1 },
      { parent: 4, at: [3, 1, 0], length: 0.5 },
      { parent: 0, at: [0, -1, 0], length: 1 },
      { parent: 1, at: [2, 2, 0], length: 0 },
    ],
    [3, 5, 6, 7],
  );
}

describe('chain root', () => {
  it('walks up from the effector bone while the parent has exactly one child', () => {
    const spec = branchedRig();
    expect(chainRootBone(spec, 3)).toBe(2);
    expect(chainRootBone(spec, 5)).toBe(4);
    expect(chainRootBone(spec, 6)).toBe(6); // its parent branches: the bone itself
    expect(chainRootBone(spec, 1)).toBe(1);
    expect(chainRootBone(straightLimb(), 1)).toBe(0); // no branch: up to the root
  });

  it('the chain root point is the base of that bone at rest (its rest translation)', () => {
    const spec = branchedRig();
    expect(restBase(spec, 4)).toEqual([2, 1, 0]);
    expect(restBase(spec, chainRootBone(spec, 3))).toEqual([2, 0, 0]);
  });

  it('paths start towards the chain root point; an effector whose tip lies on it has none', () => {
    const spec = branchedRig();
    const tips = referenceTips(spec, new Float64Array(spec.lower.length));
    const paths = reachPaths(spec, tips);
    expect(draggableEffectors(spec)).toEqual([0, 1, 2, 3]);
    expect(paths.map((p) => p.effector)).toEqual([0, 0, 0, 1, 1, 1, 2, 2, 2]);
    // Effector 0: tip (4, 0, 0), chain root point (2, 0, 0).
    expect(paths[0].direction).toEqual([-1, 0, 0]);
    expect(paths[0].length).toBeCloseTo(REACH_SHARE * 2, 14);
    // Effector 1: tip (3.5, 1, 0), chain root point (2, 1, 0).
    expect(paths[3].length).toBeCloseTo(REACH_SHARE * 1.5, 14);
  });
});

describe('orthonormal frame', () => {
  it('the first vector is d normalised; the three are orthonormal and right-handed', () => {
    const rand = seeded(3);
    for (let i = 0; i < 200; i++) {
      const d: Vec3 = [rand() - 0.5, rand() - 0.5, i % 10 === 0 ? 0 : rand() - 0.5];
      const [u, v, w] = orthonormalFrame(d);
      expect(
        maxAbsDiff(
          u,
          d.map((x) => x / norm(d)),
        ),
      ).toBeLessThan(1e-15);
      for (const x of [u, v, w]) expect(norm(x)).toBeCloseTo(1, 14);
      expect(Math.abs(dot(u, v)) + Math.abs(dot(u, w)) + Math.abs(dot(v, w))).toBeLessThan(1e-14);
      const cross = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
      expect(maxAbsDiff(cross, w)).toBeLessThan(1e-15);
    }
    expect(orthonormalFrame([-2, 0, 0])).toEqual([
      [-1, 0, 0],
      [0, 1, 0],
      [0, 0, -1],
    ]);
  });
});

describe.each(testRigs)('reach on $label', (testRig) => {
  it('3 straight paths of 40 equal steps per draggable effector, from the rest pose, the others pinned', () => {
    const spec = loadTestRig(testRig);
    const rig = new IkRig(ik, spec);
    rigs.push(rig);
    const set = generateTargets(spec, 'reach', 100000, 1, (a) => rig.tips(a));
    const m = set.numAngles,
      r = set.numResiduals;
    const rest = project(spec, new Float64Array(m));
    const restTips = referenceTips(spec, rest);
    const scale = Math.max(1, ...Array.from(restTips, Math.abs));
    const draggable = draggableEffectors(spec);
    expect(set.count).toBe(3 * REACH_PATH_STEPS * draggable.length);
    expect(set.targetAngles).toBeNull();
    const ranges = independentRanges(set);
    expect(ranges.map(([b, e]) => e - b)).toEqual(new Array(3 * draggable.length).fill(REACH_PATH_STEPS));

    ranges.forEach(([begin, end], path) => {
      const effector = draggable[Math.floor(path / 3)];
      const tip = restTips.subarray(3 * effector, 3 * effector + 3);
      const toRoot = sub(restBase(spec, chainRootBone(spec, spec.effectors[effector])), tip);
      const moved = (k: number): Vec3 => sub(set.targets.subarray(k * r + 3 * effector, k * r + 3 * effector + 3), tip);
      const last = moved(end - 1);
      expect(norm(last)).toBeCloseTo(REACH_SHARE * norm(toRoot), 9);
      for (let k = begin; k < end; k++) {
        expect(set.dragged[k]).toBe(effector);
        expect(set.group[k]).toBe(path);
        expect(set.chained[k]).toBe(k > begin ? 1 : 0);
        expect(Array.from(set.starts.subarray(k * m, (k + 1) * m))).toEqual(Array.from(rest));
        // Equal steps on a straight line.
        const t = k - begin + 1;
        expect(
          maxAbsDiff(
            moved(k),
            last.map((x) => (x * t) / REACH_PATH_STEPS),
          ),
        ).toBeLessThan(1e-9 * scale);
        // Every other target stays at its rest tip.
        const target = set.targets.subarray(k * r, (k + 1) * r);
        for (let e = 0; e < spec.effectors.length; e++)
          if (e !== effector)
            expect(maxAbsDiff(target.subarray(3 * e, 3 * e + 3), restTips.subarray(3 * e, 3 * e + 3))).toBeLessThan(
              1e-9 * scale,
            );
      }
      if (path % 3 === 0) {
        // The first direction points at the chain root; the next two are perpendicular to it and to each other.
        const [towards, side, other] = [0, 1, 2].map((j) => moved(ranges[path + j][1] - 1));
        expect(dot(towards, toRoot) / (norm(towards) * norm(toRoot))).toBeCloseTo(1, 9);
        expect(Math.abs(dot(towards, side)) + Math.abs(dot(towards, other)) + Math.abs(dot(side, other))).toBeLessThan(
          1e-9 * scale ** 2,
        );
        expect(norm(side)).toBeCloseTo(norm(towards), 9);
        expect(norm(other)).toBeCloseTo(norm(towards), 9);
      }
    });
  });
});
