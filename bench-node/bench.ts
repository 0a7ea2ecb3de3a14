// One benchmark run: load and check the rigs, make the target sets, run every (rig, experiment,
// method, engine) on them and summarise each into a row. Knows nothing of argv or output files.
import type { IkCoreModule } from '../web/src/ik/module.js';
import { IkRig } from '../web/src/ik/rig.js';
import { defaultTolerances, dragTolerances, rigSize } from '../web/src/rig/tolerances.js';
import { draggableEffectors } from './effectors.js';
import { BenchError, errorLine } from './errors.js';
import { paperIterations, summarize, type Row, type SolveResult } from './metrics.js';
import { isNativeOnly, isPeer, type BenchOptions } from './options.js';
import type { Progress } from './progress.js';
import { REACH_PATH_STEPS, reachPaths } from './reach.js';
import { addOrientations, ORIENTATION_TOLERANCE_DEG } from './pose_goals.js';
import { markReachable, REFERENCE_METHOD } from './reachability.js';
import { loadBenchRig, type BenchRig } from './rigs.js';
import { checkNativeTool, runNative } from './run_native.js';
import { effectiveRestarts } from './runners.js';
import { runOnPool, WorkerPool } from './run_wasm.js';
import type { RunSettings } from './runner.js';
import { generateTargets, isDragging, prefix, project, type Experiment, type TargetSet } from './targets.js';

export interface PreparedRig extends BenchRig {
  /** Rig units (rigSize). */
  size: number;
  /** The report's tolerances (random, incremental): gradient, and E (the success test). */
  gtol: number;
  ftol: number;
  /** Drag and reach: the gradient tolerance, and the tip tolerance of the success test (0: E < ftol). */
  drag: { gtol: number; tipTolerance: number };
  /** Samples in the whole reach set. */
  reachSteps: number;
}

/** Most numbers (float64) the target sets of one rig may hold: 512 MiB. */
const MAX_TARGET_NUMBERS = 2 ** 26;

/**
 * Loads every rig and checks it in the WebAssembly core; fills in tolerances. Drag and reach use
 * the page's drag tolerances (dragTolerances); --gtol replaces their gradient tolerance, and
 * --ftol their tip test by E < ftol. Any error is a BenchError naming the --rig entry.
 */
export async function prepareRigs(opts: BenchOptions, ik: IkCoreModule): Promise<PreparedRig[]> {
  const out: PreparedRig[] = [];
  for (const entry of opts.rigs) out.push(await namingRig(entry, () => prepareRig(entry, opts, ik)));
  return out;
}

/** `work()`, with any error but a BenchError turned into one line naming the --rig entry. */
async function namingRig<T>(entry: string, work: () => T | Promise<T>): Promise<T> {
  try {
    return await work();
  } catch (e) {
    if (e instanceof BenchError) throw e;
    throw new BenchError(`${entry}: ${errorLine(e)}`);
  }
}

/** One rig of prepareRigs. */
async function prepareRig(entry: string, opts: BenchOptions, ik: IkCoreModule): Promise<PreparedRig> {
  const rig = await loadBenchRig(entry, opts.humanoidLimits);
  const core = new IkRig(ik, rig.spec);
  let size: number, reachSteps: number;
  try {
    size = rigSize(core.boneTips(new Float64Array(core.numAngles)));
    reachSteps = reachPaths(rig.spec, core.tips(project(rig.spec, new Float64Array(core.numAngles)))).length * REACH_PATH_STEPS;
  } finally {
    core.dispose();
  }
  if (rig.spec.effectors.length === 0) throw new BenchError(`${entry}: no end effectors`);
  if (opts.experiments.includes('drag') && draggableEffectors(rig.spec).length === 0)
    throw new BenchError(`${entry}: the drag experiment needs an end effector that can move while the others stay pinned`);
  if (opts.experiments.includes('reach') && reachSteps === 0)
    throw new BenchError(`${entry}: the reach experiment needs an end effector that can move while the others stay pinned, its tip off its chain root`);
  const defaults = defaultTolerances(rig.name, rig.format === 'a7', size);
  const drag = dragTolerances(size);
  const prepared: PreparedRig = {
    ...rig,
    size,
    gtol: opts.gtol ?? defaults.gtol,
    ftol: opts.ftol ?? defaults.ftol,
    drag: { gtol: opts.gtol ?? drag.gradientTolerance, tipTolerance: opts.ftol === undefined ? drag.tipTolerance : 0 },
    reachSteps,
  };
  checkTargetSetSize(entry, prepared, opts);
  return prepared;
}

/** Refuses (usage error) a --samples that would make the rig's target sets exceed MAX_TARGET_NUMBERS. */
function checkTargetSetSize(entry: string, rig: PreparedRig, opts: BenchOptions): void {
  // start, target angles, targets (and with --goals pose the orientations)
  const perSample = 2 * rig.spec.lower.length + (opts.goals === 'pose' ? 7 : 3) * rig.spec.effectors.length;
  const samples = opts.experiments.reduce((n, e) => n + largestSet(rig, e, opts), 0);
  if (samples * perSample <= MAX_TARGET_NUMBERS) return;
  const mib = (numbers: number): string => `${Math.ceil((8 * numbers) / 2 ** 20)} MiB`;
  throw new BenchError(
    `${entry}: ${samples} samples of ${perSample} numbers would take ${mib(samples * perSample)} of target sets, ` +
      `more than ${mib(MAX_TARGET_NUMBERS)}: lower --samples`,
    2,
  );
}

/** The engines a method runs on: ours on each requested engine, kdl on the native one, the peers in JavaScript. */
export function enginesFor(method: string, opts: BenchOptions): string[] {
  return isPeer(method) ? ['js'] : isNativeOnly(method) ? ['native'] : opts.engines;
}

