// The bench command's options as commander declares them, in the order of its help: flags, help
// text, defaults, and the limits of their values (options.ts checks the values against them).
import { availableParallelism } from 'node:os';

import { Command, Option } from 'commander';

import { quote } from './errors.js';
import { usage } from './option_values.js';
import { experiments } from './target_set.js';
import { WARM_UP_MS } from './warm_up.js';

/** Solves of one method per experiment: the default, and the largest --samples value. */
export const DEFAULT_SAMPLES = 1000;
export const MAX_SAMPLES = 1_000_000;
/**
 * Worker threads or native processes --workers takes per core, and in all. Each worker holds its
 * own WebAssembly instance (about 45 MB), and more workers than cores only share the cores.
 */
export const WORKERS_PER_CORE = 4;
export const WORKERS_CAP = 64;
export const MAX_WORKERS = Math.min(WORKERS_CAP, WORKERS_PER_CORE * availableParallelism());
/** Most --restarts per solve. */
export const MAX_RESTARTS = 1_000_000;
/** Longest --timeout, seconds per solve. */
export const MAX_TIMEOUT_SECONDS = 3600;
/** Longest --warm-up, milliseconds. */
export const MAX_WARM_UP_MS = 60_000;

/** What the help adds after a list option's description. */
const MERGED = ' (repeatable: --rig a --rig b is --rig a,b)';

/** Makers of the command's options, which differ in what a second use of the option does. */
interface OptionMakers {
  /** A list option: its values add up when repeated (the first one replaces the default). */
  listOption: (flags: string, description: string) => Option;
  /** Any other option with a value, refused the second time; `fallback` is its default. */
  single: (flags: string, description: string, fallback?: string) => Option;
}

/** The option makers of one command line: they share the record of the flags given so far. */
function optionMakers(): OptionMakers {
  const seen = new Set<string>();
  const collect = (value: string, previous: string | string[]): string[] =>
    Array.isArray(previous) ? [...previous, value] : [value];
  function once(flag: string): (value: string) => string {
    return (value) => {
      if (seen.has(flag)) throw usage(`${flag} given twice (${quote(value)} the second time); give it once`);
      seen.add(flag);
      return value;
    };
  }
  return {
    listOption: (flags, description) => new Option(flags, `${description}${MERGED}`).argParser(collect),
    single: (flags, description, fallback) => {
      const option = new Option(flags, description).argParser(once(flags.split(' ')[0]));
      return fallback === undefined ? option : option.default(fallback);
    },
  };
}

/** The options saying what runs: the rigs and their chain, the experiments (track's clips and points), the methods. */
function addWhatRuns(
  cmd: Command,
  make: OptionMakers,
  allMethods: readonly string[],
  defaultMethods: readonly string[],
): void {
  cmd
    .addOption(
      make
        .listOption('--rig <paths>', 'rig files (.glb, .gltf, A7 .json) or project rig names, comma-separated')
        .makeOptionMandatory(),
    )
    .addOption(
      make.single(
        '--chain <base:tip>',
        'URDF rigs: the chain, from its base link to its tip link (default: the longest serial chain)',
      ),
    )
    .addOption(
      make
        .listOption(
          '--experiment <list>',
          `experiments: ${experiments.filter((e) => e !== 'tracik').join(', ')}, or track or tracik alone`,
        )
        .default('random,incremental'),
    )
    .addOption(make.single('--clips <list>', 'track: the animation clips to run, comma-separated, or all', 'all'))
    .addOption(
      make.single('--points <n>', 'track: tracked points, 3 (head and hands) or 6 (and the hips and feet)', '3'),
    )
    .addOption(
      make.single(
        '--noise <share>',
        "track: each tracked position jitters by up to half this share of the height on each coordinate, seeded by --seed (a tracker's noise)",
        '0',
      ),
    )
    .addOption(
      make
        .listOption('--methods <list>', `methods: ${allMethods.join(', ')} (kdl, kdl_nr_jl: --engine native only)`)
        .default(defaultMethods.join(',')),
    );
}

/**
 * The options of each solve: samples and seed, the tolerances, the time budget (seconds) and
 * restarts, paper mode, the goals' kind and a humanoid's limits.
 */
function addSolveSettings(cmd: Command, make: OptionMakers): void {
  cmd
    .addOption(
      make.single(
        '--samples <n>',
        `samples per experiment (at most ${MAX_SAMPLES}); per-method overrides like 1000,gd=100`,
        String(DEFAULT_SAMPLES),
      ),
    )
    .addOption(make.single('--seed <s>', 'seed of the target sets', '1'))
    .addOption(make.single('--gradient-tolerance <x>', 'gradient tolerance (default: per rig, see README; was --gtol)'))
    .addOption(
      make.single(
        '--error-tolerance <y>',
        'E tolerance, also the success threshold (default: per rig; drag and reach: a tip distance, see README; was --ftol)',
      ),
    )
    .addOption(
      make.single(
        '--time-budget <seconds>',
        `time budget per solve (at most ${MAX_TIMEOUT_SECONDS}; was --timeout)`,
        '1',
      ),
    )
    .addOption(
      make.single(
        '--restarts <n>',
        `restarts per solve for every method, peers included, within the time budget (random and incremental; default: the solvers' default; at most ${MAX_RESTARTS})`,
      ),
    )
    .option('--paper', "the report's original algorithms (solver paper mode)", false)
    .addOption(
      make.single(
        '--goals <kind>',
        `targets per end effector: position (the protocol's tip positions) or pose (tip position and frame orientation)`,
        'position',
      ),
    )
    .option(
      '--no-humanoid-limits',
      "a recognised humanoid keeps the file's own limits (extras.ik or +-180) instead of anatomical ones",
    );
}

/** The options of the run: engines and workers, the files written and compared, the progress bar, the warm-up (milliseconds). */
function addRunSettings(cmd: Command, make: OptionMakers): void {
  cmd
    .addOption(make.single('--engine <list>', 'wasm, native, or both (prints the ratio)', 'wasm'))
    .addOption(
      make.single(
        '--workers <n>',
        `worker threads (native: processes), at most ${MAX_WORKERS}`,
        String(Math.min(availableParallelism(), MAX_WORKERS)),
      ),
    )
    .addOption(make.single('--json <file>', 'write the rows as JSON (checked writable before the run)'))
    .addOption(make.single('--csv <file>', 'write the rows as CSV (checked writable before the run)'))
    .addOption(make.single('--markdown <file>', 'write the tables as Markdown (checked writable before the run)'))
    .addOption(
      make.single(
        '--compare <file>',
        'a results CSV of the report (results.csv, original-measured.csv) to print beside ours',
      ),
    )
    .option('--no-progress', 'no progress bar even on a terminal')
    .addOption(
      make.single(
        '--warm-up <ms>',
        'untimed solving per worker and method before timing (0: a single solve; times then include V8 compiling)',
        String(WARM_UP_MS),
      ),
    );
}

/** The bench command: its options in the order of its help, what runs first, then each solve's settings, then the run's. */
export function program(allMethods: readonly string[], defaultMethods: readonly string[]): Command {
  const make = optionMakers();
  const cmd = new Command('bench').description(
    "Benchmarks the IK solvers on the report's target sets and more (see bench-node/README.md).",
  );
  addWhatRuns(cmd, make, allMethods, defaultMethods);
  addSolveSettings(cmd, make);
  addRunSettings(cmd, make);
  return cmd.helpOption('-h, --help').allowExcessArguments(false).showSuggestionAfterError(true);
}
