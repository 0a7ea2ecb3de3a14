// --goals pose: each effector's target is its tip frame's whole pose at the target angles. A run
// reports the orientation errors, judges success from forward kinematics of the returned angles
// (tips and frame rotations, never the solver's own flag), refuses what cannot take pose goals
// (three-ccd, --paper, drag and reach) with one line, leaves --goals position as it was, and runs
// on the native engine (lm and kdl) too.
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

import { afterAll, describe, expect, it } from 'vitest';

import { isOnTarget } from '../../bench-node/evaluate.js';
import { summarize, type SolveResult } from '../../bench-node/metrics.js';
import { parseOptions } from '../../bench-node/options.js';
import {
  addOrientations,
  largestRotationErrorDeg,
  ORIENTATION_TOLERANCE_DEG,
  poseGoals,
} from '../../bench-node/pose_goals.js';
import { encodeJob, nativeToolPath } from '../../bench-node/run_native.js';
import { prefix } from '../../bench-node/target_set.js';
import { generateTargets } from '../../bench-node/targets.js';
import { orientationErrorsDeg } from '../../web/src/ik/goals.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { IkSolver } from '../../web/src/ik/solver.js';
import { loadTestRig, rigsLike } from '../helpers/a7.js';
import { benchHere, type Outcome } from './bench_here.js';

