// The command line as a user runs it: each error gives one clear line and a non-zero exit, and a
// small run writes the JSON schema. (The benchmark itself is `npm run bench`, not a test.)
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

import { afterAll, describe, expect, it } from 'vitest';

import { writeA7Rig } from '../../bench-node/a7_writer.js';
import { a7Path } from '../helpers/a7.js';
import { straightLimb } from '../helpers/rig_builder.js';

const root = resolve(import.meta.dirname, '../..');
const knight = a7Path('knight');
const dir = mkdtempSync(join(tmpdir(), 'bench-cli-test-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

function bench(...args: string[]): { code: number; stdout: string; stderr: string } {
  const r = spawnSync(process.execPath, ['--import', 'tsx', 'bench-node/cli.ts', ...args], { cwd: root, encoding: 'utf8' });
  return { code: r.status ?? -1, stdout: r.stdout, stderr: r.stderr };
}

function expectOneLineError(args: string[], pattern: RegExp): void {
  const r = bench(...args);
  expect(r.code).not.toBe(0);
  expect(r.stdout).toBe('');
  const lines = r.stderr.trim().split('\n');
  expect(lines).toHaveLength(1);
  expect(lines[0]).toMatch(/^bench: /);
  expect(lines[0]).toMatch(pattern);
}

describe('errors: one line on stderr, non-zero exit', () => {
  const bad = join(dir, 'bad.json');
  writeFileSync(bad, '{"bones": [{"parent_id": 3, "rest_T": [[1,0,0,0],[0,1,0,0],[0,0,1,0]]}]}');
  const notJson = join(dir, 'broken.json');
  writeFileSync(notJson, '{"bones": [');
  const badCsv = join(dir, 'bad.csv');
  writeFileSync(badCsv, 'rig,method\nknight,GN\n');

  it.each([
    [['--rig', knight, '--frobnicate'], /unknown option '--frobnicate'/],
    [['--rig', join(dir, 'missing.json')], /missing\.json: no such file/],
    [['--rig', 'no-such-project-rig'], /no project rig .*no-such-project-rig\.glb/],
    [['--rig', bad], /parent_id 3 is not -1 or a bone index/],
    [['--rig', notJson], /bad JSON/],
    [['--rig', join(dir, 'rig.txt')], /no such file/],
    [['--rig', knight, '--methods', 'gn,simplex'], /unknown method "simplex"/],
    [['--rig', knight, '--experiment', 'sideways'], /unknown experiment "sideways"/],
    [['--rig', knight, '--engine', 'gpu'], /unknown engine "gpu"/],
    [['--rig', knight, '--samples', 'many'], /--samples: "many" is not a positive integer/],
    [['--rig', knight, '--samples', '10,foo=3'], /unknown method "foo" in --samples/],
    [['--rig', knight, '--timeout', '-1'], /--timeout: "-1" is not a positive number/],
    [['--rig', knight, '--workers', '0'], /--workers: "0" is not a positive integer/],
    [['--rig', knight, '--compare', join(dir, 'none.csv')], /none\.csv: no such file/],
    [['--rig', knight, '--compare', badCsv], /no "experiment" column/],
    [[], /required option '--rig/],
    [['--rig', knight, 'stray'], /too many arguments/],
  ] as Array<[string[], RegExp]>)('%j', (args, pattern) => {
    expectOneLineError(args, pattern);
  });

  it('--help prints the options and exits 0', () => {
    const r = bench('--help');
    expect(r.code).toBe(0);
    expect(r.stdout).toMatch(/--rig <paths>/);
    expect(r.stdout).toMatch(/--engine <list>/);
  });
});

interface JsonRow {
  [key: string]: unknown;
}

const schema: Record<string, string> = {
  rig: 'string', experiment: 'string', method: 'string', engine: 'string', samples: 'number',
  t_avg_s: 'number', t_median_s: 'number', t_p95_s: 'number', t_max_s: 'number',
  iter_avg: 'number', E_avg: 'number', E_iqm: 'number', E_max: 'number', success_rate: 'number', unreachable: 'number',
};

function runJson(args: string[]): JsonRow[] {
  const file = join(dir, `out-${Math.random().toString(36).slice(2)}.json`);
  const r = bench(...args, '--json', file);
  expect(r.stderr).toBe('');
  expect(r.code).toBe(0);
  const doc = JSON.parse(readFileSync(file, 'utf8')) as { rows: JsonRow[] };
  return doc.rows;
}

describe('a small run', () => {
  it('prints a table per rig and experiment and writes the JSON schema', () => {
    const csv = join(dir, 'out.csv');
    const md = join(dir, 'out.md');
    const file = join(dir, 'smoke.json');
    const r = bench('--rig', knight, '--samples', '5', '--methods', 'three-ccd,closed-chain-ik', '--timeout', '0.2', '--workers', '2',
      '--json', file, '--csv', csv, '--markdown', md);
    expect(r.stderr).toBe('');
    expect(r.code).toBe(0);
    expect(r.stdout).toMatch(/knight, random targets/);
    expect(r.stdout).toMatch(/knight, incremental targets/);
    const rows = (JSON.parse(readFileSync(file, 'utf8')) as { rows: JsonRow[] }).rows;
    expect(rows).toHaveLength(4);
    for (const row of rows) {
      for (const [key, type] of Object.entries(schema)) expect(typeof row[key], key).toBe(type);
      expect(row.rig).toBe('knight');
      expect(row.samples).toBe(5);
      expect(row.success_rate as number).toBeGreaterThanOrEqual(0);
      expect(row.success_rate as number).toBeLessThanOrEqual(1);
      expect(row.t_max_s as number).toBeLessThan(0.5);
    }
    expect(rows.map((row) => `${row.experiment} ${row.method} ${row.engine}`)).toEqual([
      'random three-ccd js', 'random closed-chain-ik js', 'incremental three-ccd js', 'incremental closed-chain-ik js',
    ]);
    expect(readFileSync(csv, 'utf8').split('\n')[0]).toMatch(/^rig,experiment,method,engine,samples,t_avg_s/);
    expect(readFileSync(md, 'utf8')).toMatch(/### knight, random targets\n\n\| method \| engine \|/);
  });

  it('the same seed gives the same solves across engines and worker counts', () => {
    const args = ['--rig', knight, '--samples', '12', '--methods', 'gn,lm', '--experiment', 'incremental,drag,reach', '--seed', '5'];
    const one = runJson([...args, '--workers', '1', '--engine', 'wasm,native']);
    const three = runJson([...args, '--workers', '3', '--engine', 'wasm,native']);
    const key = (row: JsonRow): string => `${row.experiment} ${row.method} ${row.engine}`;
    expect(three.map(key)).toEqual(one.map(key));
    one.forEach((row, i) => {
      // Deterministic solvers on identical inputs: identical results whatever the partition.
      expect(three[i].E_avg).toBe(row.E_avg);
      expect(three[i].iter_avg).toBe(row.iter_avg);
    });
    // The same core natively: the same iterations and E to rounding on independent targets (drag
    // paths chain each step's result into the next start, so rounding differences accumulate there).
    for (const w of one.filter((row) => row.engine === 'wasm' && row.experiment === 'incremental')) {
      const n = one.find((row) => row.engine === 'native' && row.method === w.method && row.experiment === w.experiment)!;
      expect(n.iter_avg).toBe(w.iter_avg);
      expect(Math.abs((n.E_avg as number) - (w.E_avg as number))).toBeLessThanOrEqual(1e-9 * (w.E_avg as number));
    }
  });
});

describe('the reach experiment', () => {
  it('runs on a project rig, with the drag columns', () => {
    const file = join(dir, 'reach.json');
    const csv = join(dir, 'reach.csv');
    const r = bench('--rig', 'lamp', '--experiment', 'reach', '--methods', 'lm', '--samples', '40', '--json', file, '--csv', csv);
    expect(r.stderr).toBe('');
    expect(r.code).toBe(0);
    expect(r.stdout).toMatch(/lamp, reach targets/);
    expect(r.stdout).toMatch(/unreachable .* jump_max_deg/);
    const [row] = (JSON.parse(readFileSync(file, 'utf8')) as { rows: JsonRow[] }).rows;
    for (const [key, type] of Object.entries(schema)) expect(typeof row[key], key).toBe(type);
    expect(row).toMatchObject({ rig: 'lamp', experiment: 'reach', method: 'lm', samples: 40 });
    expect(row.jump_max_deg as number).toBeGreaterThan(0);
    expect(readFileSync(csv, 'utf8').split('\n')[0]).toMatch(/,success_rate,unreachable,.*,jump_max_deg,stop_reasons$/);
  });

  it('counts steps out of reach as unreachable and leaves them out of success, on both engines', () => {
    // A straight limb of length 2 from the origin (size 1, tip tolerance 0.001): the path towards
    // its root can be reached by bending. Step t of either path sideways puts the target
    // hypot(2, 0.02 t) from the root, out of reach by more than the tip tolerance from t = 4 on.
    const limb = join(dir, 'limb.json');
    writeFileSync(limb, writeA7Rig(straightLimb()));
    const outOfReach = Array.from({ length: 40 }, (_, i) => Math.hypot(2, 0.02 * (i + 1)) - 2 >= 0.001).filter(Boolean).length;
    expect(outOfReach).toBe(37);
    const rows = runJson(['--rig', limb, '--experiment', 'reach', '--methods', 'lm', '--engine', 'wasm,native', '--timeout', '0.2']);
    expect(rows.map((row) => row.engine)).toEqual(['wasm', 'native']);
    for (const row of rows) {
      expect(row).toMatchObject({ experiment: 'reach', samples: 120, unreachable: 2 * outOfReach });
      expect(row.success_rate).toBe(1);
    }
  });
});
