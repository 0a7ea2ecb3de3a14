// The WebAssembly engine (and the JavaScript peers): a pool of worker threads. The main thread
// compiles the .wasm once and posts the compiled WebAssembly.Module to every worker, which only
// instantiates it: its own memory and instance, without compiling the module again. A target set
// is cut into batches of whole independent ranges (single samples, or whole drag paths), so what
// each solve sees never depends on the number of workers; results come back in sample order.
import { readFileSync } from 'node:fs';
import { Worker } from 'node:worker_threads';

import type { RigSpec } from '#ik/rig_arrays.js';
import { wasmPath } from '#ik/node.js';
import { BenchError } from './errors.js';
import type { FlipLimb } from './flips.js';
import type { SolveResult } from './metrics.js';
import type { RunSettings } from './runner.js';
import { independentRanges, type TargetSet } from './target_set.js';
import type { WorkerInit, WorkerReply, WorkerTask } from './worker_protocol.js';

/** Batches per worker a target set is cut into (more: better balance, more messages). */
const BATCHES_PER_WORKER = 8;

interface Pending {
  task: WorkerTask;
  resolve: (results: SolveResult[]) => void;
  reject: (error: Error) => void;
  onProgress: (solved: number) => void;
  solved: number;
}

export class WorkerPool {
  private readonly idle: Worker[] = [];
  private readonly queue: Pending[] = [];
  private readonly busy = new Map<Worker, Pending>();
  private nextId = 1;

  private constructor(private readonly workers: Worker[]) {}

  /**
   * Starts `size` workers sharing one compiled module, each warming every new runner up for
   * `warmUpMs` milliseconds (warm_up.ts); resolves when all are ready.
   */
  static async create(size: number, warmUpMs: number): Promise<WorkerPool> {
    const wasmModule = await WebAssembly.compile(readFileSync(wasmPath));
    const init: WorkerInit = { wasmModule, warmUpMs };
    const workers = Array.from(
      { length: size },
      () => new Worker(new URL('./worker_boot.mjs', import.meta.url), { workerData: init }),
    );
    const pool = new WorkerPool(workers);
    await Promise.all(
      workers.map(
        (w) =>
          new Promise<void>((resolve, reject) => {
            const onMessage = (m: WorkerReply): void => {
              if (m.kind !== 'ready') return;
              w.off('message', onMessage);
              resolve();
            };
            w.on('message', onMessage);
            w.once('error', reject);
          }),
      ),
    );
    for (const w of workers) {
      w.on('message', (m: WorkerReply) => pool.onMessage(w, m));
      w.on('error', (e) => pool.onError(w, e));
      pool.idle.push(w);
    }
    return pool;
  }

  get size(): number {
    return this.workers.length;
  }

  /** Runs one batch; `onProgress` gets the number of solves finished so far in it. */
  run(task: Omit<WorkerTask, 'id' | 'kind'>, onProgress: (solved: number) => void): Promise<SolveResult[]> {
    return new Promise((resolve, reject) => {
      this.queue.push({ task: { ...task, kind: 'task', id: this.nextId++ }, resolve, reject, onProgress, solved: 0 });
      this.dispatch();
    });
  }

  private dispatch(): void {
    while (this.idle.length > 0 && this.queue.length > 0) {
      const worker = this.idle.pop()!;
      const pending = this.queue.shift()!;
      this.busy.set(worker, pending);
      worker.postMessage(pending.task);
    }
  }

  private onMessage(worker: Worker, m: WorkerReply): void {
    const pending = this.busy.get(worker);
    if (!pending || m.kind === 'ready' || m.id !== pending.task.id) return;
    if (m.kind === 'progress') {
      pending.onProgress(m.solved - pending.solved);
      pending.solved = m.solved;
      return;
    }
    this.busy.delete(worker);
    this.idle.push(worker);
    if (m.kind === 'done') pending.resolve(m.results);
    else pending.reject(new BenchError(`worker: ${m.message}`));
    this.dispatch();
  }

  private onError(worker: Worker, e: Error): void {
    const pending = this.busy.get(worker);
    this.busy.delete(worker);
    pending?.reject(new BenchError(`worker crashed: ${e.message.split('\n')[0]}`));
  }

  async close(): Promise<void> {
    await Promise.all(this.workers.map((w) => w.terminate()));
  }
}

/** Cuts a set into batches of whole independent ranges: [begin, end) sample intervals. */
export function batchesOf(set: TargetSet, batches: number): Array<[number, number]> {
  const ranges = independentRanges(set);
  const per = Math.max(1, Math.ceil(set.count / Math.max(1, batches)));
  const out: Array<[number, number]> = [];
  let begin = 0,
    end = 0;
  for (const [b, e] of ranges) {
    if (end > begin && e - begin > per) {
      out.push([begin, end]);
      begin = b;
    }
    end = e;
  }
  if (end > begin) out.push([begin, end]);
  return out;
}

/**
 * Runs every sample of `set` on the pool; results in sample order. `limbs` (drag, reach,
 * gestures): the rig's limbs for the step measures (joint move, flips); null: none measured.
 */
export async function runOnPool(
  pool: WorkerPool,
  rigKey: string,
  spec: RigSpec,
  settings: RunSettings,
  set: TargetSet,
  onProgress: (solved: number) => void,
  limbs: FlipLimb[] | null = null,
): Promise<SolveResult[]> {
  const m = set.numAngles,
    r = set.numResiduals;
  const parts = batchesOf(set, pool.size * BATCHES_PER_WORKER).map(([begin, end]) =>
    pool.run(
      {
        rigKey,
        spec,
        settings,
        count: end - begin,
        numAngles: m,
        numResiduals: r,
        starts: set.starts.slice(begin * m, end * m),
        targets: set.targets.slice(begin * r, end * r),
        orientations: set.orientations?.slice((begin * 4 * r) / 3, (end * 4 * r) / 3) ?? null,
        chained: set.chained.slice(begin, end),
        dragged: set.dragged.slice(begin, end),
        limbs,
      },
      onProgress,
    ),
  );
  return (await Promise.all(parts)).flat();
}
