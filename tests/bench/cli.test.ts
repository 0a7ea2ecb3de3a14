// The command line as a user runs it: each error gives one clear line and a non-zero exit before
// any solve, and a small run writes the JSON schema. (The benchmark itself is `npm run bench`, not
// a test.) Most cases run in this process through runCommand, what cli.ts calls, to keep the file
// fast, and the runs without warm-up (--warm-up 0: no run here measures speed); a few run the real
// command to check the exit code and output of the process.
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

import { afterAll, describe, expect, it } from 'vitest';

import { writeA7Rig } from '../../web/src/rig/a7/a7_writer.js';
import { prepareRigs } from '../../bench-node/bench.js';
import { parseOptions } from '../../bench-node/options.js';
import { checkOutputs } from '../../bench-node/outputs.js';
import { REACH_MARGIN } from '../../bench-node/reachability.js';
import { loadBenchRig } from '../../bench-node/rigs.js';
import { checkNativeTool } from '../../bench-node/run_native.js';
import type { IkCoreModule } from '../../web/src/ik/module.js';
import { loadIkNode } from '../../web/src/ik/node.js';
import { IkSolver } from '../../web/src/ik/solver.js';
import { rigsLike } from '../helpers/a7.js';
import { sketchRig, straightLimb } from '../../scripts/rig_files/rig_builder.js';
import { benchHere, type Outcome } from './bench_here.js';

const root = resolve(import.meta.dirname, '../..');
const methods = IkSolver.methods(await loadIkNode());
const knight = rigsLike('knight')[0].path; // an A7 file: the project's knight (build/test-rigs)
const dir = mkdtempSync(join(tmpdir(), 'bench-cli-test-'));
afterAll(() => rmSync(dir, { recursive: true, force: true }));

function bench(...args: string[]): Outcome {
  const r = spawnSync(process.execPath, ['--import', 'tsx', 'bench-node/cli.ts', ...args], {
    cwd: root,
    encoding: 'utf8',
  });
  return { code: r.status ?? -1, stdout: r.stdout, stderr: r.stderr };
}

/** Exit code `code`, nothing on stdout, one line `bench: ...` matching `pattern` on stderr, no stack. */
function expectOneLineError(r: Outcome, code: number, pattern: RegExp): void {
  expect(r.stderr).not.toContain('    at ');
  expect(r.stdout).toBe('');
  const lines = r.stderr.trim().split('\n');
  expect(lines).toHaveLength(1);
  expect(lines[0]).toMatch(/^bench: /);
  expect(lines[0]).toMatch(pattern);
  expect(r.code).toBe(code);
}

type Case = [args: string[], code: number, pattern: RegExp];

