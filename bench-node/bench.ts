// One benchmark run: load and check the rigs, make the target sets, run every (rig, experiment,
// method, engine) on them and summarise each into a row. Knows nothing of argv or output files.
import type { IkCoreModule } from '../web/src/ik/module.js';
import { IkRig } from '../web/src/ik/rig.js';
import { defaultTolerances, rigSize } from '../web/src/rig/tolerances.js';
import { BenchError } from './errors.js';
import { summarize, type Row } from './metrics.js';
import { isPeer, type BenchOptions, type Method } from './options.js';
import type { Progress } from './progress.js';
import { loadBenchRig, type BenchRig } from './rigs.js';
import { checkNativeTool, runNative } from './run_native.js';
import { runOnPool, WorkerPool } from './run_wasm.js';
import type { RunSettings } from './runner.js';
import { draggableEffectors, generateTargets, prefix, type Experiment, type TargetSet } from './targets.js';

export interface PreparedRig extends BenchRig {
  size: number;
  gtol: number;
  ftol: number;
}

/** Loads every rig and checks it in the WebAssembly core; fills in tolerances. */
export async function prepareRigs(opts: BenchOptions, ik: IkCoreModule): Promise<PreparedRig[]> {
  const out: PreparedRig[] = [];
  for (const entry of opts.rigs) {
    const rig = await loadBenchRig(entry);
    let core: IkRig;
    try {
      core = new IkRig(ik, rig.spec);
    } catch (e) {
      throw new BenchError(`rig ${entry}: ${(e as Error).message.split('\n')[0]}`);
    }
    const size = rigSize(core.boneTips(new Float64Array(core.numAngles)));
    core.dispose();
    if (rig.spec.effectors.length === 0) throw new BenchError(`rig ${entry}: no end effectors`);
    if (opts.experiments.includes('drag') && draggableEffectors(rig.spec).length === 0)
      throw new BenchError(`rig ${entry}: the drag experiment needs an end effector that can move while the others stay pinned`);
    const defaults = defaultTolerances(rig.name, rig.format === 'a7', size);
    out.push({ ...rig, size, gtol: opts.gtol ?? defaults.gtol, ftol: opts.ftol ?? defaults.ftol });
  }
  return out;
}

/** The engines a method runs on: ours on each requested engine, the peers in JavaScript. */
export function enginesFor(method: Method, opts: BenchOptions): string[] {
  return isPeer(method) ? ['js'] : opts.engines;
}

/** Number of solves a run will do, for the progress bar. */
export function totalSolves(opts: BenchOptions, rigs: number): number {
  let n = 0;
  for (const method of opts.methods) n += opts.samples[method] * enginesFor(method, opts).length;
  return n * rigs * opts.experiments.length;
}

export interface RunContext {
  opts: BenchOptions;
  ik: IkCoreModule;
  progress: Progress;
  /** Called with each finished row (for streaming output). */
  onRow?: (row: Row) => void;
}

/** Target sets for one rig: one per experiment, as long as the longest method needs. */
export function targetSetsFor(rig: PreparedRig, opts: BenchOptions, ik: IkCoreModule): Map<Experiment, TargetSet> {
  const core = new IkRig(ik, rig.spec);
  try {
    const count = Math.max(...opts.methods.map((m) => opts.samples[m]));
    return new Map(opts.experiments.map((e) => [e, generateTargets(rig.spec, e, count, opts.seed, (a) => core.tips(a))]));
  } finally {
    core.dispose();
  }
}

/** Runs everything; rows in (rig, experiment, method, engine) order. */
export async function runBench(rigs: readonly PreparedRig[], ctx: RunContext): Promise<Row[]> {
  const { opts, ik, progress } = ctx;
  const needsPool = opts.methods.some((m) => isPeer(m) || opts.engines.includes('wasm'));
  if (opts.methods.some((m) => !isPeer(m)) && opts.engines.includes('native')) checkNativeTool();
  const pool = needsPool ? await WorkerPool.create(opts.workers) : undefined;
  const rows: Row[] = [];
  try {
    for (const rig of rigs) {
      const sets = targetSetsFor(rig, opts, ik);
      for (const experiment of opts.experiments) {
        for (const method of opts.methods) {
          const set = prefix(sets.get(experiment)!, opts.samples[method]);
          const settings: RunSettings = {
            method,
            gtol: rig.gtol,
            ftol: rig.ftol,
            timeoutSeconds: opts.timeoutSeconds,
            paper: opts.paper,
            rigSize: rig.size,
            // Dragging never restarts (as on the page): a restart jumps the whole pose.
            ...(experiment === 'drag' ? { restarts: 0 } : {}),
          };
          for (const engine of enginesFor(method, opts)) {
            progress.label(`${rig.name} ${experiment} ${method} ${engine}`);
            const results =
              engine === 'native'
                ? await runNative(rig.spec, settings, set, opts.workers, (n) => progress.advance(n))
                : await runOnPool(pool!, rig.path, rig.spec, settings, set, (n) => progress.advance(n));
            const row = summarize({ rig: rig.name, experiment, method, engine }, results, rig.ftol);
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
