// One benchmark run: load and check the rigs, make the target sets, run every (rig, experiment,
// method, engine) on them and summarise each into a row. Knows nothing of argv or output files.
import type { IkCoreModule } from '#ik/module.js';
import { IkRig } from '#ik/rig.js';
import { defaultTolerances, dragTolerances, rigSize } from '#rig/tolerances.js';
import { draggableEffectors } from './effectors.js';
import { BenchError, errorLine } from './errors.js';
import { flipLimbs, type FlipLimb } from './flips.js';
import { gesturePaths, gestureSteps, type GestureBody } from './gestures.js';
import { draggedTargetMoves } from './jumps.js';
import { paperIterations, summarize, type Row, type SolveResult } from './metrics.js';
import { isNativeOnly, isPeer, type BenchOptions } from './options.js';
import type { Progress } from './progress.js';
import { REACH_PATH_STEPS, reachPaths } from './reach.js';
import { addOrientations, ORIENTATION_TOLERANCE_DEG } from './pose_goals.js';
import { markReachable, REFERENCE_METHOD } from './reachability.js';
import { loadBenchRig, type BenchRig } from './rigs.js';
import { checkNativeTool, runNative } from './run_native.js';
import { effectiveRestarts } from './make_runner.js';
import { runOnPool, WorkerPool } from './run_wasm.js';
import type { RunSettings } from './runner.js';
import { addFlips, StepMeasurer } from './step_measures.js';
import { tracikSettings } from './tracik.js';
import { hasReachability, isDragging, prefix, project, type Experiment, type TargetSet } from './target_set.js';
import { generateTargets } from './targets.js';

export interface PreparedRig extends BenchRig {
  /** Rig units (rigSize). */
  size: number;
  /** The report's tolerances (random, incremental): gradient, and E (the success test). */
  gradientTolerance: number;
  errorTolerance: number;
  /** Drag and reach: the gradient tolerance, and the tip tolerance of the success test (0: E < errorTolerance). */
  drag: { gradientTolerance: number; tipTolerance: number; maxJointMove: number };
  /** Samples in the whole reach set. */
  reachSteps: number;
  /** Samples in the whole gestures set: 0 for a rig without a recognised humanoid (no gestures). */
  gestureSteps: number;
  /** The limbs whose flips count in drag, reach and gestures (flips.ts; empty: flips not measured). */
  limbs: FlipLimb[];
}

/** Most numbers (float64) the target sets of one rig may hold: 512 MiB. */
const MAX_TARGET_NUMBERS = 2 ** 26;

/**
 * Loads every rig and checks it in the WebAssembly core; fills in tolerances. Drag and reach use
 * the page's drag tolerances (dragTolerances); --gradient-tolerance replaces their gradient tolerance, and
 * --error-tolerance their tip test by E < errorTolerance. Any error is a BenchError naming the --rig entry.
 */
export async function prepareRigs(opts: BenchOptions, ik: IkCoreModule): Promise<PreparedRig[]> {
  const out: PreparedRig[] = [];
  for (const entry of opts.rigs) out.push(await namingRig(entry, () => prepareRig(entry, opts, ik)));
  if (opts.experiments.includes('gestures') && out.every((rig) => rig.gestureSteps === 0)) {
    const why =
      'the gestures experiment needs a humanoid the importer recognises, with hand, foot or head end effectors (npm run rig -- FILE shows the mapping; A7 rigs have none)';
    throw new BenchError(
      out.length === 1 ? `${opts.rigs[0]}: ${why}` : `--experiment gestures: no rig has gestures: ${why}`,
    );
  }
  return out;
}

/**
 * Why `rig` has no gestures rows (a note for the user), or undefined when it has gestures. A run of
 * several rigs leaves those out; a run where no rig has gestures is refused (prepareRigs).
 */
