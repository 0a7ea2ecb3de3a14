// The command line's options: parsing, defaults and checks. Every problem is a BenchError with
// one line of text (exit code 2), so `npm run bench -- --bad` fails the same way as a bad value.
import { availableParallelism } from 'node:os';

import { Command, CommanderError, Option } from 'commander';

import { BenchError } from './errors.js';
import { experiments, type Experiment } from './targets.js';

export const ownMethods = ['gd', 'bfgs', 'gn', 'newton', 'lm'] as const;
export const peerMethods = ['three-ccd', 'closed-chain-ik'] as const;
export const allMethods: readonly string[] = [...ownMethods, ...peerMethods];
export type Method = (typeof ownMethods)[number] | (typeof peerMethods)[number];
export type Engine = 'wasm' | 'native';
export const engines: readonly Engine[] = ['wasm', 'native'];

export function isPeer(method: string): boolean {
  return (peerMethods as readonly string[]).includes(method);
}

export interface BenchOptions {
  rigs: string[];
  experiments: Experiment[];
  methods: Method[];
  /** Samples per method (a --samples default plus METHOD=N overrides). */
  samples: Record<Method, number>;
  seed: number;
  /** Overrides of the per-rig default tolerances; undefined means the rig's default. */
  gtol?: number;
  ftol?: number;
  timeoutSeconds: number;
  paper: boolean;
  engines: Engine[];
  workers: number;
  json?: string;
  csv?: string;
  markdown?: string;
  compare?: string;
  progress: boolean;
}

const usage = (message: string): BenchError => new BenchError(message, 2);

function list(value: string): string[] {
  return value
    .split(',')
    .map((s) => s.trim())
    .filter((s) => s.length > 0);
}

function positiveNumber(flag: string, value: string): number {
  const x = Number(value);
  if (value.trim() === '' || !Number.isFinite(x) || x <= 0) throw usage(`${flag}: "${value}" is not a positive number`);
  return x;
}

function positiveInteger(flag: string, value: string): number {
  const x = Number(value);
  if (!Number.isInteger(x) || x <= 0) throw usage(`${flag}: "${value}" is not a positive integer`);
  return x;
}

function pick<T extends string>(flag: string, values: string[], known: readonly T[], what: string): T[] {
  if (values.length === 0) throw usage(`${flag}: empty list`);
  for (const v of values)
    if (!(known as readonly string[]).includes(v)) throw usage(`unknown ${what} "${v}" (known: ${known.join(', ')})`);
  return [...new Set(values)] as T[];
}

/** `1000` or `1000,gd=100`: a default plus per-method overrides. */
function parseSamples(value: string): Record<Method, number> {
  let fallback = 1000;
  const overrides: Partial<Record<Method, number>> = {};
  for (const entry of list(value)) {
    const eq = entry.indexOf('=');
    if (eq < 0) {
      fallback = positiveInteger('--samples', entry);
      continue;
    }
    const method = entry.slice(0, eq);
    if (!allMethods.includes(method)) throw usage(`unknown method "${method}" in --samples (known: ${allMethods.join(', ')})`);
    overrides[method as Method] = positiveInteger(`--samples ${method}`, entry.slice(eq + 1));
  }
  const out = {} as Record<Method, number>;
  for (const m of allMethods as Method[]) out[m] = overrides[m] ?? fallback;
  return out;
}

function program(): Command {
  return new Command('bench')
    .description('Benchmarks the IK solvers on target sets of ../shared/paper/PROTOCOL.md (see bench-node/README.md).')
    .addOption(new Option('--rig <paths>', 'rig files (.glb, .gltf, A7 .json) or project rig names, comma-separated').makeOptionMandatory())
    .option('--experiment <list>', `experiments: ${experiments.join(', ')}`, 'random,incremental')
    .option('--methods <list>', `methods: ${allMethods.join(', ')}`, allMethods.join(','))
    .option('--samples <n>', 'samples per experiment; per-method overrides like 1000,gd=100', '1000')
    .option('--seed <s>', 'seed of the target sets', '1')
    .option('--gtol <x>', 'gradient tolerance (default: per rig, see README)')
    .option('--ftol <y>', 'E tolerance, also the success threshold (default: per rig; drag and reach: a tip distance, see README)')
    .option('--timeout <seconds>', 'time budget per solve', '1')
    .option('--paper', "the report's original algorithms (solver paper mode)", false)
    .option('--engine <list>', 'wasm, native, or both (prints the ratio)', 'wasm')
    .option('--workers <n>', 'worker threads (native: processes)', String(availableParallelism()))
    .option('--json <file>', 'write the rows as JSON')
    .option('--csv <file>', 'write the rows as CSV')
    .option('--markdown <file>', 'write the tables as Markdown')
    .option('--compare <file>', "a CSV like ../shared/paper/original-measured.csv to print beside ours")
    .option('--no-progress', 'no progress bar even on a terminal')
    .helpOption('-h, --help')
    .allowExcessArguments(false)
    .showSuggestionAfterError(true);
}

interface RawOptions {
  rig: string;
  experiment: string;
  methods: string;
  samples: string;
  seed: string;
  gtol?: string;
  ftol?: string;
  timeout: string;
  paper: boolean;
  engine: string;
  workers: string;
  json?: string;
  csv?: string;
  markdown?: string;
  compare?: string;
  progress: boolean;
}

/**
 * Parses argv (without node and the script). Returns undefined after printing help.
 * Throws BenchError (exit code 2) with one line for any problem.
 */
export function parseOptions(argv: string[], isTTY: boolean): BenchOptions | undefined {
  const cmd = program();
  let helped = false;
  cmd.exitOverride((err: CommanderError) => {
    if (err.code === 'commander.helpDisplayed' || err.code === 'commander.help') {
      helped = true;
      throw err;
    }
    throw usage(err.message.replace(/^error: /, '').split('\n')[0]);
  });
  cmd.configureOutput({ writeErr: () => {}, outputError: () => {} });
  try {
    cmd.parse(argv, { from: 'user' });
  } catch (e) {
    if (helped) return undefined;
    throw e;
  }
  const raw = cmd.opts<RawOptions>();
  const methods = pick('--methods', list(raw.methods), allMethods, 'method') as Method[];
  const seed = Number(raw.seed);
  if (!Number.isInteger(seed) || seed < 0 || seed > 0xffffffff) throw usage(`--seed: "${raw.seed}" is not an integer in 0..4294967295`);
  const rigs = list(raw.rig);
  if (rigs.length === 0) throw usage('--rig: empty list');
  return {
    rigs,
    experiments: pick('--experiment', list(raw.experiment), experiments, 'experiment'),
    methods,
    samples: parseSamples(raw.samples),
    seed,
    gtol: raw.gtol === undefined ? undefined : positiveNumber('--gtol', raw.gtol),
    ftol: raw.ftol === undefined ? undefined : positiveNumber('--ftol', raw.ftol),
    timeoutSeconds: positiveNumber('--timeout', raw.timeout),
    paper: raw.paper,
    engines: pick('--engine', list(raw.engine), engines, 'engine'),
    workers: positiveInteger('--workers', raw.workers),
    json: raw.json,
    csv: raw.csv,
    markdown: raw.markdown,
    compare: raw.compare,
    progress: raw.progress && isTTY,
  };
}
