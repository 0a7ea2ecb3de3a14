// The compare table: one row per method with the report's columns (t, iterations, E, ||grad E||),
// the tip error and the outcome in words (the stop reason's code in its tooltip), and the
// convergence histories overlaid in its own plot. While a compare runs, a progress line says which
// method is solving, how many are done and for how long, beside a cancel button. The element's
// data-state is running, done, cancelled or failed (for tests).
import type { MethodList } from '../live/methods.js';
import { statusWords } from '../live/status_words.js';
import type { CompareEnd, CompareRow } from './compare_messages.js';
import { ConvergencePlot, methodColor } from './plots.js';
import { formatNumber } from './stats.js';

export class CompareView {
  readonly element: HTMLElement;
  private readonly body: HTMLTableSectionElement;
  private readonly caption: HTMLElement;
  private readonly plot: ConvergencePlot;
  private readonly status: HTMLElement;
  private readonly cancelButton: HTMLButtonElement;
  private total = 0;
  private done = 0;
  private current = '';
  private startedAt = 0;
  private ticker = 0;

  /** `cancel` ends the running compare (the cancel button and closing the box while it runs). */
  constructor(
    parent: HTMLElement,
    private readonly methods: MethodList,
    cancel: () => void,
  ) {
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
    close.addEventListener('click', () => {
      cancel();
      this.element.hidden = true;
    });
    head.append(this.caption, close);
    const progress = document.createElement('div');
    progress.className = 'compare-progress';
    this.status = document.createElement('span');
    this.status.className = 'compare-status';
    this.status.setAttribute('role', 'status');
    this.cancelButton = document.createElement('button');
    this.cancelButton.type = 'button';
    this.cancelButton.className = 'compare-cancel';
    this.cancelButton.textContent = 'cancel';
    this.cancelButton.addEventListener('click', () => cancel());
    progress.append(this.status, this.cancelButton);
    const table = document.createElement('table');
    table.className = 'compare-table';
    const thead = table.createTHead().insertRow();
    for (const h of ['method', 't (s)', 'iterations', 'E', '‖∇E‖', 'tip error', 'outcome']) {
      const th = document.createElement('th');
      th.textContent = h;
      thead.append(th);
    }
    this.body = table.createTBody();
    this.element.append(head, progress, table);
    parent.append(this.element);
    this.plot = new ConvergencePlot(
      this.element,
      methods,
      'log E vs iteration, every method from the same pose',
      160,
      'Each method’s E per iteration shows here as it finishes.',
    );
  }

  /** Clears the table for a new comparison of `total` methods; `what` names the rig and settings. */
  begin(what: string, total: number): void {
    this.element.hidden = false;
    this.caption.textContent = `Compare: ${what}`;
    this.body.replaceChildren();
    this.plot.clear();
    this.element.dataset.state = 'running';
    this.total = total;
    this.done = 0;
    this.current = '';
    this.startedAt = performance.now();
    this.cancelButton.hidden = false;
    clearInterval(this.ticker);
    this.ticker = window.setInterval(() => this.showProgress(), 100);
    this.showProgress();
    this.element.scrollIntoView({ block: 'nearest' }); // in the side column (a phone's bottom sheet), which may be scrolled
  }

  /** Method `method` (the `index`-th, from 0) started solving. */
  progress(method: string, index: number): void {
    this.current = method;
    this.done = index;
    this.showProgress();
  }

  /** Adds one method's row; `paperMode` words a stationary point off target as paper mode has it. */
  addRow(row: CompareRow, paperMode = false): void {
    this.done = this.body.rows.length + 1;
    const tr = this.body.insertRow();
    tr.dataset.method = row.method;
    const name = tr.insertCell();
    const swatch = document.createElement('span');
    swatch.className = 'swatch';
    swatch.style.background = methodColor(this.methods, row.method);
    name.append(swatch, row.method);
    name.title = `${this.methods.label(row.method)}: ${this.methods.describe(row.method)}`;
    const o = row.outcome;
    const cells = o
      ? [
          formatNumber(o.elapsedSeconds),
          String(o.iterations),
          formatNumber(o.E),
          formatNumber(o.gradNorm),
          formatNumber(o.tipDistance),
        ]
      : ['–', '–', '–', '–', '–'];
    for (const c of cells) tr.insertCell().textContent = c;
    const outcome = tr.insertCell();
    if (o) {
      const words = statusWords(o, paperMode);
      outcome.textContent = words.text;
      outcome.title = words.title;
      outcome.dataset.reason = o.stopReason;
    } else {
      outcome.textContent = row.error ?? 'failed';
    }
    if (row.history) this.plot.record(row.method, row.history);
  }

  /** The compare ended: done, cancelled by the user, or failed (`message` says why). */
  end(how: CompareEnd = 'done', message = ''): void {
    clearInterval(this.ticker);
    this.element.dataset.state = how;
    this.cancelButton.hidden = true;
    const seconds = ((performance.now() - this.startedAt) / 1000).toFixed(1);
    const rows = `${this.body.rows.length} of ${this.total} methods`;
    this.status.textContent =
      how === 'done'
        ? `done in ${seconds} s`
        : how === 'cancelled'
          ? `cancelled after ${seconds} s (${rows} done)`
          : `failed: ${message}`;
  }

  /** Which method is solving, how many are done, and the time so far. */
  private showProgress(): void {
    const seconds = ((performance.now() - this.startedAt) / 1000).toFixed(1);
    const now = this.current ? `solving with ${this.current}` : 'starting';
    this.status.textContent = `${now}: ${this.done} of ${this.total} methods done, ${seconds} s`;
  }

  hide(): void {
    this.element.hidden = true;
  }

  dispose(): void {
    clearInterval(this.ticker);
    this.plot.dispose();
    this.element.remove();
  }
}