export function noGesturesNote(rig: PreparedRig): string | undefined {
  if (rig.gestureSteps > 0) return undefined;
  return rig.humanoid
    ? `${rig.name}: no gestures (no hand, foot or head end effector of its humanoid)`
    : `${rig.name}: no gestures (the importer recognised no humanoid)`;
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
  const rig = await loadBenchRig(entry, opts.humanoidLimits, opts.chain);
  const core = new IkRig(ik, rig.spec);
  let size: number,
    reachSteps: number,
    gestures = 0;
  try {
    size = rigSize(core.boneTips(new Float64Array(core.numAngles)));
    const rest = project(rig.spec, new Float64Array(core.numAngles));
    reachSteps = reachPaths(rig.spec, core.tips(rest)).length * REACH_PATH_STEPS;
    if (rig.humanoid) gestures = gestureSteps(gesturePaths(rig.spec, gestureBody(rig, core)!, rest, core.tips(rest)));
  } finally {
    core.dispose();
  }
  if (rig.spec.effectors.length === 0) throw new BenchError(`${entry}: no end effectors`);
  if (opts.experiments.includes('drag') && draggableEffectors(rig.spec).length === 0)
    throw new BenchError(
      `${entry}: the drag experiment needs an end effector that can move while the others stay pinned`,
    );
  if (opts.experiments.includes('reach') && reachSteps === 0)
    throw new BenchError(
      `${entry}: the reach experiment needs an end effector that can move while the others stay pinned, its tip off its chain root`,
    );
  const defaults = defaultTolerances(rig.name, rig.format === 'a7', size);
  const drag = dragTolerances(size);
  const prepared: PreparedRig = {
    ...rig,
    size,
    gradientTolerance: opts.gradientTolerance ?? defaults.gradientTolerance,
    errorTolerance: opts.errorTolerance ?? defaults.errorTolerance,
    drag: {
      gradientTolerance: opts.gradientTolerance ?? drag.gradientTolerance,
      tipTolerance: opts.errorTolerance === undefined ? drag.tipTolerance : 0,
      maxJointMove: drag.maxJointMove,
    },
    reachSteps,
    gestureSteps: gestures,
    limbs: flipLimbs(rig.spec, rig.humanoid),
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

/**
 * Samples of `experiment` that `method` solves on `rig` (reach: at most its whole set; gestures:
 * its whole set, or without gestures none, the first --samples steps when that is given).
 */
function samplesOf(rig: PreparedRig, experiment: Experiment, method: string, opts: BenchOptions): number {
  if (experiment === 'reach') return Math.min(opts.samples[method], rig.reachSteps);
  if (experiment === 'gestures')
    return opts.samplesGiven ? Math.min(opts.samples[method], rig.gestureSteps) : rig.gestureSteps;
  return opts.samples[method];
}

/** The humanoid of `rig` for the gestures set, with `core` for its forward kinematics; undefined without one. */
function gestureBody(rig: BenchRig, core: IkRig): GestureBody | undefined {
  return rig.humanoid ? { humanoid: rig.humanoid, poses: (a) => core.poses(a) } : undefined;
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
      if (hasReachability(experiment)) n += largestSet(rig, experiment, opts);
    }
  return n;
}

/**
 * The settings of `method` on `rig` for `experiment`: the report's tolerances for random and
 * incremental; TRAC-IK's for tracik (tracik.ts); for drag, reach and gestures a user's drag in the page (the rig's drag tolerances
 * and joint speed, the page's goals, and no restarts: a restart jumps the whole pose).
 */
export function runSettings(rig: PreparedRig, experiment: Experiment, method: string, opts: BenchOptions): RunSettings {
  const common = {
    method,
    errorTolerance: rig.errorTolerance,
    timeBudgetSeconds: opts.timeBudgetSeconds,
    paper: opts.paper,
    rigSize: rig.size,
  };
  const restarts = opts.restarts === undefined ? {} : { restarts: opts.restarts };
  if (experiment === 'tracik') return { ...common, ...tracikSettings(opts.gradientTolerance), ...restarts };
  if (isDragging(experiment))
    return { ...common, ...rig.drag, restarts: 0, pageGoals: true, pinFrames: rig.humanoid !== null };
  const pose = opts.goals === 'pose' ? { goals: opts.goals, orientationToleranceDeg: ORIENTATION_TOLERANCE_DEG } : {};
  return { ...common, gradientTolerance: rig.gradientTolerance, tipTolerance: 0, ...restarts, ...pose };
}

export interface RunContext {
  opts: BenchOptions;
  ik: IkCoreModule;
  progress: Progress;
  /** Called with each finished row (for streaming output). */
  onRow?: (row: Row) => void;
}

/** The experiments of the run that `rig` takes part in (all but gestures on a rig without them). */
export function experimentsOf(rig: PreparedRig, opts: BenchOptions): Experiment[] {
  return opts.experiments.filter((e) => e !== 'gestures' || rig.gestureSteps > 0);
}

/**
 * Target sets for one rig: one per experiment it takes part in, as long as the longest method
 * needs; with --goals pose each with the effectors' orientations at the target angles.
 */
export function targetSetsFor(rig: PreparedRig, opts: BenchOptions, ik: IkCoreModule): Map<Experiment, TargetSet> {
  const core = new IkRig(ik, rig.spec);
  try {
    const make = (e: Experiment): TargetSet => {
      const count = largestSet(rig, e, opts);
      const set = generateTargets(rig.spec, e, count, opts.seed, (a) => core.tips(a), gestureBody(rig, core));
      return opts.goals === 'pose' ? addOrientations(set, (a) => core.tipRotations(a)) : set;
    };
    return new Map(experimentsOf(rig, opts).map((e) => [e, make(e)]));
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
  const needsPool =
    opts.experiments.some(hasReachability) || opts.methods.some((m) => isPeer(m) || opts.engines.includes('wasm'));
  const ours = opts.methods.filter((m) => !isPeer(m));
  if (ours.length > 0 && opts.engines.includes('native')) checkNativeTool(ours);
  // No more workers than the longest set has solves: the others would only take memory.
  const longest = Math.max(...rigs.flatMap((rig) => experimentsOf(rig, opts).map((e) => largestSet(rig, e, opts))));
  const pool = needsPool ? await WorkerPool.create(Math.min(opts.workers, longest), opts.warmUpMs) : undefined;
  const rows: Row[] = [];
  try {
    for (const rig of rigs) {
      const sets = await namingRig(rig.path, () => targetSetsFor(rig, opts, ik));
      for (const experiment of experimentsOf(rig, opts).filter(hasReachability)) {
        progress.label(`${rig.name} ${experiment}: reachability (${REFERENCE_METHOD} with restarts, untimed)`);
        await markReachable(
          pool!,
          rig.path,
          rig.spec,
          runSettings(rig, experiment, REFERENCE_METHOD, opts),
          sets.get(experiment)!,
          (n) => progress.advance(n),
        );
      }
      // Forward kinematics in this thread: how far each step moves its dragged target, and the
      // native engine's flips.
      const core = new IkRig(ik, rig.spec);
      try {
        const measurer = new StepMeasurer(rig.spec, core, rig.limbs);
        for (const experiment of experimentsOf(rig, opts)) {
          const dragging = isDragging(experiment);
          const all = sets.get(experiment)!;
          const targetMoves = dragging ? draggedTargetMoves(all, (a) => core.tips(a)) : undefined;
          for (const method of opts.methods) {
            const set = prefix(all, samplesOf(rig, experiment, method, opts));
            const settings = runSettings(rig, experiment, method, opts);
            const limbs = dragging ? rig.limbs : null;
            for (const engine of enginesFor(method, opts)) {
              progress.label(`${rig.name} ${experiment} ${method} ${engine}`);
              const results =
                engine === 'native'
                  ? await runNative(rig.spec, settings, set, opts.workers, (n) => progress.advance(n))
                  : await runOnPool(pool!, rig.path, rig.spec, settings, set, (n) => progress.advance(n), limbs);
              if (engine === 'native' && dragging) addFlips(results, set, measurer);
              const counted = settings.paper && !isPeer(method) ? results.map(countedAsThePaper) : results;
              const jumpRule = targetMoves
                ? { targetMoves: targetMoves.subarray(0, set.count), size: rig.size }
                : undefined;
              const stats = summarize(
                { rig: rig.name, experiment, method, engine, goals: opts.goals },
                counted,
                settings,
                set.reachable,
                jumpRule,
              );
              const row: Row = { ...stats, restarts: effectiveRestarts(ik, settings) };
              rows.push(row);
              ctx.onRow?.(row);
            }
          }
        }
      } finally {
        core.dispose();
      }
    }
  } finally {
    await pool?.close();
  }
  return rows;
}
