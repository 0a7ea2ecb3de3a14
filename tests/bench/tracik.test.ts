// --experiment tracik: TRAC-IK's protocol (bench-node/tracik.ts). Its options and refusals, the
// configurations (uniform within the limits, a full turn for an unlimited angle) and the nominal
// seed, success judged by forward kinematics against 1e-5 (tip distance) and 1e-5 rad (rotation
// angle), a small run on the project's robot arm on both engines (lm and kdl), and the published
// KDL and TRAC-IK figures beside ours for a chain of the table (tracik_table.ts).
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

import { afterAll, describe, expect, it } from 'vitest';

import { isOnTarget } from '../../bench-node/evaluate.js';
import { parseOptions } from '../../bench-node/options.js';
import {
  addOrientations,
  largestRotationErrorDeg,
  largestTwistComponent,
  poseGoals,
} from '../../bench-node/pose_goals.js';
import { loadBenchRig } from '../../bench-node/rigs.js';
import { nativeToolPath } from '../../bench-node/run_native.js';
import { generateTargets } from '../../bench-node/targets.js';
import { renderTable } from '../../bench-node/table.js';
import {
  nominalAngles,
  TRACIK_ROTATION_TOLERANCE_DEG,
  TRACIK_SAMPLES,
  TRACIK_TIMEOUT_S,
  TRACIK_TOLERANCE,
  tracikAngles,
  tracikSettings,
} from '../../bench-node/tracik.js';
import {
  publishedRow,
  TRACIK_PUBLISHED,
  tracikTable,
  withPublished,
  type PublishedRow,
} from '../../bench-node/tracik_table.js';
import type { Row } from '../../bench-node/metrics.js';
import type { RigSpec } from '../../web/src/ik/rig_arrays.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkRig } from '../../web/src/ik/rig.js';
import { IkSolver } from '../../web/src/ik/solver.js';
import { largestTipDistance } from '../../web/src/ik/tip_distance.js';
import { needsRobots, robotPath } from '../helpers/robots.js';
import { benchHere } from './bench_here.js';