describe('errors: one line on stderr, non-zero exit', () => {
  const bad = join(dir, 'bad.json');
  writeFileSync(bad, '{"bones": [{"parent_id": 3, "rest_T": [[1,0,0,0],[0,1,0,0],[0,0,1,0]]}]}');
  const notJson = join(dir, 'broken.json');
  writeFileSync(notJson, '{"bones": [');
  const badCsv = join(dir, 'bad.csv');
  writeFileSync(badCsv, 'rig,method\nknight,GN\n');

  it.each([
    [['--rig', knight, '--frobnicate'], 2, /unknown option '--frobnicate'/],
    [['--rig', join(dir, 'missing.json')], 1, /missing\.json: no such file/],
    [['--rig', 'no-such-project-rig'], 1, /^bench: no-such-project-rig: no project rig .*no-such-project-rig\.glb/],
    [['--rig', bad], 1, /bad\.json: .*parent_id 3/],
    [['--rig', notJson], 1, /broken\.json: bad JSON/],
    [['--rig', join(dir, 'rig.txt')], 1, /rig\.txt: no such file/],
    [['--rig', knight, '--methods', 'gn,simplex'], 2, /--methods: unknown method "simplex"/],
    [['--rig', knight, '--experiment', 'sideways'], 2, /--experiment: unknown experiment "sideways"/],
    [['--rig', knight, '--engine', 'gpu'], 2, /--engine: unknown engine "gpu"/],
    [['--rig', knight, '--samples', 'many'], 2, /--samples: "many" is not an integer in 1\.\.1000000/],
    [['--rig', knight, '--samples', '10,foo=3'], 2, /--samples: unknown method "foo"/],
    [['--rig', knight, '--time-budget', '-1'], 2, /--time-budget: "-1" is not a positive number/],
    [['--rig', knight, '--workers', '0'], 2, /--workers: "0" is not an integer in 1\.\./],
    [['--rig', knight, '--compare', join(dir, 'none.csv')], 1, /--compare .*none\.csv: no such file/],
    [['--rig', knight, '--compare', badCsv], 1, /--compare .*bad\.csv: no "experiment" column/],
    [[], 2, /required option '--rig/],
    [['--rig', knight, 'stray'], 2, /too many arguments/],
  ] as Case[])('%j', async (args, code, pattern) => {
    expectOneLineError(await benchHere(...args), code, pattern);
  });

  it('--help prints the options and exits 0', () => {
    const r = bench('--help');
    expect(r.code).toBe(0);
    expect(r.stdout).toMatch(/--rig <paths>/);
    expect(r.stdout).toMatch(/--engine <list>/);
  });
});

describe('careless values: a usage error naming the option and the value', () => {
  const options = [
    '--rig',
    '--experiment',
    '--methods',
    '--samples',
    '--seed',
    '--gradient-tolerance',
    '--error-tolerance',
    '--time-budget',
    '--engine',
    '--workers',
    '--json',
    '--csv',
    '--markdown',
    '--compare',
    '--warm-up',
  ];
  it.each(options.flatMap((flag) => ['', '  '].map((value) => [flag, value])))(
    '%s %j: empty value',
    async (flag, value) => {
      const rig = flag === '--rig' ? [] : ['--rig', knight];
      expectOneLineError(await benchHere(...rig, flag, value), 2, new RegExp(`^bench: ${flag}: empty value$`));
    },
  );

  it.each([
    [['--samples', ','], /--samples: empty list ","/],
    [['--methods', ' , '], /--methods: empty list " , "/],
    [['--samples', '1e9'], /--samples: "1e9" is not an integer in 1\.\.1000000$/],
    [['--samples', '1000001'], /--samples: "1000001" is not an integer in 1\.\.1000000$/],
    [['--samples', '10,gd=1e9'], /--samples gd: "1e9" is not an integer in 1\.\.1000000$/],
    [['--samples', '10,20'], /--samples: two defaults in "10,20"/],
    [['--samples', 'gd=1,gd=2'], /--samples: gd given twice/],
    [['--samples', '3\n4'], /--samples: "3\\n4" is not an integer/],
    [['--seed', '-1'], /--seed: "-1" is not an integer in 0\.\.4294967295/],
    [['--seed', '4294967296'], /--seed: "4294967296" is not an integer/],
    [['--seed', '1.5'], /--seed: "1.5" is not an integer/],
    [['--seed', 'NaN'], /--seed: "NaN" is not an integer/],
    [['--seed', ' 5'], /--seed: " 5" is not an integer/],
    [['--workers', '1000'], /--workers: "1000" is not an integer in 1\.\.\d+ \(4 per core, 64 at most\)/],
    [['--workers', '65'], /--workers: "65" is not an integer in 1\.\.\d+/],
    [['--time-budget', 'NaN'], /--time-budget: "NaN" is not a positive number of at most 3600/],
    [['--time-budget', '0'], /--time-budget: "0" is not a positive number/],
    [['--time-budget', '3601'], /--time-budget: "3601" is not a positive number of at most 3600/],
    [['--time-budget', '1e308'], /--time-budget: "1e308" is not a positive number/],
    [['--gradient-tolerance', 'NaN'], /--gradient-tolerance: "NaN" is not a positive number/],
    [['--gradient-tolerance', '-1e-4'], /--gradient-tolerance: "-1e-4" is not a positive number/],
    [['--error-tolerance', 'Infinity'], /--error-tolerance: "Infinity" is not a positive number/],
    [['--error-tolerance', '0'], /--error-tolerance: "0" is not a positive number/],
    [['--warm-up', '-1'], /--warm-up: "-1" is not an integer in 0\.\.60000$/],
    [
      ['--experiment', 'random,Drag'],
      /--experiment: unknown experiment "Drag" \(known: random, incremental, drag, reach, gestures, tracik, track\)/,
    ],
    [['--methods', `lm,${'y'.repeat(500)}`], /--methods: unknown method "y{57}\.\.\." \(known:/],
  ] as Array<[string[], RegExp]>)('%j', async (args, pattern) => {
    expectOneLineError(await benchHere('--rig', knight, ...args), 2, pattern);
  });

  it.each(['0x10', '1e3', '1.0', '+5', '0b11', '5_000', '١٢'])(
    '--seed, --samples, --restarts, --workers and --warm-up take only decimal digits, not %j',
    async (value) => {
      for (const flag of ['--seed', '--samples', '--restarts', '--workers', '--warm-up'])
        expectOneLineError(
          await benchHere('--rig', knight, flag, value),
          2,
          new RegExp(`^bench: ${flag}: ${JSON.stringify(value).replace(/[.+]/g, '\\$&')} is not an integer in `),
        );
    },
  );

  it('takes the old names of the renamed flags (--gtol, --ftol, --timeout), saying the new name once each', async () => {
    const old = await benchHere('--rig', knight, '--gtol', '-1', '--ftol=1e-6', '--timeout', '1');
    expect(old.stderr).toContain('bench: --gtol is now --gradient-tolerance\n');
    expect(old.stderr).toContain('bench: --ftol is now --error-tolerance\n');
    expect(old.stderr).toContain('bench: --timeout is now --time-budget\n');
    // The value went to the new flag: its check names it.
    expect(old.stderr).toMatch(/^bench: --gradient-tolerance: "-1" is not a positive number/m);
    expect(old.code).toBe(2);
  });

  it('takes plain decimal integers, leading zeros included', () => {
    const o = parseOptions(
      ['--rig', knight, '--seed', '016', '--samples', '40,gd=07', '--restarts', '0', '--warm-up', '250'],
      false,
      methods,
    )!;
    expect([o.seed, o.samples.lm, o.samples.gd, o.restarts, o.warmUpMs]).toEqual([16, 40, 7, 0, 250]);
  });

  it('merges a repeated --rig, --experiment or --methods into one list, the first replacing the default', () => {
    const o = parseOptions(
      [
        '--rig',
        'lamp',
        '--rig',
        `${knight},hand`,
        '--experiment',
        'drag',
        '--experiment',
        'reach,drag',
        '--methods',
        'lm',
        '--methods',
        'gn',
      ],
      false,
      methods,
    )!;
    expect(o.rigs).toEqual(['lamp', knight, 'hand']);
    expect(o.experiments).toEqual(['drag', 'reach']);
    expect(o.methods).toEqual(['lm', 'gn']);
  });

  it.each([
    ['--seed', '5', '6'],
    ['--samples', '10', '20'],
    ['--time-budget', '1', '2'],
    ['--workers', '1', '2'],
    ['--engine', 'wasm', 'native'],
    ['--json', 'a.json', 'b.json'],
    ['--goals', 'pose', 'position'],
    ['--warm-up', '0', '10'],
  ])('refuses %s given twice instead of keeping the last', async (flag, first, second) => {
    expectOneLineError(
      await benchHere('--rig', knight, flag, first, `${flag}=${second}`),
      2,
      new RegExp(`^bench: ${flag} given twice \\("${second.replace('.', '\\.')}" the second time\\); give it once$`),
    );
  });

  it('refuses a rig given twice, by any name', async () => {
    expectOneLineError(
      await benchHere('--rig', `${knight},lamp,${knight}`),
      2,
      /^bench: --rig: ".*knight\.json" given twice$/,
    );
    expectOneLineError(
      await benchHere('--rig', 'lamp,web/public/models/lamp.glb'),
      2,
      /^bench: --rig: "lamp" and "web\/public\/models\/lamp\.glb" are the same file$/,
    );
  });

  it('refuses samples whose target sets would pass 512 MiB for the rig, before making them', async () => {
    expectOneLineError(
      await benchHere('--rig', knight, '--samples', '1000000'),
      2,
      /knight\.json: 2000000 samples of 129 numbers would take 1969 MiB of target sets, more than 512 MiB: lower --samples$/,
    );
  });
});

describe('--compare: a file that cannot be used is named before the run', () => {
  const empty = join(dir, 'empty.csv');
  writeFileSync(empty, '\n\n');
  it.each([
    [dir, /is a directory, not a CSV file$/],
    ['/dev/zero', /is not a regular file$/],
    [empty, /empty file$/],
  ] as Array<[string, RegExp]>)('%s', async (file, pattern) => {
    const r = await benchHere('--rig', knight, '--compare', file);
    expectOneLineError(r, 1, new RegExp(`^bench: --compare ${file}: ${pattern.source}`));
  });
});

describe('output files: checked before the run', () => {
  const notAFolder = join(dir, 'plain.txt');
  writeFileSync(notAFolder, '');
  const fifo = join(dir, 'fifo.json');
  spawnSync('mkfifo', [fifo]);
  const csv = join(dir, 'compare.csv');
  writeFileSync(csv, 'rig,experiment,method,t_avg_s\nknight,random,gn,0.03\n');
  mkdirSync(join(dir, 'out'));

  // Every case would run 1000 samples of every method first if the check came after the run.
  it.each([
    [['--json', join(dir, 'no-folder', 'x.json')], /--json .*x\.json: folder .*no-folder does not exist$/],
    [['--csv', join(dir, 'out')], /--csv .*out: is a directory$/],
    [['--markdown', join(dir, 'out') + '/'], /--markdown .*out\/: names a folder, not a file$/],
    [['--markdown', join(notAFolder, 'x.md')], /--markdown .*x\.md: .*plain\.txt is not a folder$/],
    [['--json', join(dir, 'out', 'a'), '--csv', join(dir, 'out', 'a')], /--csv .*a: is the file of --json$/],
    [['--csv', csv, '--compare', csv], /--csv .*compare\.csv: is an input of this run$/],
    [['--json', knight], /--json .*knight\.json: is an input of this run$/],
    // Root passes every permission check, yet nothing can be created in /proc: only opening tells.
    [['--json', '/proc/x.json'], /^bench: --json \/proc\/x\.json: cannot be written: ENOENT/],
    [
      ['--csv', join(dir, 'x.csv'), '--markdown', '/sys/x.md'],
      /^bench: --markdown \/sys\/x\.md: cannot be written: EACCES/,
    ],
  ] as Array<[string[], RegExp]>)('%j', async (args, pattern) => {
    expectOneLineError(await benchHere('--rig', knight, ...args), 2, pattern);
  });

  it('leaves no trace of the check: a new file is removed, an existing one keeps its bytes', async () => {
    const fresh = join(dir, 'fresh.csv'),
      kept = join(dir, 'kept.md');
    writeFileSync(kept, 'old results\n');
    expectOneLineError(
      await benchHere('--rig', knight, '--csv', fresh, '--markdown', kept, '--json', '/proc/x.json'),
      2,
      /--json \/proc\/x\.json/,
    );
    expect(existsSync(fresh)).toBe(false);
    expect(readFileSync(kept, 'utf8')).toBe('old results\n');
  });

  it.skipIf(process.getuid?.() === 0)('refuses a folder without write permission', async () => {
    const locked = join(dir, 'locked');
    mkdirSync(locked, { mode: 0o555 });
    expectOneLineError(
      await benchHere('--rig', knight, '--json', join(locked, 'x.json')),
      2,
      /--json .*locked\/x\.json: folder .*locked is not writable$/,
    );
  });

  it.skipIf(!existsSync(fifo))('refuses a FIFO (writing it would wait for a reader)', async () => {
    expectOneLineError(
      await benchHere('--rig', knight, '--json', fifo),
      2,
      /--json .*fifo\.json: is not a regular file$/,
    );
  });

  it('lets outputs share a character device such as /dev/null', () => {
    expect(() =>
      checkOutputs(
        [
          ['--json', '/dev/null'],
          ['--csv', '/dev/null'],
        ],
        [knight],
      ),
    ).not.toThrow();
  });
});

describe('rigs past the limits', () => {
  it('a rig of 10,000 end effectors: one line naming the file', () => {
    // A root with 10,000 leaf bones, each an end effector.
    const leaves = Array.from({ length: 10_000 }, (_, i) => ({
      parent: 0,
      at: [1, 0, 0.001 * i] as [number, number, number],
      length: 1,
    }));
    const file = join(dir, 'leaves.json');
    writeFileSync(
      file,
      writeA7Rig(
        sketchRig(
          [{ parent: -1, at: [0, 0, 0], length: 1 }, ...leaves],
          leaves.map((_, i) => i + 1),
        ),
      ),
    );
    expectOneLineError(bench('--rig', file, '--samples', '2'), 1, /^bench: .*leaves\.json: .*10000 end effectors/);
  });

  it("--no-humanoid-limits benches a recognised humanoid with the file's own limits", async () => {
    const on = await loadBenchRig('character');
    const off = await loadBenchRig(
      'character',
      parseOptions(['--rig', 'character', '--no-humanoid-limits'], false, methods)!.humanoidLimits,
    );
    expect(parseOptions(['--rig', 'character'], false, methods)!.humanoidLimits).toBe(true);
    const knee = on.spec.names.indexOf('mixamorig:LeftLeg');
    expect(Array.from(on.spec.upper.subarray(3 * knee, 3 * knee + 3)).map(Math.round)).toEqual([3, 150, 3]);
    expect(Array.from(off.spec.upper.subarray(3 * knee, 3 * knee + 3))).toEqual([180, 180, 180]);
  });

  it('the native tool knows the same methods as the module, and one that lacks a method is refused', () => {
    expect(() => checkNativeTool(methods)).not.toThrow();
    expect(() => checkNativeTool(['lm', 'simplex'])).toThrow(
      new RegExp(
        `^native engine: .*ik_bench_native has no method "simplex" \\(it knows: ${methods.join(', ')}(, kdl, kdl_nr_jl)?\\); rebuild it`,
      ),
    );
  });

  it('any error of the core while preparing a rig becomes one line naming the rig', async () => {
    const failing = (thrown: unknown): IkCoreModule =>
      new Proxy(
        {},
        {
          get: () => {
            throw thrown;
          },
        },
      ) as IkCoreModule;
    const opts = parseOptions(['--rig', knight], false, methods)!;
    await expect(prepareRigs(opts, failing(new Error('too large\n  details')))).rejects.toMatchObject({
      name: 'BenchError',
      exitCode: 1,
      message: `${knight}: too large`,
    });
    await expect(prepareRigs(opts, failing(7))).rejects.toMatchObject({
      name: 'BenchError',
      message: `${knight}: an exception without a message ([object Number]; out of memory?)`,
    });
  });
});

interface JsonRow {
  [key: string]: unknown;
}

const schema: Record<string, string> = {
  rig: 'string',
  experiment: 'string',
  method: 'string',
  engine: 'string',
  samples: 'number',
  t_avg_s: 'number',
  t_median_s: 'number',
  t_p95_s: 'number',
  t_max_s: 'number',
  iter_avg: 'number',
  E_avg: 'number',
  E_iqm: 'number',
  E_max: 'number',
  success_rate: 'number',
  unreachable: 'number',
};

/** The rows of a run in this process without warm-up, from its --json file. */
async function runJson(args: string[]): Promise<JsonRow[]> {
  const file = join(dir, `out-${Math.random().toString(36).slice(2)}.json`);
  const r = await benchHere(...args, '--warm-up', '0', '--json', file);
  expect(r.stderr).toBe('');
  expect(r.code).toBe(0);
  const doc = JSON.parse(readFileSync(file, 'utf8')) as { rows: JsonRow[] };
  return doc.rows;
}

describe('a small run', () => {
  it('prints a table per rig and experiment and writes the JSON schema', () => {
    // The real command, with a short warm-up.
    const csv = join(dir, 'out.csv');
    const md = join(dir, 'out.md');
    const file = join(dir, 'smoke.json');
    const r = bench(
      '--rig',
      knight,
      '--samples',
      '5',
      '--methods',
      'three-ccd,closed-chain-ik',
      '--time-budget',
      '0.05',
      '--workers',
      '2',
      '--warm-up',
      '20',
      '--json',
      file,
      '--csv',
      csv,
      '--markdown',
      md,
    );
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
      'random three-ccd js',
      'random closed-chain-ik js',
      'incremental three-ccd js',
      'incremental closed-chain-ik js',
    ]);
    expect(readFileSync(csv, 'utf8').split('\n')[0]).toMatch(/^rig,experiment,method,engine,samples,t_avg_s/);
    expect(readFileSync(md, 'utf8')).toMatch(/### knight, random targets\n\n\| method \| engine \|/);
  });

  it('the same seed gives the same solves across engines and worker counts', async () => {
    // The hand: the knight's first reach path is mostly out of reach, which only makes the run slower.
    const hand = rigsLike('chimpanzee-hand')[0].path;
    const args = [
      '--rig',
      hand,
      '--samples',
      '12',
      '--methods',
      'gn,lm',
      '--experiment',
      'incremental,drag,reach',
      '--seed',
      '5',
    ];
    const one = await runJson([...args, '--workers', '1', '--engine', 'wasm,native']);
    const three = await runJson([...args, '--workers', '3', '--engine', 'wasm,native']);
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
      const n = one.find(
        (row) => row.engine === 'native' && row.method === w.method && row.experiment === w.experiment,
      )!;
      expect(n.iter_avg).toBe(w.iter_avg);
      expect(Math.abs((n.E_avg as number) - (w.E_avg as number))).toBeLessThanOrEqual(1e-9 * (w.E_avg as number));
    }
  });
});

