// The command line's options: parsing, defaults and checks. Every problem is a BenchError with
// one line of text (exit code 2), so `npm run bench -- --bad` fails the same way as a bad value.
// The list options --rig, --experiment and --methods add up when repeated; any other option given
// twice is refused rather than the last one silently winning.
// Our methods are the core's (its registry, `IkSolver.methods`), given by the caller; the peers
// are the bench's own. The options themselves, with their help and defaults, are declared in
// option_flags.ts; one value's text is checked by option_values.ts.
import { Command, CommanderError } from 'commander';

import { quote } from './errors.js';
import { checkGoals } from './goals_option.js';
import {
  DEFAULT_SAMPLES,
  MAX_RESTARTS,
  MAX_SAMPLES,
  MAX_TIMEOUT_SECONDS,
  MAX_WARM_UP_MS,
  MAX_WORKERS,
  program,
  WORKERS_CAP,
  WORKERS_PER_CORE,
} from './option_flags.js';
import { fileName, integerIn, list, lists, pick, pickOne, positiveNumber, present, usage } from './option_values.js';
import { goalsKinds, type GoalsKind } from './pose_goals.js';
import { experiments, type Experiment } from './target_set.js';
import { applyTracik, checkChain } from './tracik.js';

/** The peers: other libraries' solvers, run in JavaScript (peers/). */
export const peerMethods: readonly string[] = ['three-ccd', 'closed-chain-ik'];
export type Engine = 'wasm' | 'native';
export const engines: readonly Engine[] = ['wasm', 'native'];

/** The track experiment's name (track.ts); it runs alone. */
const TRACK = 'track';
/** The track experiment's largest --noise: a tenth of the height. */
const MAX_TRACK_NOISE = 0.1;

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
  track?: { clips: string[] | 'all'; points: number; noise: number };
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
  noise: string;
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
 * Parses `argv` with `cmd`; a problem becomes a usage error with the first line of commander's
 * message. True when the options were parsed, false when the help was printed instead.
 */
function parseArgv(cmd: Command, argv: string[]): boolean {
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
    if (helped) return false;
    throw e;
  }
  return true;
}

/**
 * Every option's value checked on its own, in this order (of two problems, the first is the one
 * reported); the track experiment's settings are left to trackSettings.
 */
function checkedValues(raw: RawOptions, cmd: Command, allMethods: readonly string[], isTTY: boolean): BenchOptions {
  return {
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
}

/**
 * The track experiment's clips, points (3 or 6) and noise (a share of the height, 0..0.1); a usage
 * error for another experiment, other points or noise, or an output of the other experiments
 * (--markdown, --compare).
 */
function trackSettings(opts: BenchOptions, raw: RawOptions): NonNullable<BenchOptions['track']> {
  if (opts.experiments.length > 0)
    throw usage(`--experiment: track runs alone, not with ${opts.experiments.join(', ')}`);
  const points = integerIn('--points', raw.points, 3, 6);
  if (points !== 3 && points !== 6) throw usage('--points: 3 (head and hands) or 6 (and the hips and feet)');
  if (opts.markdown || opts.compare)
    throw usage(`${opts.markdown ? '--markdown' : '--compare'} goes with the other experiments, not track`);
  const noise = Number(raw.noise) === 0 ? 0 : positiveNumber('--noise', raw.noise, MAX_TRACK_NOISE);
  return { clips: raw.clips.trim() === 'all' ? 'all' : lists('--clips', raw.clips), points, noise };
}

/** A usage error when --clips, --points or --noise was given without the track experiment. */
function refuseTrackOptions(cmd: Command): void {
  for (const flag of ['--clips', '--points', '--noise'] as const)
    if (cmd.getOptionValueSource(flag.slice(2)) !== 'default') throw usage(`${flag} goes with --experiment track only`);
}

/** A usage error when a native-only method (kdl, kdl_nr_jl) would run without the native engine. */
function checkNativeOnly(opts: BenchOptions): void {
  const nativeOnly = opts.methods.find(isNativeOnly);
  if (nativeOnly !== undefined && !opts.engines.includes('native'))
    throw usage(`${nativeOnly} runs only on the native engine: add --engine native`);
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
  if (!parseArgv(cmd, argv)) return undefined;
  const raw = cmd.opts<RawOptions>();
  const opts = checkedValues(raw, cmd, allMethods, isTTY);
  checkChain(opts.chain, opts.rigs);
  const track = lists('--experiment', raw.experiment).includes(TRACK);
  if (track) {
    opts.track = trackSettings(opts, raw);
    return opts;
  }
  refuseTrackOptions(cmd);
  applyTracik(opts, (option) => cmd.getOptionValueSource(option) === 'cli');
  opts.methods = checkGoals(
    opts.goals,
    opts.methods,
    cmd.getOptionValueSource('methods') !== 'default',
    opts.experiments,
    opts.paper,
    opts.compare !== undefined,
  );
  checkNativeOnly(opts);
  return opts;
}
