// The compare table: one row per method with the report's columns (t, iterations, E, ||grad E||),
// the tip error and the outcome in words (the stop reason's code in its tooltip), and the
// convergence histories overlaid in its own plot.
import type { MethodList } from '../live/methods.js';
import { statusWords } from '../live/status_words.js';
import type { CompareRow } from './compare.js';
import { ConvergencePlot, methodColor } from './plots.js';
import { formatNumber } from './stats.js';

export class CompareView {
  readonly element: HTMLElement;
  private readonly body: HTMLTableSectionElement;
  private readonly caption: HTMLElement;
  private readonly plot: ConvergencePlot;

  constructor(parent: HTMLElement, private readonly methods: MethodList) {
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
    this.plot = new ConvergencePlot(this.element, methods, 'log E vs iteration, every method from the same pose', 160);
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
    swatch.style.background = methodColor(this.methods, row.method);
    name.append(swatch, row.method);
    name.title = `${this.methods.label(row.method)}: ${this.methods.describe(row.method)}`;
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
    if (row.history) this.plot.record(row.method, row.history);
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