describe('the reach experiment', () => {
  it('runs on a project rig, with the drag columns', async () => {
    const file = join(dir, 'reach.json');
    const csv = join(dir, 'reach.csv');
    const r = await benchHere(
      '--rig',
      'lamp',
      '--experiment',
      'reach',
      '--methods',
      'lm',
      '--samples',
      '40',
      '--warm-up',
      '0',
      '--json',
      file,
      '--csv',
      csv,
    );
    expect(r.stderr).toBe('');
    expect(r.code).toBe(0);
    expect(r.stdout).toMatch(/lamp, reach targets/);
    expect(r.stdout).toMatch(/unreachable .* wobble_unreach max {2}jumps {2}flips {2}jump_max_deg/);
    const [row] = (JSON.parse(readFileSync(file, 'utf8')) as { rows: JsonRow[] }).rows;
    for (const [key, type] of Object.entries(schema)) expect(typeof row[key], key).toBe(type);
    expect(row).toMatchObject({ rig: 'lamp', experiment: 'reach', method: 'lm', samples: 40 });
    expect(row.jump_max_deg as number).toBeGreaterThan(0);
    expect(row.jumps).toBe(0); // 1% steps of a lamp's arm: no joint moves 5% of the rig in a step
    expect(readFileSync(csv, 'utf8').split('\n')[0]).toMatch(
      /,success_rate,unreachable,.*,wobble_unreachable_max,jump_max_deg,jumps,flips,stop_reasons$/,
    );
  });

  it('counts steps out of reach as unreachable and leaves them out of success, on both engines', async () => {
    // A straight limb of length 2 from the origin (size 1, tip tolerance 0.001): the path towards
    // its root can be reached by bending. Step t of either path sideways puts the target
    // hypot(2, 0.02 t) from the root, out of reach by more than the reference's margin (half the
    // tip tolerance) from t = 3 on.
    const limb = join(dir, 'limb.json');
    writeFileSync(limb, writeA7Rig(straightLimb()));
    const outOfReach = Array.from(
      { length: 40 },
      (_, i) => Math.hypot(2, 0.02 * (i + 1)) - 2 >= REACH_MARGIN * 0.001,
    ).filter(Boolean).length;
    expect(outOfReach).toBe(38);
    const rows = await runJson([
      '--rig',
      limb,
      '--experiment',
      'reach',
      '--methods',
      'lm',
      '--engine',
      'wasm,native',
      '--time-budget',
      '0.2',
    ]);
    expect(rows.map((row) => row.engine)).toEqual(['wasm', 'native']);
    for (const row of rows) {
      expect(row).toMatchObject({ experiment: 'reach', samples: 120, unreachable: 2 * outOfReach });
      expect(row.success_rate).toBe(1);
    }
  });
});
