// "Compare": solves the current targets with every registered method from the same start, the
// current pose or the rest pose (the pose on screen is left as it was), with compare's budget and
// restarts, and shows the rows in the compare table and the histories in the plots. The live
// solve pauses meanwhile.
import { errorText } from '../live/error_text.js';
import type { LiveController } from '../live/live_controller.js';
import type { MethodList } from '../live/methods.js';
import type { IkSession } from '../live/session.js';
import type { SolveOutcome, SolveSettings } from '../live/solver.js';
import { CompareView } from './compare_view.js';
import type { CompareStart, PageSettings } from './page_settings.js';
import type { ConvergencePlot } from './plots.js';

export interface CompareRow {
  method: string;
  outcome: SolveOutcome | null;
  /** E before the first iteration and after each one. */
  history: Float64Array | null;
  error: string | null;
}

/** Runs every method of `methods` in turn from the same start, yielding to the browser between methods. */
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

  /** The table goes into `parent`; every history also goes to `plot` (the side column's). */
  constructor(parent: HTMLElement, private readonly methods: MethodList, private readonly plot: ConvergencePlot) {
    this.view = new CompareView(parent, methods);
  }

  /** Compares every method on the rig `controller` shows, with the settings `s`; nothing while a compare runs. */
  async run(controller: LiveController, s: PageSettings): Promise<void> {
    const live = controller.live;
    if (!live || controller.paused) return;
    controller.paused = true;
    const settings: SolveSettings = {
      gradientTolerance: s.gradientTolerance,
      tipTolerance: s.tipTolerance,
      maxIterations: s.compareMaxIterations,
      timeBudgetMs: s.compareTimeBudgetMs,
      restarts: s.restarts,
      paperMode: s.paperMode,
    };
    this.view.begin(`${live.name}, from the ${s.compareFrom} (budget ${s.compareTimeBudgetMs} ms, restarts ${s.restarts})`);
    try {
      await compareMethods(live.session, this.methods.names, settings, s.compareFrom, (row) => {
        this.view.addRow(row, s.paperMode);
        if (row.history) this.plot.record(row.method, row.history);
      });
    } finally {
      this.view.end();
      controller.paused = false;
    }
  }

  dispose(): void {
    this.view.dispose();
  }
}
