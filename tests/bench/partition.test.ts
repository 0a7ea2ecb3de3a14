// Every engine and worker count sees the same solves: batches cover the set in order without
// cutting a drag path, the native job file carries the exact numbers, and the rig written for the
// native engine reads back bit for bit.
import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { UNBOUNDED_DEG, writeA7Rig } from '../../web/src/rig/a7/a7_writer.js';
import { decodeResults, encodeJob } from '../../bench-node/run_native.js';
import { batchesOf } from '../../bench-node/run_wasm.js';
import { type TargetSet } from '../../bench-node/target_set.js';
import { generateTargets } from '../../bench-node/targets.js';
import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { parseA7Rig } from '../../web/src/rig/a7/a7_rig.js';
import { loadTestRig, rigsLike, testRigs } from '../helpers/a7.js';

let ik: IkCoreModule;
let rig: IkRig;
const sets: Record<string, TargetSet> = {};

// Batches and job files depend on the paths, not on the rig: the project's knight stands for all.
beforeAll(async () => {
  ik = await loadIkNode();
  const spec = loadTestRig(rigsLike('knight')[0]);
  rig = new IkRig(ik, spec);
  for (const e of ['random', 'incremental', 'drag', 'reach'] as const)
    sets[e] = generateTargets(spec, e, 130, 11, (a) => rig.tips(a));
});
afterAll(() => rig.dispose());

describe('batches', () => {
  it.each(['random', 'incremental', 'drag', 'reach'])(
    '%s: any batch count covers every sample once, in order, whole paths only',
    (e) => {
      const set = sets[e];
      for (let batches = 1; batches <= 40; batches++) {
        const parts = batchesOf(set, batches);
        expect(parts[0][0]).toBe(0);
        expect(parts[parts.length - 1][1]).toBe(set.count);
        for (let i = 1; i < parts.length; i++) expect(parts[i][0]).toBe(parts[i - 1][1]);
        for (const [begin, end] of parts) {
          expect(end).toBeGreaterThan(begin);
          expect(set.chained[begin]).toBe(0); // a batch never starts inside a drag or reach path
        }
      }
    },
  );
});

describe('native job file', () => {
  it('holds the chained flag, dragged effector, start and target of each sample exactly', () => {
    const set = sets.drag;
    const [begin, end] = [40, 95];
    const bytes = encodeJob(set, begin, end);
    expect(new TextDecoder().decode(bytes.subarray(0, 7))).toBe('IKBJOB1');
    const header = new DataView(bytes.buffer, 8, 16);
    const [count, m, r] = [0, 1, 2].map((i) => header.getInt32(4 * i, true));
    expect([count, m, r]).toEqual([end - begin, set.numAngles, set.numResiduals]);
    const body = new Float64Array(bytes.buffer.slice(24));
    const stride = 2 + m + r;
    for (let k = 0; k < count; k++) {
      const rec = body.subarray(k * stride, (k + 1) * stride);
      expect(rec[0]).toBe(k === 0 ? 0 : set.chained[begin + k]);
      expect(rec[1]).toBe(set.dragged[begin + k]);
      expect(Array.from(rec.subarray(2, 2 + m))).toEqual(
        Array.from(set.starts.subarray((begin + k) * m, (begin + k + 1) * m)),
      );
      expect(Array.from(rec.subarray(2 + m))).toEqual(
        Array.from(set.targets.subarray((begin + k) * r, (begin + k + 1) * r)),
      );
    }
  });

  it('results parse back, null as NaN', () => {
    const line = (fields: Record<string, unknown>): string =>
      JSON.stringify({ gradient_norm: 1, function_evaluations: 4, jacobian_evaluations: 2, ...fields });
    const text =
      line({
        E: 0.5,
        iterations: 3,
        seconds: 0.25,
        stop_reason: 'converged_E',
        wobble_during: null,
        wobble_after: null,
        tip_distance: 0.01,
        jump_deg: 2.5,
      }) +
      '\n' +
      line({
        E: 1e-5,
        iterations: 0,
        seconds: 1e-6,
        stop_reason: 'timeout',
        wobble_during: 0.1,
        wobble_after: 0.2,
        tip_distance: null,
        jump_deg: null,
      }) +
      '\n';
    const results = decodeResults(text, 2, 'x.jsonl');
    expect(results[0]).toMatchObject({
      E: 0.5,
      iterations: 3,
      seconds: 0.25,
      stopReason: 'converged_E',
      tipDistance: 0.01,
      jumpDeg: 2.5,
    });
    expect(results[0].wobbleDuring).toBeNaN();
    expect(results[1]).toMatchObject({ E: 1e-5, stopReason: 'timeout', wobbleDuring: 0.1, wobbleAfter: 0.2 });
    expect(results[1].tipDistance).toBeNaN();
    expect(results[1].jumpDeg).toBeNaN();
    expect(() => decodeResults(text, 3, 'x.jsonl')).toThrow(/2 results, expected 3/);
  });
});

describe('A7 writer', () => {
  // Bit for bit but for the sign of zero: JSON writes -0 as 0, which no clamp or product tells apart.
  const values = (a: ArrayLike<number>): number[] => Array.from(a, (x) => x + 0);

  it.each(testRigs)('$label reads back bit for bit', (testRig) => {
    const spec = loadTestRig(testRig);
    const back = parseA7Rig(writeA7Rig(spec), `${testRig.name}.json`);
    expect(Array.from(back.parents)).toEqual(Array.from(spec.parents));
    expect(values(back.rest)).toEqual(values(spec.rest));
    expect(values(back.lengths)).toEqual(values(spec.lengths));
    expect(values(back.lower)).toEqual(values(spec.lower));
    expect(values(back.upper)).toEqual(values(spec.upper));
    expect(Array.from(back.effectors)).toEqual(Array.from(spec.effectors));
  });

  it('unbounded limits: left out when a side is all unbounded, +-1e300 in a mix', () => {
    const spec = loadTestRig(rigsLike('ikea-lamp')[0]);
    spec.lower.fill(-Infinity, 0, 3);
    spec.upper.fill(Infinity, 0, 3);
    spec.lower[3] = -Infinity;
    const doc = JSON.parse(writeA7Rig(spec)) as { bones: Array<{ xzx_min?: number[]; xzx_max?: number[] }> };
    expect(doc.bones[0].xzx_min).toBeUndefined();
    expect(doc.bones[0].xzx_max).toBeUndefined();
    expect(doc.bones[1].xzx_min![0]).toBe(-UNBOUNDED_DEG);
    const back = parseA7Rig(writeA7Rig(spec), 'x.json');
    expect(back.lower[0]).toBe(-Infinity);
    expect(back.lower[3]).toBe(-UNBOUNDED_DEG);
  });
});
