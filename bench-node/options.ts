// The command line's options: parsing, defaults and checks. Every problem is a BenchError with
// one line of text (exit code 2), so `npm run bench -- --bad` fails the same way as a bad value.
// The list options --rig, --experiment and --methods add up when repeated; any other option given
// twice is refused rather than the last one silently winning.
// Our methods are the core's (its registry, `IkSolver.methods`), given by the caller; the peers
// are the bench's own.
import { availableParallelism } from 'node:os';

import { Command, CommanderError, Option } from 'commander';

import { BenchError, quote } from './errors.js';
import { checkGoals } from './goals_option.js';
import { goalsKinds, type GoalsKind } from './pose_goals.js';
import { experiments, type Experiment } from './target_set.js';
import { applyTracik, checkChain } from './tracik.js';
import { WARM_UP_MS } from './warm_up.js';

/** The peers: other libraries' solvers, run in JavaScript (peers/). */
export const peerMethods: readonly string[] = ['three-ccd', 'closed-chain-ik'];
export type Engine = 'wasm' | 'native';
export const engines: readonly Engine[] = ['wasm', 'native'];

/** The track experiment's name (track.ts); it runs alone. */
const TRACK = 'track';

export function isPeer(method: string): boolean {
  return (peerMethods as readonly string[]).includes(method);
}

/** Methods of the native engine only (ik_bench_native, built with Orocos KDL): not in the --methods default. */
export const nativeOnlyMethods: readonly string[] = ['kdl', 'kdl_nr_jl'];

export function isNativeOnly(method: string): boolean {
  return (nativeOnlyMethods as readonly string[]).includes(method);
}

export interface BenchOptions {
  rigs: string[];
  /** --chain BASE:TIP: the chain of every rig, URDF files only (the importer's default: the longest serial chain). */
  chain?: string;
  experiments: Experiment[];
  methods: string[];
  /** Samples per known method (a --samples default plus METHOD=N overrides). */
  samples: Record<string, number>;
  /** Whether --samples was given: without it the gestures experiment runs its whole set. */
  samplesGiven: boolean;
  seed: number;
  /** Overrides of the per-rig default tolerances; undefined means the rig's default. */
  gradientTolerance?: number;
  errorTolerance?: number;
  timeBudgetSeconds: number;
  /** Restarts per solve for every method (random, incremental); undefined: the solvers' default. */
  restarts?: number;
  paper: boolean;
  /** A recognised humanoid's anatomical limits (the importer's default); false: the file's own (extras.ik or +-180). */
  humanoidLimits: boolean;
  engines: Engine[];
  workers: number;
  json?: string;
  csv?: string;
  markdown?: string;
  compare?: string;
  progress: boolean;
  /** Untimed solving per worker and runner before timing, milliseconds (warm_up.ts). */
  warmUpMs: number;
  /** What each effector's target is: its tip position (the protocol's), or its tip frame's pose (pose_goals.ts). */
  goals: GoalsKind;
  /** The track experiment (track.ts) instead of the others: the clips to run ('all': every one) and the tracked points. */
  track?: { clips: string[] | 'all'; points: number };
}

/** Solves of one method per experiment: the default, and the largest --samples value. */
const DEFAULT_SAMPLES = 1000;
const MAX_SAMPLES = 1_000_000;
/**
 * Worker threads or native processes --workers takes per core, and in all. Each worker holds its
 * own WebAssembly instance (about 45 MB), and more workers than cores only share the cores.
 */
const WORKERS_PER_CORE = 4;
const WORKERS_CAP = 64;
const MAX_WORKERS = Math.min(WORKERS_CAP, WORKERS_PER_CORE * availableParallelism());
/** Most --restarts per solve. */
const MAX_RESTARTS = 1_000_000;
/** Longest --timeout, seconds per solve. */
const MAX_TIMEOUT_SECONDS = 3600;
/** Longest --warm-up, milliseconds. */
const MAX_WARM_UP_MS = 60_000;

const usage = (message: string): BenchError => new BenchError(message, 2);

/** `value` itself; a usage error naming `flag` when it is empty or blank. */
function present(flag: string, value: string): string {
  if (value.trim() === '') throw usage(`${flag}: empty value`);
  return value;
}

/** The comma-separated items of `value`, trimmed; a usage error when there are none. */
function list(flag: string, value: string): string[] {
  const items = present(flag, value)
    .split(',')
    .map((s) => s.trim())
    .filter((s) => s.length > 0);
  if (items.length === 0) throw usage(`${flag}: empty list ${quote(value)}`);
  return items;
}