const ik = await loadIkNode();
const methods = IkSolver.methods(ik);
const dir = mkdtempSync(join(tmpdir(), 'bench-tracik-test-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

type Json = Record<string, unknown>;

/** A run in this process without warm-up, on one worker: stdout, its --json document and its --csv text. */
async function runJson(...args: string[]): Promise<{ stdout: string; rows: Json[]; run: Json; csv: string }> {
  const name = Math.random().toString(36).slice(2);
  const json = join(dir, `${name}.json`),
    csv = join(dir, `${name}.csv`);
  const r = await benchHere(...args, '--warm-up', '0', '--workers', '1', '--no-progress', '--json', json, '--csv', csv);
  expect(r.stderr).toBe('');
  expect(r.code).toBe(0);
  const doc = JSON.parse(readFileSync(json, 'utf8')) as { rows: Json[]; run: Json };
  return { stdout: r.stdout, ...doc, csv: readFileSync(csv, 'utf8') };
}

const parse = (...args: string[]) => parseOptions(['--rig', 'robot-arm', ...args], false, methods)!;

describe('tracik options', () => {
  it('defaults to the protocol: pose goals, 10,000 queries, 5 ms each; --samples and --time-budget override', () => {
    const o = parse('--experiment', 'tracik');
    expect(o.goals).toBe('pose');
    expect(o.samples.lm).toBe(TRACIK_SAMPLES);
    expect(o.timeBudgetSeconds).toBe(TRACIK_TIMEOUT_S);
    expect(o.methods).not.toContain('three-ccd');
    const p = parse('--experiment', 'tracik', '--samples', '50', '--time-budget', '0.01', '--goals', 'pose');
    expect([p.samples.lm, p.timeBudgetSeconds]).toEqual([50, 0.01]);
    expect(parse('--samples', '50').timeBudgetSeconds).toBe(1); // other experiments keep theirs
  });

  it.each([
    [['--experiment', 'tracik,random'], /^bench: --experiment: tracik runs alone, not with random$/],
    [['--experiment', 'tracik', '--goals', 'position'], /^bench: --goals: the tracik experiment targets whole poses/],
    [
      ['--experiment', 'tracik', '--error-tolerance', '0.001'],
      /^bench: --error-tolerance: the tracik experiment has TRAC-IK's tolerances/,
    ],
    [['--experiment', 'tracik', '--methods', 'three-ccd'], /^bench: --goals pose: three-ccd solves tip positions only/],
    [['--experiment', 'tracik', '--paper'], /^bench: --goals pose: paper mode/],
    [
      ['--chain', 'a:b'],
      /^bench: --chain: "robot-arm" is no URDF file \(\.urdf\): only URDF rigs have chains to choose$/,
    ],
    [['--chain', 'panda_link0'], /^bench: --chain: "panda_link0" is not BASE:TIP/],
    [['--chain', 'a:b:c'], /^bench: --chain: "a:b:c" is not BASE:TIP/],
    [['--chain', ' '], /^bench: --chain: empty value$/],
    [['--chain', 'a:b', '--chain', 'c:d'], /^bench: --chain given twice/],
  ])('refuses %j with one usage line', async (args, pattern) => {
    const r = await benchHere('--rig', 'robot-arm', ...args);
    expect(r.stdout).toBe('');
    expect(r.stderr.trim().split('\n')).toHaveLength(1);
    expect(r.stderr.trim()).toMatch(pattern);
    expect(r.code).toBe(2);
  });

  it('takes --chain for URDF rigs', () => {
    expect(parseOptions(['--rig', 'x/panda.urdf', '--chain', 'panda_link0:panda_link8'], false, methods)!.chain).toBe(
      'panda_link0:panda_link8',
    );
  });
});

describe('tracik configurations', () => {
  // A limited angle, a locked one, a +-180 one and an unlimited one.
  const spec = {
    parents: Int32Array.of(-1),
    lower: Float64Array.of(-90, 10, -180, -Infinity),
    upper: Float64Array.of(30, 10, 180, Infinity),
  } as unknown as RigSpec;

  it('starts from the nominal configuration: mid-limit, 0 for an unlimited angle', () => {
    expect(Array.from(nominalAngles(spec))).toEqual([-30, 10, 0, 0]);
  });

  it('draws uniformly within the limits, a full turn around the nominal value for a continuous angle', () => {
    const nominal = nominalAngles(spec);
    expect(Array.from(tracikAngles(spec, nominal, () => 0))).toEqual([-90, 10, -180, -180]);
    expect(Array.from(tracikAngles(spec, nominal, () => 0.5))).toEqual([-30, 10, 0, 0]);
    expect(Array.from(tracikAngles(spec, nominal, () => 0.75))).toEqual([0, 10, 90, 90]);
  });

  it('gives every query the nominal start and a pose target; seeded', async () => {
    const { spec: arm } = await loadBenchRig('robot-arm');
    const rig = new IkRig(ik, arm);
    const make = (seed: number) =>
      addOrientations(
        generateTargets(arm, 'tracik', 20, seed, (a) => rig.tips(a)),
        (a) => rig.tipRotations(a),
      );
    const set = make(1);
    const m = set.numAngles,
      nominal = Array.from(nominalAngles(arm));
    for (let k = 0; k < set.count; k++) {
      expect(Array.from(set.starts.subarray(k * m, (k + 1) * m))).toEqual(nominal);
      const a = set.targetAngles!.subarray(k * m, (k + 1) * m);
      a.forEach((x, i) => {
        expect(x).toBeGreaterThanOrEqual(Math.max(arm.lower[i], -180));
        expect(x).toBeLessThanOrEqual(Math.min(arm.upper[i], 180));
      });
    }
    expect(Array.from(make(1).targets)).toEqual(Array.from(set.targets));
    expect(Array.from(make(2).targets)).not.toEqual(Array.from(set.targets));
    rig.dispose();
  });
});

describe('tracik success: TRAC-IK tolerances on the pose from forward kinematics', () => {
  it('needs the tip within 1e-5 and the rotation angle within 1e-5 rad', () => {
    const test = tracikSettings(undefined);
    const on = (tip: number, rad: number): boolean =>
      isOnTarget({ errorTolerance: 1, ...test }, 0, tip, (rad * 180) / Math.PI);
    expect(TRACIK_ROTATION_TOLERANCE_DEG).toBeCloseTo(5.7296e-4, 8);
    expect(on(0.9e-5, 0.9e-5)).toBe(true);
    expect(on(1.1e-5, 0.9e-5)).toBe(false);
    expect(on(0.9e-5, 1.1e-5)).toBe(false);
  });

  it('counts exactly the solves whose returned pose meets both tolerances by forward kinematics (wasm lm)', async () => {
    // A long budget makes the solves deterministic, so the API's solves are the bench's.
    const samples = 30;
    const { rows } = await runJson(
      '--rig',
      'robot-arm',
      '--experiment',
      'tracik',
      '--methods',
      'lm',
      '--samples',
      String(samples),
      '--time-budget',
      '60',
    );
    const { spec } = await loadBenchRig('robot-arm');
    const rig = new IkRig(ik, spec);
    const settings = tracikSettings(undefined);
    const solver = new IkSolver(rig, 'lm', {
      gradientTolerance: settings.gradientTolerance,
      tipTolerance: settings.tipTolerance,
      orientationToleranceDeg: settings.orientationToleranceDeg,
      timeBudgetSeconds: 60,
    });
    const set = addOrientations(
      generateTargets(spec, 'tracik', samples, 1, (a) => rig.tips(a)),
      (a) => rig.tipRotations(a),
    );
    const m = set.numAngles,
      r = set.numResiduals,
      q = (4 * r) / 3;
    let onTarget = 0;
    for (let k = 0; k < samples; k++) {
      const target = set.targets.subarray(k * r, (k + 1) * r),
        orientation = set.orientations!.subarray(k * q, (k + 1) * q);
      const result = solver.solve(
        set.starts.subarray(k * m, (k + 1) * m),
        poseGoals(Array.from(rig.effectors()), target, orientation),
      );
      const tip = largestTipDistance(rig.tips(result.angles), target);
      const rad = (largestRotationErrorDeg(rig.tipRotations(result.angles), orientation) * Math.PI) / 180;
      if (tip < TRACIK_TOLERANCE && rad < TRACIK_TOLERANCE) onTarget++;
    }
    solver.dispose();
    rig.dispose();
    expect(onTarget).toBeGreaterThanOrEqual(samples - 1);
    expect(Math.round((rows[0].success_rate as number) * samples)).toBe(onTarget);
    expect(rows[0].rot_err_max_deg as number).toBeLessThan(onTarget === samples ? TRACIK_ROTATION_TOLERANCE_DEG : 180);
  });
});

describe("TRAC-IK's own test: each component of the twist onto the target", () => {
  // A frame turned 1e-5 rad about z and 2e-5 about x from its target, its tip off by (3e-6, -4e-6, 0).
  const half = (angle: number, axis: number[]) => [...axis.map((a) => a * Math.sin(angle / 2)), Math.cos(angle / 2)];
  const mul = (a: number[], b: number[]) => [
    a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
    a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
    a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
    a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2],
  ];
  const goal = half(0.7, [0, 0.6, 0.8]);

  it('reads the largest of the position differences and of the world rotation vector (radians)', () => {
    const turned = mul(half(-1e-5, [0, 0, 1]), goal); // the frame is the goal turned back by 1e-5 about world z
    expect(largestTwistComponent([1, 2, 3], [1 + 3e-6, 2 - 4e-6, 3], turned, goal)).toBeCloseTo(1e-5, 12);
    const both = mul(half(-2e-5, [1, 0, 0]), turned);
    expect(largestTwistComponent([1, 2, 3], [1 + 3e-6, 2 - 4e-6, 3], both, goal)).toBeCloseTo(2e-5, 11);
    expect(largestTwistComponent([1, 2, 3], [1 + 3e-6, 2 - 4e-6, 3], goal, goal)).toBeCloseTo(4e-6, 15);
    // A negated quaternion is the same frame.
    expect(
      largestTwistComponent(
        [0, 0, 0],
        [0, 0, 0],
        turned.map((x) => -x),
        goal,
      ),
    ).toBeCloseTo(1e-5, 12);
  });

  it('passes a turn of 1.3e-5 rad split over two axes that the angle test fails', () => {
    const split = mul(half(-1.3e-5, [Math.SQRT1_2, Math.SQRT1_2, 0]), goal);
    expect(largestTwistComponent([0, 0, 0], [0, 0, 0], split, goal)).toBeLessThan(TRACIK_TOLERANCE);
    expect((largestRotationErrorDeg(split, goal) * Math.PI) / 180).toBeGreaterThan(TRACIK_TOLERANCE);
  });
});

describe('a small tracik run on the robot arm', () => {
  it('prints the protocol table and writes its rows as JSON and CSV (wasm lm, native lm, kdl and kdl_nr_jl)', async () => {
    const native = existsSync(nativeToolPath);
    const { stdout, rows, run, csv } = await runJson(
      '--rig',
      'robot-arm',
      '--experiment',
      'tracik',
      '--methods',
      'lm,kdl,kdl_nr_jl',
      '--engine',
      'wasm,native',
      '--samples',
      '50',
    );
    expect(native).toBe(true);
    const lines = stdout.split('\n');
    expect(lines[0]).toBe('robot-arm, tracik protocol (pose within 1e-5, 5 ms budget by default)');
    expect(lines[1].split(/ {2,}/)).toEqual([
      'method',
      'engine',
      'samples',
      'restarts',
      'solve rate',
      "rate (TRAC-IK's test)",
      't_avg',
      't_median',
      't_p95',
      't_max',
      'rot_err_max_deg',
      'KDL rate (published)',
      'KDL t_avg (published)',
      'TRAC-IK rate (published)',
      'TRAC-IK t_avg (published)',
      'stop reasons',
    ]);
    expect(rows.map((r) => `${r.method} ${r.engine}`)).toEqual([
      'lm wasm',
      'lm native',
      'kdl native',
      'kdl_nr_jl native',
    ]);
    for (const row of rows) {
      expect([row.experiment, row.goals, row.samples, row.chain, row.published_kdl_rate]).toEqual([
        'tracik',
        'pose',
        50,
        null,
        null,
      ]);
      // TRAC-IK's test (each twist component within 1e-5) is at most as strict as ours (distance and angle).
      expect(row.twist_rate as number).toBeGreaterThanOrEqual(row.success_rate as number);
      if (row.method === 'kdl_nr_jl') {
        // KDL's own verdict (converged_E: its per-component test passed) is the harness's TRAC-IK test
        // of the returned angles by forward kinematics, to a sample at the 1e-5 border.
        const converged = ((row.stop_reasons as Record<string, number>).converged_E ?? 0) / 50;
        expect(Math.abs((row.twist_rate as number) - converged)).toBeLessThanOrEqual(1 / 50);
        expect(converged).toBeGreaterThan(0.2);
        continue;
      }
      // 5 ms per query on a shared machine: a few may time out.
      expect(row.success_rate as number).toBeGreaterThanOrEqual(row.method === 'lm' ? 0.9 : 0.8);
      expect(row.t_median_s as number).toBeLessThan(TRACIK_TIMEOUT_S);
    }
    expect(run.timeBudgetSeconds).toBe(TRACIK_TIMEOUT_S);
    expect(run.goals).toBe('pose');
    const [header, first] = csv.split('\n');
    expect(header).toBe(
      'rig,chain,experiment,method,engine,goals,samples,restarts,success_rate,t_avg_s,t_median_s,t_p95_s,t_max_s,iter_avg,E_max,' +
        'rot_err_avg_deg,rot_err_max_deg,twist_rate,published_chain,published_kdl_rate,published_kdl_avg_s,published_tracik_rate,published_tracik_avg_s,stop_reasons',
    );
    expect(first).toMatch(/^robot-arm,,tracik,lm,wasm,pose,50,1000,/);
  });
});

describe('the published figures beside ours', () => {
  const row = {
    rig: 'robot-arm',
    experiment: 'tracik',
    method: 'kdl',
    engine: 'native',
    goals: 'pose',
    samples: 10,
    restarts: 1000,
    success_rate: 0.5,
    twist_rate: 0.55,
    t_avg_s: 1e-3,
    t_median_s: 5e-4,
    t_p95_s: 4e-3,
    t_max_s: 5e-3,
    rot_err_max_deg: 1,
    stop_reasons: { converged_E: 5, timeout: 5 },
  } as unknown as Row;

  it('matches a row by the file base name and the chain', () => {
    expect(publishedRow('panda', 'panda_link0:panda_link8')?.chain).toBe('Franka Emika Panda');
    expect(publishedRow('baxter', 'base:left_hand_link')?.chain).toBe('Baxter arm');
    expect(publishedRow('kinova', 'j2s6s200_link_base:j2s6s200_end_effector')?.chain).toBe('Jaco2');
    expect(publishedRow('pr2', 'torso_lift_link:r_wrist_roll_link')?.chain).toBe('PR2 arm');
    expect(publishedRow('panda', 'panda_link0:panda_link7')).toBeUndefined();
    expect(publishedRow('panda', undefined)).toBeUndefined();
    expect(publishedRow('ur5_robot', 'base_link:tool0')).toBeUndefined();
  });

  it('puts them in the table and the row for a matching chain (a test-only row for the robot arm)', () => {
    const table: PublishedRow[] = [
      { ...TRACIK_PUBLISHED[2], chain: 'test arm', matches: [{ rig: 'robot-arm', chain: 'base:tip' }] },
    ];
    const matched = withPublished(row, 'base:tip', table);
    expect([
      matched.chain,
      matched.published_chain,
      matched.published_kdl_rate,
      matched.published_tracik_avg_s,
    ]).toEqual(['base:tip', 'test arm', 0.6177, 0.38e-3]);
    const text = renderTable(tracikTable([matched]), 'text').split('\n');
    expect(text[0]).toBe(
      'robot-arm base:tip, tracik protocol (pose within 1e-5, 5 ms budget by default; published: test arm, TRAC-IK v1.4.6 README)',
    );
    expect(text[3].split(/ {2,}/)).toEqual([
      'kdl',
      'native',
      '10',
      '1000',
      '50.00%',
      '55.00%',
      '0.001',
      '5e-04',
      '0.004',
      '0.005',
      '1',
      '61.77%',
      '0.00214',
      '99.70%',
      '3.8e-04',
      'converged_E 5, timeout 5',
    ]);
    expect(withPublished(row, 'other:chain', table).published_kdl_rate).toBeNull();
  });

  it('on the shared Panda, through the command line (lm, 20 queries)', needsRobots, async () => {
    const { stdout, rows } = await runJson(
      '--rig',
      robotPath('panda'),
      '--chain',
      'panda_link0:panda_link8',
      '--experiment',
      'tracik',
      '--methods',
      'lm',
      '--samples',
      '20',
    );
    expect(stdout.split('\n')[0]).toMatch(
      /^panda panda_link0:panda_link8, tracik protocol .*published: Franka Emika Panda/,
    );
    expect(rows[0]).toMatchObject({
      chain: 'panda_link0:panda_link8',
      published_kdl_rate: 0.6177,
      published_tracik_rate: 0.997,
      published_tracik_avg_s: 0.38e-3,
    });
  });
});
