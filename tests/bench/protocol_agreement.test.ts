// The protocol's facts are coded once per language: TypeScript (web/src/rig/tolerances.ts,
// bench-node/targets.ts) and C++ (wasm/native/protocol.h, which the native tools and tests use).
// Both must give the same numbers: the random and incremental target sets of a seed, angle for
// angle and bit for bit (but for the sign of zero, which a clamp to a fixed angle of 0 may set
// either way); the rig size, default tolerances and targets, which go through each engine's own
// forward kinematics, to rounding. wasm/tools/protocol_targets prints the C++ side.
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';

import { afterAll, beforeAll, describe, expect, it } from 'vitest';

import { generateTargets } from '../../bench-node/targets.js';
import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { defaultTolerances, rigSize } from '../../web/src/rig/tolerances.js';
import { loadTestRig, testRigs } from '../helpers/a7.js';

const tool = fileURLToPath(new URL('../../build/native/protocol_targets', import.meta.url));

interface NativeSet {
  starts: number[][];
  goals: number[][];
  targets: number[][];
}

interface NativeProtocol {
  size: number;
  gradientTolerance: number;
  errorTolerance: number;
  random: NativeSet;
  incremental: NativeSet;
}

const SAMPLES = 30;
const SEED = 9;

let ik: IkCoreModule;
const rigs: IkRig[] = [];
beforeAll(async () => {
  ik = await loadIkNode();
});
afterAll(() => rigs.forEach((r) => r.dispose()));

/** `flat` (count x width) as rows. */
const rows = (flat: Float64Array, width: number): number[][] =>
  Array.from({ length: flat.length / width }, (_, k) => Array.from(flat.subarray(k * width, (k + 1) * width)));

/** The rows with -0 as 0. */
const unsigned = (values: number[][]): number[][] => values.map((row) => row.map((x) => x + 0));

/** |a - b| within `relative` of |b|. */
const expectClose = (a: number, b: number, relative = 1e-14): void =>
  expect(Math.abs(a - b)).toBeLessThanOrEqual(relative * Math.abs(b));

describe.each(testRigs)('$label', (testRig) => {
  const native = JSON.parse(
    execFileSync(tool, [testRig.path, '--samples', String(SAMPLES), '--seed', String(SEED)], { encoding: 'utf8' }),
  ) as NativeProtocol;

  it('the same size and default tolerances (as for an A7 file of that name)', () => {
    const rig = new IkRig(ik, loadTestRig(testRig));
    rigs.push(rig);
    const size = rigSize(rig.boneTips(new Float64Array(rig.numAngles)));
    expectClose(native.size, size);
    const { gradientTolerance, errorTolerance } = defaultTolerances(testRig.name, true, size);
    expectClose(native.gradientTolerance, gradientTolerance);
    expectClose(native.errorTolerance, errorTolerance);
  });

  it.each(['random', 'incremental'] as const)('the same %s target set', (experiment) => {
    const spec = loadTestRig(testRig);
    const rig = new IkRig(ik, spec);
    rigs.push(rig);
    const set = generateTargets(spec, experiment, SAMPLES, SEED, (a) => rig.tips(a));
    const theirs = native[experiment];
    expect(unsigned(theirs.starts)).toEqual(unsigned(rows(set.starts, set.numAngles)));
    expect(unsigned(theirs.goals)).toEqual(unsigned(rows(set.targetAngles!, set.numAngles)));
    const ours = rows(set.targets, set.numResiduals);
    const scale = Math.max(1, native.size);
    theirs.targets.forEach((row, k) =>
      row.forEach((x, i) => expect(Math.abs(x - ours[k][i]), `sample ${k}`).toBeLessThan(1e-12 * scale)),
    );
  });
});