const ik = await loadIkNode();
const methods = IkSolver.methods(ik);
const knight = rigsLike('knight')[0]; // the project's knight as an A7 file
const lamp = rigsLike('ikea-lamp')[0];
const dir = mkdtempSync(join(tmpdir(), 'bench-goals-test-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

type Json = Record<string, unknown>;

/** A run in this process without warm-up: its stdout and its --json document. */
async function runJson(...args: string[]): Promise<{ stdout: string; rows: Json[]; run: Json }> {
  const file = join(dir, `out-${Math.random().toString(36).slice(2)}.json`);
  const r = await benchHere(...args, '--warm-up', '0', '--workers', '1', '--json', file);
  expect(r.stderr).toBe('');
  expect(r.code).toBe(0);
  const doc = JSON.parse(readFileSync(file, 'utf8')) as { rows: Json[]; run: Json };
  return { stdout: r.stdout, ...doc };
}

/** Exit code 2, nothing on stdout, one line `bench: ...` matching `pattern`. */
function expectUsageError(r: Outcome, pattern: RegExp): void {
  expect(r.stdout).toBe('');
  const lines = r.stderr.trim().split('\n');
  expect(lines).toHaveLength(1);
  expect(lines[0]).toMatch(pattern);
  expect(r.code).toBe(2);
}

describe('--goals pose on the WebAssembly engine', () => {
  it('runs lm on a project rig and reports the orientation errors in the table, JSON and CSV', async () => {
    const csv = join(dir, 'pose.csv');
    const { stdout, rows, run } = await runJson(
      '--rig',
      lamp.path,
      '--goals',
      'pose',
      '--methods',
      'lm',
      '--samples',
      '20',
      '--csv',
      csv,
    );
    const lines = stdout.split('\n');
    const title = lines.findIndex((l) => / random targets \(pose goals\)$/.test(l));
    expect(title).toBeGreaterThanOrEqual(0);
    expect(lines[title + 1].split(/ {2,}/).slice(-4)).toEqual([
      't_max',
      'rot_err_avg_deg',
      'rot_err_max_deg',
      'stop reasons',
    ]);
    expect(stdout).toMatch(/, incremental targets \(pose goals\)\n/);
    expect(rows.map((r) => `${r.experiment} ${r.method} ${r.goals}`)).toEqual([
      'random lm pose',
      'incremental lm pose',
    ]);
    for (const row of rows) {
      expect(row.success_rate).toBe(1);
      expect(typeof row.rot_err_avg_deg).toBe('number');
      expect(row.rot_err_max_deg as number).toBeGreaterThanOrEqual(row.rot_err_avg_deg as number);
      // Every solve on target: every orientation within the tolerance, but not all exactly there.
      expect(row.rot_err_max_deg as number).toBeLessThan(ORIENTATION_TOLERANCE_DEG);
      expect(row.rot_err_max_deg as number).toBeGreaterThan(0);
    }
    expect(run.goals).toBe('pose');
    const [header, first] = readFileSync(csv, 'utf8').split('\n');
    expect(header).toMatch(/,restarts,goals,rot_err_avg_deg,rot_err_max_deg,/);
    expect(first).toMatch(/^[a-z-]+,random,lm,wasm,.*,1000,pose,[0-9.e-]+,[0-9.e-]+,/);
  });

  it('counts as successes exactly the solves whose returned pose is on target by forward kinematics', async () => {
    // bfgs without restarts stops off target on some random knight poses (deterministically: a
    // generous time budget), so the count is a real test.
    const samples = 20;
    const { rows, run } = await runJson(
      '--rig',
      knight.path,
      '--goals',
      'pose',
      '--methods',
      'bfgs',
      '--samples',
      String(samples),
      '--experiment',
      'random',
      '--restarts',
      '0',
      '--time-budget',
      '60',
    );
    const [{ gradientTolerance, errorTolerance }] = run.rigs as Array<{
      gradientTolerance: number;
      errorTolerance: number;
    }>;
    // The same solves through the public API, judged by the API's own forward kinematics.
    const spec = loadTestRig(knight);
    const rig = new IkRig(ik, spec);
    const solver = new IkSolver(rig, 'bfgs', {
      gradientTolerance: gradientTolerance,
      errorTolerance: errorTolerance,
      timeBudgetSeconds: 60,
      restarts: 0,
    });
    const set = addOrientations(
      generateTargets(spec, 'random', samples, 1, (a) => rig.tips(a)),
      (a) => rig.tipRotations(a),
    );
    const m = set.numAngles,
      r = set.numResiduals;
    const effectors = Array.from(rig.effectors());
    let onTarget = 0,
      reachedFlag = 0;
    for (let k = 0; k < samples; k++) {
      const target = set.targets.subarray(k * r, (k + 1) * r);
      const goals = poseGoals(effectors, target, set.orientations!.subarray((4 * k * r) / 3, (4 * (k + 1) * r) / 3));
      const result = solver.solve(set.starts.subarray(k * m, (k + 1) * m), goals);
      const tips = rig.tips(result.angles);
      let E = 0;
      for (let i = 0; i < r; i++) E += 0.5 * (tips[i] - target[i]) ** 2;
      const worst = Math.max(...orientationErrorsDeg(rig, result.angles, goals));
      if (E < errorTolerance && worst < ORIENTATION_TOLERANCE_DEG) onTarget++;
      if (result.reached) reachedFlag++;
    }
    solver.dispose();
    rig.dispose();
    expect(onTarget).toBeGreaterThan(0);
    expect(onTarget).toBeLessThan(samples);
    expect(Math.round((rows[0].success_rate as number) * samples)).toBe(onTarget);
    expect(onTarget).toBe(reachedFlag); // and the core agrees
  });

  it('a pose is on target only with every orientation within the tolerance', () => {
    const test = { errorTolerance: 1e-4, tipTolerance: 0, orientationToleranceDeg: ORIENTATION_TOLERANCE_DEG };
    expect(isOnTarget(test, 1e-5, 0, 0.49)).toBe(true);
    expect(isOnTarget(test, 1e-5, 0, 0.51)).toBe(false);
    expect(isOnTarget(test, 2e-4, 0, 0.1)).toBe(false);
    expect(isOnTarget(test, 1e-5, 0)).toBe(false); // no orientation error known: not on target
    const solve = (E: number, rotErrDeg: number): SolveResult => ({
      E,
      tipDistance: 0,
      iterations: 1,
      seconds: 1e-3,
      stopReason: 'converged_E',
      wobbleDuring: NaN,
      wobbleAfter: NaN,
      jumpDeg: 0,
      rotErrDeg,
    });
    const row = summarize(
      { rig: 'r', experiment: 'random', method: 'lm', engine: 'wasm', goals: 'pose' },
      [solve(1e-5, 0.1), solve(1e-5, 0.7), solve(1e-3, 0.2)],
      test,
      [1, 1, 1],
    );
    expect(row.success_rate).toBeCloseTo(1 / 3, 12);
    expect(row.rot_err_avg_deg).toBeCloseTo(1 / 3, 12);
    expect(row.rot_err_max_deg).toBe(0.7);
    expect(row.goals).toBe('pose');
  });

  it('measures orientation errors as the angle between the frames', () => {
    const q = (axis: [number, number, number], deg: number): number[] => {
      const h = (deg * Math.PI) / 360;
      return [axis[0] * Math.sin(h), axis[1] * Math.sin(h), axis[2] * Math.sin(h), Math.cos(h)];
    };
    expect(
      largestRotationErrorDeg([...q([0, 0, 1], 30), ...q([1, 0, 0], 0)], [...q([0, 0, 1], 10), ...q([1, 0, 0], 0.25)]),
    ).toBeCloseTo(20, 10);
    // q and -q are the same rotation; the length of a quaternion does not matter.
    expect(
      largestRotationErrorDeg(
        q([0, 1, 0], 5).map((x) => -2 * x),
        q([0, 1, 0], 5),
      ),
    ).toBeCloseTo(0, 6);
  });

  it('refuses three-ccd, paper mode and the dragging experiments with one line, and leaves three-ccd out of its default', async () => {
    expectUsageError(
      await benchHere('--rig', lamp.path, '--goals', 'pose', '--methods', 'lm,three-ccd'),
      /^bench: --goals pose: three-ccd solves tip positions only; leave it out of --methods$/,
    );
    expectUsageError(
      await benchHere('--rig', lamp.path, '--goals', 'pose', '--paper'),
      /^bench: --goals pose: paper mode \(--paper\) solves tip positions only/,
    );
    expectUsageError(
      await benchHere('--rig', lamp.path, '--goals', 'pose', '--experiment', 'random,drag'),
      /^bench: --goals pose: the drag experiment has tip positions only/,
    );
    expectUsageError(
      await benchHere('--rig', lamp.path, '--goals', 'pose', '--compare', 'results.csv'),
      /^bench: --goals pose: --compare sets the report's position-only figures beside these/,
    );
    expectUsageError(
      await benchHere('--rig', lamp.path, '--goals', 'orientation'),
      /^bench: --goals: unknown goal kind "orientation" \(known: position, pose\)$/,
    );
    const defaults = parseOptions(['--rig', lamp.path, '--goals', 'pose'], false, methods)!.methods;
    expect(defaults).not.toContain('three-ccd');
    expect(defaults).toEqual([...methods, 'closed-chain-ik']);
  });

  it('closed-chain-ik solves pose goals, judged by our forward kinematics', async () => {
    const { rows } = await runJson(
      '--rig',
      lamp.path,
      '--goals',
      'pose',
      '--methods',
      'closed-chain-ik',
      '--samples',
      '10',
      '--experiment',
      'incremental',
    );
    expect(rows[0].goals).toBe('pose');
    expect(rows[0].success_rate).toBe(1);
    expect(rows[0].rot_err_max_deg as number).toBeLessThan(ORIENTATION_TOLERANCE_DEG);
  });
});

describe('--goals position', () => {
  it('is the default and gives the same solves and table as before: no orientation columns', async () => {
    const args = ['--rig', lamp.path, '--methods', 'lm,gn', '--samples', '10'];
    const plain = await runJson(...args);
    const position = await runJson(...args, '--goals', 'position');
    expect(parseOptions(['--rig', lamp.path], false, methods)!.goals).toBe('position');
    expect(parseOptions(['--rig', lamp.path], false, methods)!.methods).toContain('three-ccd');
    const headers = (out: string): string[][] =>
      out
        .split('\n')
        .filter((l) => l.startsWith('method '))
        .map((l) => l.split(/ {2,}/));
    const titles = (out: string): string[] => out.split('\n').filter((l) => l.includes(' targets'));
    expect(headers(position.stdout)).toEqual(headers(plain.stdout));
    expect(titles(position.stdout)).toEqual(titles(plain.stdout));
    expect(headers(plain.stdout)[0]).toEqual([
      'method',
      'engine',
      'samples',
      'restarts',
      't_avg',
      'iter_avg',
      'E_avg',
      'E_IQM',
      'max E',
      'success',
      't_median',
      't_p95',
      't_max',
      'stop reasons',
    ]);
    expect(titles(plain.stdout)).toHaveLength(2);
    expect(titles(plain.stdout)[0]).toMatch(/, random targets$/);
    const same = (r: Json): unknown[] => [
      r.experiment,
      r.method,
      r.E_avg,
      r.E_max,
      r.iter_avg,
      r.success_rate,
      r.stop_reasons,
      r.goals,
      r.rot_err_avg_deg,
    ];
    expect(position.rows.map(same)).toEqual(plain.rows.map(same));
    for (const row of plain.rows) {
      expect(row.goals).toBe('position');
      expect(row.rot_err_avg_deg).toBeNull();
      expect(row.rot_err_max_deg).toBeNull();
    }
  });

  it('target sets carry no orientations, and job files keep their layout', () => {
    const spec = loadTestRig(lamp);
    const rig = new IkRig(ik, spec);
    const set = generateTargets(spec, 'incremental', 4, 1, (a) => rig.tips(a));
    expect(set.orientations).toBeNull();
    const header = (bytes: Uint8Array): number[] =>
      [0, 1, 2, 3].map((i) => new DataView(bytes.buffer, 8, 16).getInt32(4 * i, true));
    const plain = encodeJob(set, 0, 4);
    expect(header(plain)).toEqual([4, set.numAngles, set.numResiduals, 0]);
    expect(plain.length).toBe(24 + 8 * 4 * (2 + set.numAngles + set.numResiduals));
    // With pose goals each record ends with the quaternions, 4 per effector.
    const pose = addOrientations(
      generateTargets(spec, 'incremental', 4, 1, (a) => rig.tips(a)),
      (a) => rig.tipRotations(a),
    );
    const o = (4 * set.numResiduals) / 3;
    const bytes = encodeJob(pose, 1, 3);
    expect(header(bytes)).toEqual([2, set.numAngles, set.numResiduals, o]);
    const body = new Float64Array(bytes.buffer.slice(24));
    const stride = 2 + set.numAngles + set.numResiduals + o;
    expect(Array.from(body.subarray(stride - o, stride))).toEqual(Array.from(pose.orientations!.subarray(o, 2 * o)));
    expect(Array.from(prefix(pose, 2).orientations!)).toEqual(Array.from(pose.orientations!.subarray(0, 2 * o)));
    // The orientations are the frames at the target angles: unit quaternions.
    for (let e = 0; e < pose.orientations!.length; e += 4)
      expect(Math.hypot(...pose.orientations!.subarray(e, e + 4))).toBeCloseTo(1, 12);
    rig.dispose();
  });
});

describe('--goals pose on the native engine', () => {
  // npm test's setup builds the native tool with KDL (IK_NATIVE_BUILD may name another build).
  it('is built', () => {
    expect(existsSync(nativeToolPath)).toBe(true);
  });

  it('lm gives the same solves as on WebAssembly, and kdl solves the poses', async () => {
    const { rows } = await runJson(
      '--rig',
      lamp.path,
      '--goals',
      'pose',
      '--methods',
      'lm,kdl',
      '--engine',
      'wasm,native',
      '--samples',
      '10',
    );
    const row = (experiment: string, method: string, engine: string): Json =>
      rows.find((r) => r.experiment === experiment && r.method === method && r.engine === engine)!;
    for (const experiment of ['random', 'incremental']) {
      const wasm = row(experiment, 'lm', 'wasm'),
        native = row(experiment, 'lm', 'native');
      expect(native.goals).toBe('pose');
      expect(native.success_rate).toBe(wasm.success_rate);
      expect(native.iter_avg).toBe(wasm.iter_avg);
      expect(native.E_avg as number).toBeCloseTo(wasm.E_avg as number, 12);
      expect(native.rot_err_max_deg as number).toBeCloseTo(wasm.rot_err_max_deg as number, 6);
      const kdl = row(experiment, 'kdl', 'native');
      expect(kdl.success_rate).toBe(1);
      expect(kdl.rot_err_max_deg as number).toBeLessThan(ORIENTATION_TOLERANCE_DEG);
      expect(kdl.rot_err_max_deg as number).toBeGreaterThan(0);
    }
  });

  it('kdl with --goals position solves as without the option', async () => {
    const args = [
      '--rig',
      lamp.path,
      '--methods',
      'kdl',
      '--engine',
      'native',
      '--samples',
      '10',
      '--experiment',
      'random',
    ];
    const same = (r: Json): unknown[] => [
      r.E_avg,
      r.E_max,
      r.iter_avg,
      r.success_rate,
      r.stop_reasons,
      r.rot_err_max_deg,
    ];
    expect((await runJson(...args, '--goals', 'position')).rows.map(same)).toEqual(
      (await runJson(...args)).rows.map(same),
    );
  });
});
