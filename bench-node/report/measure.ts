// The measurements of bench:report, each read as JSON from the program that makes it: the
// benchmark command line (`--json`), wasm/tools/solver_speed and scale_bench (`--json`), natively
// and in WebAssembly, and the heap check (heap_growth.ts, in this process).
import { spawnSync } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { join } from 'node:path';

import type { Row } from '../metrics.js';
import { measureHeapGrowth, type HeapGrowth } from './heap_growth.js';

/** Samples per rig and experiment for section 4 (at most). */
export const PEER_SAMPLES = 200;

/** What to measure, and where. */
export interface ReportPlan {
  /** Samples per rig and experiment; gd takes gdSamples. */
  samples: number;
  gdSamples: number;
  /** The report's A7 rigs (paths, in the report's order) and the project's rigs (names). */
  a7Rigs: string[];
  projectRigs: readonly string[];
  /** A folder for the intermediate JSON files. */
  work: string;
}

/** One row of wasm/tools/solver_speed --json (times in seconds). */
export interface SolverSpeedRow {
  set: string;
  method: string;
  samples: number;
  t_median_s: number;
  t_mean_s: number;
  success_rate: number;
}

/** One row of wasm/tools/scale_bench --json. */
export interface ScaleRow {
  shape: string;
  bones: number;
  angles: number;
  effectors: number;
  us_per_iteration: number;
  ns_per_angle_effector: number;
  iterations_median: number;
  success_rate: number;
}

/** The solver core alone on one rig, on one engine. */
export interface CoreRow extends SolverSpeedRow {
  rig: string;
  engine: 'native' | 'wasm';
}

export interface Measurements {
  /** 1. lm (restarts on) on the A7 and project rigs, random and incremental, both engines. */
  defaults: Row[];
  /** 2. gd, bfgs, gn in normal mode on the A7 rigs; 2b. the same with --paper and the original's sample counts. */
  classic: Row[];
  paper: Row[];
  /**
   * 4. lm against the peers on the A7 rigs, each with the solvers' default restarts and with none
   * (the same restart policy for every method): three-ccd and closed-chain-ik beside lm in
   * WebAssembly, kdl beside lm natively.
   */
  peers: Row[];
  /** 4. solver_speed on the A7 rigs, native and WebAssembly. */
  core: CoreRow[];
  /** 5. scale_bench, native and WebAssembly. */
  scale: { native: ScaleRow[]; wasm: ScaleRow[] };
  /** 6. The heap check. */
  heap: HeapGrowth;
  /** 7. lm on drag and reach, every rig (the A7 ones named "NAME (A7)"). */
  dragging: Row[];
}

/** Runs `command args`, returns its stdout; throws with its stderr when it fails. */
function run(command: string, args: string[]): string {
  process.stderr.write(`bench:report: ${command} ${args.join(' ')}\n`);
  const r = spawnSync(command, args, { encoding: 'utf8', maxBuffer: 1 << 28 });
  if (r.status !== 0) throw new Error(`${command} ${args.join(' ')} failed (${r.status}):\n${r.stderr}`);
  return r.stdout;
}

/** `npm run bench` with `args`, its rows read from its --json file `work/NAME.json`. */
function bench(plan: ReportPlan, name: string, args: string[]): Row[] {
  const file = join(plan.work, `${name}.json`);
  run('npx', ['tsx', 'bench-node/cli.ts', ...args, '--no-progress', '--json', file]);
  return (JSON.parse(readFileSync(file, 'utf8')) as { rows: Row[] }).rows;
}

/** A native tool (build/native/NAME) or its WebAssembly build (build/wasm/NAME.cjs) run with `args`, its JSON output. */
function tool<T>(engine: 'native' | 'wasm', name: string, args: string[]): T {
  const out =
    engine === 'native' ? run(`build/native/${name}`, args) : run('node', [`build/wasm/${name}.cjs`, ...args]);
  return JSON.parse(out) as T;
}

/** The rig's display name: its file's base name. */
const baseName = (path: string): string =>
  path
    .split('/')
    .pop()!
    .replace(/\.json$/, '');

/** Runs every measurement of the plan (minutes to hours: see the sample count). */
export async function measure(plan: ReportPlan): Promise<Measurements> {
  const { samples, gdSamples, a7Rigs, projectRigs } = plan;
  const a7 = a7Rigs.join(',');
  const defaults = bench(plan, 'default', [
    '--rig',
    [...a7Rigs, ...projectRigs].join(','),
    '--methods',
    'lm',
    '--samples',
    String(samples),
    '--engine',
    'wasm,native',
  ]);
  const classic = bench(plan, 'classic', [
    '--rig',
    a7,
    '--methods',
    'gd,bfgs,gn',
    '--samples',
    `${samples},gd=${gdSamples}`,
  ]);
  // The original's success rate, which its CSV lacks: the original algorithms (--paper) on the
  // same targets, with the original's sample counts (GD 50, the others 300).
  const paper = bench(plan, 'paper', [
    '--rig',
    a7,
    '--methods',
    'gd,bfgs,gn',
    '--paper',
    '--samples',
    `${Math.min(samples, 300)},gd=${Math.min(samples, 50)}`,
  ]);
  // Failed peer solves use the whole 1 s budget: at most 200 samples each.
  const peerArgs = ['--rig', a7, '--samples', String(Math.min(samples, PEER_SAMPLES))];
  const peers: Row[] = [];
  for (const restarts of [[], ['--restarts', '0']]) {
    const tag = restarts.length ? 'no-restarts' : 'restarts';
    peers.push(...bench(plan, `peers-${tag}`, [...peerArgs, '--methods', 'lm,three-ccd,closed-chain-ik', ...restarts]));
    peers.push(...bench(plan, `kdl-${tag}`, [...peerArgs, '--methods', 'lm,kdl', '--engine', 'native', ...restarts]));
  }
  const core: CoreRow[] = [];
  for (const path of a7Rigs)
    for (const engine of ['native', 'wasm'] as const) {
      const rows = tool<SolverSpeedRow[]>(engine, 'solver_speed', [
        path,
        '--methods',
        'lm',
        '--samples',
        String(Math.min(samples, 500)),
        '--json',
      ]);
      core.push(...rows.map((r) => ({ ...r, rig: baseName(path), engine })));
    }
  const scale = {
    native: tool<ScaleRow[]>('native', 'scale_bench', ['--json']),
    wasm: tool<ScaleRow[]>('wasm', 'scale_bench', ['--json']),
  };
  process.stderr.write(`bench:report: heap check, ${samples * 1000} solves\n`);
  const heap = await measureHeapGrowth(samples * 1000);
  const dragArgs = ['--experiment', 'drag,reach', '--methods', 'lm', '--samples', String(samples)];
  // The A7 rigs and the project's share names, so the A7 ones are labelled.
  const dragging = [
    ...bench(plan, 'dragging-a7', ['--rig', a7, ...dragArgs]).map((r) => ({ ...r, rig: `${r.rig} (A7)` })),
    ...bench(plan, 'dragging-project', ['--rig', projectRigs.join(','), ...dragArgs]),
  ];
  return { defaults, classic, paper, peers, core, scale, heap, dragging };
}