/** Samples of `experiment` that `method` solves on `rig` (reach: at most its whole set). */
function samplesOf(rig: PreparedRig, experiment: Experiment, method: string, opts: BenchOptions): number {
  return experiment === 'reach' ? Math.min(opts.samples[method], rig.reachSteps) : opts.samples[method];
}

/** Samples of the longest set one method solves in `experiment` on `rig`. */
function largestSet(rig: PreparedRig, experiment: Experiment, opts: BenchOptions): number {
  return Math.max(...opts.methods.map((m) => samplesOf(rig, experiment, m, opts)));
}

/** Number of solves a run will do (reach's reference solves included), for the progress bar. */
export function totalSolves(opts: BenchOptions, rigs: readonly PreparedRig[]): number {
  let n = 0;
  for (const rig of rigs)
    for (const experiment of opts.experiments) {
      for (const m of opts.methods) n += samplesOf(rig, experiment, m, opts) * enginesFor(m, opts).length;
      if (experiment === 'reach') n += largestSet(rig, experiment, opts);
    }
  return n;
}

/**
 * The settings of `method` on `rig` for `experiment`: the report's tolerances for random and
 * incremental; for drag and reach a user's drag (the rig's drag tolerances, and no restarts: a
 * restart jumps the whole pose).
 */
export function runSettings(rig: PreparedRig, experiment: Experiment, method: string, opts: BenchOptions): RunSettings {
  const common = { method, ftol: rig.ftol, timeoutSeconds: opts.timeoutSeconds, paper: opts.paper, rigSize: rig.size };
  if (isDragging(experiment)) return { ...common, ...rig.drag, restarts: 0 };
  const pose = opts.goals === 'pose' ? { goals: opts.goals, orientationToleranceDeg: ORIENTATION_TOLERANCE_DEG } : {};
  return { ...common, gtol: rig.gtol, tipTolerance: 0, ...(opts.restarts === undefined ? {} : { restarts: opts.restarts }), ...pose };
}

export interface RunContext {
  opts: BenchOptions;
  ik: IkCoreModule;
  progress: Progress;
  /** Called with each finished row (for streaming output). */
  onRow?: (row: Row) => void;
}

/**
 * Target sets for one rig: one per experiment, as long as the longest method needs; with --goals
 * pose each with the effectors' orientations at the target angles.
 */
export function targetSetsFor(rig: PreparedRig, opts: BenchOptions, ik: IkCoreModule): Map<Experiment, TargetSet> {
  const core = new IkRig(ik, rig.spec);
  try {
    const count = Math.max(...opts.methods.map((m) => opts.samples[m]));
    const make = (e: Experiment): TargetSet => {
      const set = generateTargets(rig.spec, e, count, opts.seed, (a) => core.tips(a));
      return opts.goals === 'pose' ? addOrientations(set, (a) => core.tipRotations(a)) : set;
    };
    return new Map(opts.experiments.map((e) => [e, make(e)]));
  } finally {
    core.dispose();
  }
}

/** A paper-mode result with its iterations counted as the report's runner counted them. */
function countedAsThePaper(r: SolveResult): SolveResult {
  return { ...r, iterations: paperIterations(r.iterations, r.stopReason) };
}

/** Runs everything; rows in (rig, experiment, method, engine) order. */
export async function runBench(rigs: readonly PreparedRig[], ctx: RunContext): Promise<Row[]> {
  const { opts, ik, progress } = ctx;
  const needsPool = opts.experiments.includes('reach') || opts.methods.some((m) => isPeer(m) || opts.engines.includes('wasm'));
  const ours = opts.methods.filter((m) => !isPeer(m));
  if (ours.length > 0 && opts.engines.includes('native')) checkNativeTool(ours);
  // No more workers than the longest set has solves: the others would only take memory.
  const longest = Math.max(...rigs.flatMap((rig) => opts.experiments.map((e) => largestSet(rig, e, opts))));
  const pool = needsPool ? await WorkerPool.create(Math.min(opts.workers, longest), opts.warmUpMs) : undefined;
  const rows: Row[] = [];
  try {
    for (const rig of rigs) {
      const sets = await namingRig(rig.path, () => targetSetsFor(rig, opts, ik));
      const reach = sets.get('reach');
      if (reach) {
        progress.label(`${rig.name} reach: reachability (${REFERENCE_METHOD} with restarts, untimed)`);
        await markReachable(pool!, rig.path, rig.spec, runSettings(rig, 'reach', REFERENCE_METHOD, opts), reach, (n) => progress.advance(n));
      }
      for (const experiment of opts.experiments) {
        for (const method of opts.methods) {
          const set = prefix(sets.get(experiment)!, opts.samples[method]);
          const settings = runSettings(rig, experiment, method, opts);
          for (const engine of enginesFor(method, opts)) {
            progress.label(`${rig.name} ${experiment} ${method} ${engine}`);
            const results =
              engine === 'native'
                ? await runNative(rig.spec, settings, set, opts.workers, (n) => progress.advance(n))
                : await runOnPool(pool!, rig.path, rig.spec, settings, set, (n) => progress.advance(n));
            const counted = settings.paper && !isPeer(method) ? results.map(countedAsThePaper) : results;
            const stats = summarize({ rig: rig.name, experiment, method, engine, goals: opts.goals }, counted, settings, set.reachable);
            const row: Row = { ...stats, restarts: effectiveRestarts(ik, settings) };
            rows.push(row);
            ctx.onRow?.(row);
          }
        }
      }
    }
  } finally {
    await pool?.close();
  }
  return rows;
}