/** The items of every value a list option was given (it may be repeated: --rig a --rig b is --rig a,b). */
function lists(flag: string, values: string | string[]): string[] {
  return (Array.isArray(values) ? values : [values]).flatMap((v) => list(flag, v));
}

/**
 * Commander's parsers for options given more than once: a list option collects its values (the
 * first one replaces the default), any other option is refused the second time.
 */
function repeats(): {
  collect: (value: string, previous: string | string[]) => string[];
  once: (flag: string) => (value: string) => string;
} {
  const seen = new Set<string>();
  return {
    collect: (value, previous) => (Array.isArray(previous) ? [...previous, value] : [value]),
    once: (flag) => (value) => {
      if (seen.has(flag)) throw usage(`${flag} given twice (${quote(value)} the second time); give it once`);
      seen.add(flag);
      return value;
    },
  };
}

/** A finite number above 0 and at most `max`. */
function positiveNumber(flag: string, value: string, max = Infinity): number {
  const x = Number(present(flag, value));
  if (!Number.isFinite(x) || x <= 0 || x > max)
    throw usage(`${flag}: ${quote(value)} is not a positive number${Number.isFinite(max) ? ` of at most ${max}` : ''}`);
  return x;
}

/**
 * An integer in min..max written in plain decimal digits (no 0x10, 1e3, 1.0 or blanks, which
 * Number() would take); `why` follows the range in the message.
 */
function integerIn(flag: string, value: string, min: number, max: number, why = ''): number {
  const x = /^-?\d+$/.test(present(flag, value)) ? Number(value) : NaN;
  if (!Number.isSafeInteger(x) || x < min || x > max)
    throw usage(`${flag}: ${quote(value)} is not an integer in ${min}..${max}${why}`);
  return x;
}

/** The items of `value`, each one of `known`, without repeats. */
function pick<T extends string>(flag: string, value: string | string[], known: readonly T[], what: string): T[] {
  const values = lists(flag, value);
  for (const v of values)
    if (!(known as readonly string[]).includes(v))
      throw usage(`${flag}: unknown ${what} ${quote(v)} (known: ${known.join(', ')})`);
  return [...new Set(values)] as T[];
}

/** One of `known`. */
function pickOne<T extends string>(flag: string, value: string, known: readonly T[], what: string): T {
  const v = present(flag, value).trim();
  if (!(known as readonly string[]).includes(v))
    throw usage(`${flag}: unknown ${what} ${quote(v)} (known: ${known.join(', ')})`);
  return v as T;
}

/** `1000` or `1000,gd=100`: a default plus per-method overrides (methods of `allMethods`), each in 1..MAX_SAMPLES. */
function parseSamples(value: string, allMethods: readonly string[]): Record<string, number> {
  let fallback: number | undefined;
  const overrides = new Map<string, number>();
  for (const entry of list('--samples', value)) {
    const eq = entry.indexOf('=');
    if (eq < 0) {
      if (fallback !== undefined) throw usage(`--samples: two defaults in ${quote(value)}`);
      fallback = integerIn('--samples', entry, 1, MAX_SAMPLES);
      continue;
    }
    const method = entry.slice(0, eq).trim();
    if (!allMethods.includes(method))
      throw usage(`--samples: unknown method ${quote(method)} in ${quote(value)} (known: ${allMethods.join(', ')})`);
    if (overrides.has(method)) throw usage(`--samples: ${method} given twice in ${quote(value)}`);
    overrides.set(method, integerIn(`--samples ${method}`, entry.slice(eq + 1), 1, MAX_SAMPLES));
  }
  return Object.fromEntries(allMethods.map((m) => [m, overrides.get(m) ?? fallback ?? DEFAULT_SAMPLES]));
}

/** An output or --compare file name; undefined when the option is absent. */
function fileName(flag: string, value: string | undefined): string | undefined {
  return value === undefined ? undefined : present(flag, value);
}

