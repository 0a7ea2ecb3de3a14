// "Compare": solves the current targets with every method from the same start, the current pose
// or the rest pose (the pose on screen is left as it was) and shows the report's columns (t,
// iterations, E, ||grad E||) with the tip error and the outcome in words (the stop reason's code in
// its tooltip), and the convergence histories overlaid.
import { ConvergencePlot, METHOD_COLORS } from './plots.js';
import type { IkSession } from './session.js';
import { formatNumber } from './stats.js';
import { statusWords } from './status_words.js';
import { METHOD_LABELS, METHODS, type Method, type SolveOutcome, type SolveSettings } from './solver_port.js';

export interface CompareRow {
  method: Method;
  outcome: SolveOutcome | null;
  error: string | null;
}

export type CompareStart = 'current pose' | 'rest pose';

/** Runs every method in turn from the same start, yielding to the browser between methods. */
export async function compareMethods(
  session: IkSession,
  settings: SolveSettings,
  from: CompareStart,
  onRow: (row: CompareRow) => void,
): Promise<CompareRow[]> {
  const rows: CompareRow[] = [];
  const start = from === 'rest pose' ? session.restPose() : session.angles.slice();
  for (const method of METHODS) {
    await new Promise((r) => setTimeout(r, 0));
    let row: CompareRow;
    try {
      row = { method, outcome: session.trySolve(method, settings, start), error: null };
    } catch (e) {
      row = { method, outcome: null, error: e instanceof Error ? e.message : String(e) };
    }
    rows.push(row);
    onRow(row);
  }
  return rows;
}

export class CompareView {
  readonly element: HTMLElement;
  private readonly body: HTMLTableSectionElement;
  private readonly caption: HTMLElement;
  private readonly plot: ConvergencePlot;

  constructor(parent: HTMLElement) {
    this.element = document.createElement('section');
    this.element.className = 'compare';
    this.element.id = 'compare';
    this.element.hidden = true;
    const head = document.createElement('header');
    this.caption = document.createElement('h2');
    this.caption.textContent = 'Compare';
    const close = document.createElement('button');
    close.type = 'button';
    close.textContent = '×';
    close.title = 'close';
    close.addEventListener('click', () => (this.element.hidden = true));
    head.append(this.caption, close);
    const table = document.createElement('table');
    table.className = 'compare-table';
    const thead = table.createTHead().insertRow();
    for (const h of ['method', 't (s)', 'iterations', 'E', '‖∇E‖', 'tip error', 'outcome']) {
      const th = document.createElement('th');
      th.textContent = h;
      thead.append(th);
    }
    this.body = table.createTBody();
    this.element.append(head, table);
    parent.append(this.element);
    this.plot = new ConvergencePlot(this.element, 'log E vs iteration, every method from the same pose', 160);
  }

  /** Clears the table for a new comparison; `what` names the rig and settings. */
  begin(what: string): void {
    this.element.hidden = false;
    this.caption.textContent = `Compare: ${what}`;
    this.body.replaceChildren();
    this.plot.clear();
    this.element.dataset.state = 'running';
  }

  /** Adds one method's row; `paperMode` words a stationary point off target as paper mode has it. */
  addRow(row: CompareRow, paperMode = false): void {
    const tr = this.body.insertRow();
    tr.dataset.method = row.method;
    const name = tr.insertCell();
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = METHOD_COLORS[row.method];
    name.append(swatch, row.method);
    name.title = METHOD_LABELS[row.method];
    const o = row.outcome;
    const cells = o
      ? [formatNumber(o.elapsedSeconds), String(o.iterations), formatNumber(o.E), formatNumber(o.gradNorm), formatNumber(o.tipDistance)]
      : ['–', '–', '–', '–', '–'];
    for (const c of cells) tr.insertCell().textContent = c;
    const outcome = tr.insertCell();
    if (o) {
      const words = statusWords(o.reached, o.stopReason, paperMode);
      outcome.textContent = words.text;
      outcome.title = words.title;
      outcome.dataset.reason = o.stopReason;
    } else {
      outcome.textContent = row.error ?? 'failed';
    }
    if (o) this.plot.record(row.method, o.history);
  }

  end(): void {
    this.element.dataset.state = 'done';
  }

  hide(): void {
    this.element.hidden = true;
  }

  dispose(): void {
    this.plot.dispose();
    this.element.remove();
  }
}
