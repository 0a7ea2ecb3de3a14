// Worker threads that run cases, each under a watchdog: a case that runs longer than the hang
// limit is recorded as a hang, its worker is stopped and a new one started. The limit counts
// from when a file case's input is drawn (drawing it gets a limit of its own). A worker that
// dies is a crash of its case, and is replaced too.
import { readFileSync } from 'node:fs';
import { Worker } from 'node:worker_threads';

import { wasmPath } from '#ik/node.js';
import type { CaseId, CaseReport } from './case_id.js';
import { modelFolder, type Fixture } from './fixture.js';
import { releaseFifos } from './folder.js';
import type { Outcome } from './outcome.js';
import type { FromWorker, WorkerInit } from './worker_protocol.js';

/** How long a worker gets to stop before it is left behind. */
const TERMINATE_SECONDS = 3;

/** One worker slot: the thread and the case it runs. */
class Slot {
  private worker: Worker | undefined;
  /** Settles when the current worker is ready (a replacement may be starting). */
  private ready: Promise<void>;
  private running:
    { id: CaseId; notes: string[]; began: number; finish: (r: CaseReport) => void; timer: NodeJS.Timeout } | undefined;

  constructor(
    private readonly init: WorkerInit,
    private readonly hangSeconds: number,
  ) {
    this.ready = this.spawn();
  }

  /** Runs case `id` to its report (a hang or a dead worker included). */
  async run(id: CaseId): Promise<CaseReport> {
    await this.ready;
    return new Promise((finish) => {
      this.running = { id, notes: [], began: performance.now(), finish, timer: this.watch() };
      this.worker!.postMessage({ type: 'run', id });
    });
  }

  async close(): Promise<void> {
    await this.ready;
    await this.stop();
  }

  private spawn(): Promise<void> {
    const worker = new Worker(new URL('./worker_boot.mjs', import.meta.url), { workerData: this.init });
    this.worker = worker;
    const mine = (): boolean => this.worker === worker;
    return new Promise((ready, failed) => {
      worker.on('message', (m: FromWorker) => {
        if (!mine()) return;
        if (m.type === 'ready') ready();
        else if (m.type === 'note') this.running?.notes.push(m.text);
        else if (m.type === 'drawn') this.rewatch();
        else this.finish(m.report);
      });
      worker.on('error', (e) => {
        if (!mine()) return;
        if (this.running) this.replace({ kind: 'crash', message: `the worker died: ${e.name}: ${e.message}` });
        else failed(e);
      });
      worker.on(
        'exit',
        (code) =>
          mine() && this.running && this.replace({ kind: 'crash', message: `the worker exited with code ${code}` }),
      );
    });
  }

  /** The watchdog: the running case is a hang if it has not finished within the limit. */
  private watch(): NodeJS.Timeout {
    return setTimeout(
      () => this.replace({ kind: 'hang', message: `still running after ${this.hangSeconds} s` }),
      this.hangSeconds * 1000,
    );
  }

  /** Starts the limit again: drawing the case's input (test code) is not counted as running it. */
  private rewatch(): void {
    if (!this.running) return;
    clearTimeout(this.running.timer);
    this.running.timer = this.watch();
  }

  private finish(report: CaseReport): void {
    const r = this.running;
    if (!r) return;
    clearTimeout(r.timer);
    this.running = undefined;
    r.finish(report);
  }

  /** Ends the running case with `outcome` and starts a new worker in place of this one. */
  private replace(outcome: Outcome): void {
    const r = this.running!;
    this.ready = this.stop().then(() => this.spawn());
    this.finish({
      id: r.id,
      description: r.notes.join('; '),
      outcome,
      budgets: [],
      seconds: (performance.now() - r.began) / 1000,
    });
  }

  /** Stops the worker: first releases FIFOs a loader may be blocked on (a blocked open() would hold terminate()). */
  private async stop(): Promise<void> {
    const worker = this.worker;
    if (!worker) return;
    this.worker = undefined;
    releaseFifos(modelFolder(this.init.fixture, this.init.worker));
    const timeout = new Promise<void>((done) => setTimeout(done, TERMINATE_SECONDS * 1000).unref());
    await Promise.race([worker.terminate(), timeout]);
    worker.unref();
  }
}

/** Runs cases on `size` workers. */
export class CasePool {
  private constructor(private readonly slots: Slot[]) {}

  /** Starts the workers (the core is compiled once here). */
  static async create(size: number, fixture: Fixture, hangSeconds: number): Promise<CasePool> {
    const wasmModule = await WebAssembly.compile(readFileSync(wasmPath));
    return new CasePool(
      Array.from({ length: size }, (_, worker) => new Slot({ wasmModule, fixture, worker }, hangSeconds)),
    );
  }

  /** Runs every case of `ids`, calling `onReport` as each finishes; the reports in the order of `ids`. */
  async runAll(ids: readonly CaseId[], onReport: (r: CaseReport) => void): Promise<CaseReport[]> {
    const reports: CaseReport[] = new Array(ids.length);
    let next = 0;
    await Promise.all(
      this.slots.map(async (slot) => {
        while (next < ids.length) {
          const k = next++;
          reports[k] = await slot.run(ids[k]);
          onReport(reports[k]);
        }
      }),
    );
    return reports;
  }

  async close(): Promise<void> {
    await Promise.all(this.slots.map((s) => s.close()));
  }
}