function program(allMethods: readonly string[], defaultMethods: readonly string[]): Command {
  const { collect, once } = repeats();
  const single = (flags: string, description: string, fallback?: string): Option => {
    const option = new Option(flags, description).argParser(once(flags.split(' ')[0]));
    return fallback === undefined ? option : option.default(fallback);
  };
  const merged = ' (repeatable: --rig a --rig b is --rig a,b)';
  return new Command('bench')
    .description("Benchmarks the IK solvers on the report's target sets and more (see bench-node/README.md).")
    .addOption(
      new Option('--rig <paths>', `rig files (.glb, .gltf, A7 .json) or project rig names, comma-separated${merged}`)
        .argParser(collect)
        .makeOptionMandatory(),
    )
    .addOption(
      single(
        '--chain <base:tip>',
        'URDF rigs: the chain, from its base link to its tip link (default: the longest serial chain)',
      ),
    )
    .addOption(
      new Option(
        '--experiment <list>',
        `experiments: ${experiments.filter((e) => e !== 'tracik').join(', ')}, or track or tracik alone${merged}`,
      )
        .argParser(collect)
        .default('random,incremental'),
    )
    .addOption(single('--clips <list>', 'track: the animation clips to run, comma-separated, or all', 'all'))
    .addOption(single('--points <n>', 'track: tracked points, 3 (head and hands) or 6 (and the hips and feet)', '3'))
    .addOption(
      new Option(
        '--methods <list>',
        `methods: ${allMethods.join(', ')} (kdl, kdl_nr_jl: --engine native only)${merged}`,
      )
        .argParser(collect)
        .default(defaultMethods.join(',')),
    )
    .addOption(
      single(
        '--samples <n>',
        `samples per experiment (at most ${MAX_SAMPLES}); per-method overrides like 1000,gd=100`,
        String(DEFAULT_SAMPLES),
      ),
    )
    .addOption(single('--seed <s>', 'seed of the target sets', '1'))
    .addOption(single('--gradient-tolerance <x>', 'gradient tolerance (default: per rig, see README; was --gtol)'))
    .addOption(
      single(
        '--error-tolerance <y>',
        'E tolerance, also the success threshold (default: per rig; drag and reach: a tip distance, see README; was --ftol)',
      ),
    )
    .addOption(
      single('--time-budget <seconds>', `time budget per solve (at most ${MAX_TIMEOUT_SECONDS}; was --timeout)`, '1'),
    )
    .addOption(
      single(
        '--restarts <n>',
        `restarts per solve for every method, peers included, within the time budget (random and incremental; default: the solvers' default; at most ${MAX_RESTARTS})`,
      ),
    )
    .option('--paper', "the report's original algorithms (solver paper mode)", false)
    .addOption(
      single(
        '--goals <kind>',
        `targets per end effector: position (the protocol's tip positions) or pose (tip position and frame orientation)`,
        'position',
      ),
    )
    .option(
      '--no-humanoid-limits',
      "a recognised humanoid keeps the file's own limits (extras.ik or +-180) instead of anatomical ones",
    )
    .addOption(single('--engine <list>', 'wasm, native, or both (prints the ratio)', 'wasm'))
    .addOption(
      single(
        '--workers <n>',
        `worker threads (native: processes), at most ${MAX_WORKERS}`,
        String(Math.min(availableParallelism(), MAX_WORKERS)),
      ),
    )
    .addOption(single('--json <file>', 'write the rows as JSON (checked writable before the run)'))
    .addOption(single('--csv <file>', 'write the rows as CSV (checked writable before the run)'))
    .addOption(single('--markdown <file>', 'write the tables as Markdown (checked writable before the run)'))
    .addOption(
      single(
        '--compare <file>',
        'a results CSV of the report (results.csv, original-measured.csv) to print beside ours',
      ),
    )
    .option('--no-progress', 'no progress bar even on a terminal')
    .addOption(
      single(
        '--warm-up <ms>',
        'untimed solving per worker and method before timing (0: a single solve; times then include V8 compiling)',
        String(WARM_UP_MS),
      ),
    )
    .helpOption('-h, --help')
    .allowExcessArguments(false)
    .showSuggestionAfterError(true);
}

interface RawOptions {
  /** The list options: the default as a string, the values given as an array. */
  rig: string[];
  chain?: string;
  experiment: string | string[];
  methods: string | string[];
  samples: string;
  seed: string;
  gradientTolerance?: string;
  errorTolerance?: string;
  timeBudget: string;
  restarts?: string;
  paper: boolean;
  goals: string;
  humanoidLimits: boolean;
  engine: string;
  workers: string;
  json?: string;
  csv?: string;
  markdown?: string;
  compare?: string;
  progress: boolean;
  warmUp: string;
  clips: string;
  points: string;
}

/** The flags renamed to the core's option names, the old name still taken: old -> new. */
export const RENAMED_FLAGS: Readonly<Record<string, string>> = {
  '--gtol': '--gradient-tolerance',
  '--ftol': '--error-tolerance',
  '--timeout': '--time-budget',
};

