// "Compare": solves the current targets with every registered method from the same start, the
// current pose or the rest pose (the pose on screen is left as it was), with compare's budget and
// restarts, and shows the rows in the compare table and the histories in the plots. The solves run
// in a Web Worker (compare_worker.ts), so the page keeps drawing and a compare of seconds can be
// watched and cancelled (the box's cancel button, its ×, or C again). The live solve pauses
// meanwhile. Where workers are missing the methods run on the main thread, one per task.
import { errorText } from '../live/error_text.js';
import type { LiveController } from '../view/live_controller.js';
import type { MethodList } from '../live/methods.js';
import type { IkSession } from '../live/session.js';
import type { SolveSettings } from '../live/method_solver.js';
import { compareRequest, type CompareEnd, type CompareReply, type CompareRow } from './compare_messages.js';
import { CompareView } from './compare_view.js';
import type { CompareStart, PageSettings } from './page_settings.js';
import type { ConvergencePlot } from './plots.js';

export type { CompareRow } from './compare_messages.js';

/** Runs every method of `methods` in turn from the same start on the main thread, yielding to the browser between methods. */
export async function compareMethods(
  session: IkSession,
  methods: readonly string[],
  settings: SolveSettings,
  from: CompareStart,
  onRow: (row: CompareRow) => void,
): Promise<CompareRow[]> {
  const rows: CompareRow[] = [];
  const start = from === 'rest pose' ? session.restPose() : session.angles.slice();
  for (const method of methods) {
    await new Promise((r) => setTimeout(r, 0));
    let row: CompareRow;
    try {
      const outcome = session.trySolve(method, settings, start);
      row = { method, outcome, history: session.history(method), error: null };
    } catch (e) {
      row = { method, outcome: null, history: null, error: errorText(e) };
    }
    rows.push(row);
    onRow(row);
  }
  return rows;
}

export class Compare {
  readonly view: CompareView;
  private worker: Worker | null = null;
  private nextId = 0;
  /** The compare running now: its id and how to end it. */
  private running: { id: number; finish: (end: CompareEnd, message?: string) => void } | null = null;

  /** The table goes into `parent`; every history also goes to `plot` (the side column's). */
  constructor(
    parent: HTMLElement,
    private readonly methods: MethodList,
    private readonly plot: ConvergencePlot,
  ) {
    this.view = new CompareView(parent, methods, () => this.cancel());
  }

  /** Whether a compare is running. */
  get busy(): boolean {
    return this.running !== null;
  }

  /**
   * Compares every method on the rig `controller` shows, with the settings `s`; while one runs,
   * cancels it instead. Resolves when the compare ends.
   */
  async run(controller: LiveController, s: PageSettings): Promise<CompareEnd | null> {
    if (this.running) {
      this.cancel();
      return null;
    }
    const live = controller.live;
    if (!live || controller.paused) return null;
    const settings: SolveSettings = {
      gradientTolerance: s.gradientTolerance,
      tipTolerance: s.tipTolerance,
      maxIterations: s.compareMaxIterations,
      timeBudgetMs: s.compareTimeBudgetMs,
      restarts: s.restarts,
      paperMode: s.paperMode,
      strictPriority: s.strictPriority,
    };
    const paper = s.paperMode ? ' in paper mode (the report’s algorithms)' : '';
    this.view.begin(
      `${live.name}, from the ${s.compareFrom}${paper} (budget ${s.compareTimeBudgetMs} ms, restarts ${s.restarts})`,
      this.methods.names.length,
    );
    const onRow = (row: CompareRow): void => {
      this.view.addRow(row, s.paperMode);
      if (row.history) this.plot.record(row.method, row.history);
    };
    controller.paused = true;
    try {
      if (typeof Worker === 'undefined') {
        await compareMethods(live.session, this.methods.names, settings, s.compareFrom, onRow);
        this.view.end('done');
        return 'done';
      }
      const session = live.session;
      const start = s.compareFrom === 'rest pose' ? session.restPose() : session.angles;
      const end = await this.inWorker(session, start, settings, onRow);
      return end;
    } finally {
      controller.paused = false;
    }
  }

  /** Ends the running compare now (the worker is stopped); the rows shown so far stay. */
  cancel(): void {
    if (!this.running) return;
    this.worker?.terminate();
    this.worker = null;
    this.running.finish('cancelled');
  }

  dispose(): void {
    this.cancel();
    this.worker?.terminate();
    this.worker = null;
    this.view.dispose();
  }

  /** Runs the compare in the worker (made on first use), showing progress; resolves how it ended. */
  private inWorker(
    session: IkSession,
    start: Float64Array,
    settings: SolveSettings,
    onRow: (row: CompareRow) => void,
  ): Promise<CompareEnd> {
    const id = ++this.nextId;
    const worker = (this.worker ??= new Worker(new URL('./compare_worker.ts', import.meta.url), { type: 'module' }));
    return new Promise<CompareEnd>((resolve) => {
      const finish = (end: CompareEnd, message?: string): void => {
        worker.removeEventListener('message', listen);
        worker.removeEventListener('error', failed);
        this.running = null;
        this.view.end(end, message);
        resolve(end);
      };
      const listen = (e: MessageEvent<CompareReply>): void => {
        const m = e.data;
        if (m.id !== id) return;
        if (m.type === 'started') this.view.progress(m.method, m.index);
        else if (m.type === 'row') onRow(m.row);
        else if (m.type === 'done') finish('done');
        else finish('failed', m.message);
      };
      const failed = (e: ErrorEvent): void => {
        this.worker?.terminate();
        this.worker = null;
        finish('failed', `the compare worker failed: ${e.message || 'it could not start'}`);
      };
      worker.addEventListener('message', listen);
      worker.addEventListener('error', failed);
      this.running = { id, finish };
      worker.postMessage(compareRequest(id, session, start, this.methods.names, settings));
    });
  }
}