/** `argv` with each renamed flag (--gtol x, --gtol=x) under its new name; `note` gets a line saying so for each. */
function renamedFlags(argv: string[], note: (text: string) => void): string[] {
  return argv.map((arg) => {
    const [flag, ...value] = arg.split('=');
    const renamed = RENAMED_FLAGS[flag];
    if (renamed === undefined) return arg;
    note(`bench: ${flag} is now ${renamed}\n`);
    return [renamed, ...value].join('=');
  });
}

/**
 * Parses argv (without node and the script); `ownMethods` are the core's methods (IkSolver.methods),
 * the default first; `note` gets a line per renamed flag used (RENAMED_FLAGS). Returns undefined after printing help. Throws BenchError (exit code 2) with
 * one line for any problem.
 */
export function parseOptions(
  argv: string[],
  isTTY: boolean,
  ownMethods: readonly string[],
  note: (text: string) => void = () => {},
): BenchOptions | undefined {
  argv = renamedFlags(argv, note);
  const allMethods = [...ownMethods, ...nativeOnlyMethods, ...peerMethods];
  const cmd = program(allMethods, [...ownMethods, ...peerMethods]);
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
  const opts: BenchOptions = {
    rigs: lists('--rig', raw.rig),
    chain: raw.chain === undefined ? undefined : present('--chain', raw.chain).trim(),
    experiments: pick('--experiment', raw.experiment, [...experiments, TRACK], 'experiment').filter(
      (e): e is Experiment => e !== TRACK,
    ),
    methods: pick('--methods', raw.methods, allMethods, 'method'),
    samples: parseSamples(raw.samples, allMethods),
    samplesGiven: cmd.getOptionValueSource('samples') !== 'default',
    seed: integerIn('--seed', raw.seed, 0, 0xffffffff),
    gradientTolerance:
      raw.gradientTolerance === undefined ? undefined : positiveNumber('--gradient-tolerance', raw.gradientTolerance),
    errorTolerance:
      raw.errorTolerance === undefined ? undefined : positiveNumber('--error-tolerance', raw.errorTolerance),
    timeBudgetSeconds: positiveNumber('--time-budget', raw.timeBudget, MAX_TIMEOUT_SECONDS),
    restarts: raw.restarts === undefined ? undefined : integerIn('--restarts', raw.restarts, 0, MAX_RESTARTS),
    paper: raw.paper,
    humanoidLimits: raw.humanoidLimits,
    engines: pick('--engine', raw.engine, engines, 'engine'),
    workers: integerIn(
      '--workers',
      raw.workers,
      1,
      MAX_WORKERS,
      ` (${WORKERS_PER_CORE} per core, ${WORKERS_CAP} at most)`,
    ),
    json: fileName('--json', raw.json),
    csv: fileName('--csv', raw.csv),
    markdown: fileName('--markdown', raw.markdown),
    compare: fileName('--compare', raw.compare),
    progress: raw.progress && isTTY,
    warmUpMs: integerIn('--warm-up', raw.warmUp, 0, MAX_WARM_UP_MS),
    goals: pickOne('--goals', raw.goals, goalsKinds, 'goal kind'),
  };
  checkChain(opts.chain, opts.rigs);
  const track = lists('--experiment', raw.experiment).includes(TRACK);
  if (track) {
    if (opts.experiments.length > 0)
      throw usage(`--experiment: track runs alone, not with ${opts.experiments.join(', ')}`);
    const points = integerIn('--points', raw.points, 3, 6);
    if (points !== 3 && points !== 6) throw usage('--points: 3 (head and hands) or 6 (and the hips and feet)');
    if (opts.markdown || opts.compare)
      throw usage(`${opts.markdown ? '--markdown' : '--compare'} goes with the other experiments, not track`);
    opts.track = { clips: raw.clips.trim() === 'all' ? 'all' : lists('--clips', raw.clips), points };
    return opts;
  }
  for (const flag of ['--clips', '--points'] as const)
    if (cmd.getOptionValueSource(flag.slice(2)) !== 'default') throw usage(`${flag} goes with --experiment track only`);
  applyTracik(opts, (option) => cmd.getOptionValueSource(option) === 'cli');
  opts.methods = checkGoals(
    opts.goals,
    opts.methods,
    cmd.getOptionValueSource('methods') !== 'default',
    opts.experiments,
    opts.paper,
    opts.compare !== undefined,
  );
  const nativeOnly = opts.methods.find(isNativeOnly);
  if (nativeOnly !== undefined && !opts.engines.includes('native'))
    throw usage(`${nativeOnly} runs only on the native engine: add --engine native`);
  return opts;
}
