// Convergence plot: E per iteration (log scale) of the last solve of each method, overlaid, one
// series per method the core registers, coloured by its place in that list. The iteration axis is
// logarithmic by default (asinh: linear near 0, so iteration 0 is shown), or linear with the
// checkbox under the plot: gd's thousands of iterations in paper mode flatten a linear axis. Redraws at most a
// few times a second and only while on screen, so live dragging does not pay for it every frame. The
// element's data-state is 'waiting' while a change is not drawn yet, then 'drawn' (for tests). When
// every history shown is E = 0 throughout (solves that started on target), a line under the plot
// says there is nothing a log scale can show.
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';

import type { MethodList } from '../live/methods.js';
import { plotIndices } from './plot_sampling.js';

/** Series colours, by a method's position in the registry's list (lm, gn, bfgs, newton, gd, then any added). */
const PALETTE = [
  '#f2b134',
  '#59c26b',
  '#4e9bf5',
  '#b07aa1',
  '#e15759',
  '#76b7b2',
  '#ff9da7',
  '#9c755f',
  '#edc948',
  '#bab0ac',
];

/** The colour of `method` in the plots and the compare table. */
export function methodColor(methods: MethodList, method: string): string {
  const i = methods.indexOf(method);
  return i < 0 ? '#aab' : PALETTE[i % PALETTE.length];
}

const NOTHING_YET = 'Nothing solved yet: drag a target, and E of each iteration of the solve shows here.';
const NOTHING_TO_PLOT = 'Nothing to plot: E was 0 from the start (already on target), which a log scale cannot show.';

export class ConvergencePlot {
  readonly element: HTMLElement;
  private plot: uPlot;
  /** The iteration axis is logarithmic (the checkbox under the plot). */
  logIterations = true;
  private readonly chart: HTMLElement;
  /** What the plot cannot show: nothing solved yet (the chart hidden), or every history E = 0 throughout. */
  private readonly note: HTMLElement;
  private readonly histories = new Map<string, { values: Float64Array; length: number }>();
  private readonly resizeObserver: ResizeObserver;
  private readonly visibility: IntersectionObserver;
  private visible = false;
  private dirty = false;
  private lastDraw = 0;
  private frame = 0;

  constructor(
    parent: HTMLElement,
    private readonly methods: MethodList,
    private readonly title = 'log E vs iteration (last solve per method)',
    private readonly height = 170,
    /** What the note says before any history: what will show here. */
    private readonly nothingYet = NOTHING_YET,
  ) {
    this.element = document.createElement('div');
    this.element.className = 'plot';
    this.element.dataset.state = 'drawn';
    this.chart = document.createElement('div');
    const toggle = document.createElement('label');
    toggle.className = 'plot-axis';
    const box = document.createElement('input');
    box.type = 'checkbox';
    box.checked = this.logIterations;
    box.addEventListener('change', () => this.setLogIterations(box.checked));
    toggle.append(box, ' log iteration axis');
    this.note = document.createElement('p');
    this.note.className = 'plot-note';
    this.element.append(this.chart, this.note, toggle);
    this.showNote([]);
    parent.append(this.element);
    this.plot = this.build(title, height);
    this.element.dataset.axis = 'log';
    this.resizeObserver = new ResizeObserver(() => {
      const w = this.element.clientWidth;
      if (w > 0 && Math.abs(w - this.plot.width) > 1) this.plot.setSize({ width: w, height });
    });
    this.resizeObserver.observe(this.element);
    this.visibility = new IntersectionObserver((entries) => {
      this.visible = entries[entries.length - 1].isIntersecting;
      this.schedule();
    });
    this.visibility.observe(this.element);
  }

  /** The iteration axis logarithmic (true) or linear; the plot is built anew with the same histories (sampled for that axis). */
  setLogIterations(on: boolean): void {
    if (on === this.logIterations) return;
    this.logIterations = on;
    this.plot.destroy();
    this.plot = this.build(this.title, this.height);
    this.element.dataset.axis = on ? 'log' : 'linear';
  }

  /** A uPlot in the chart slot with the histories shown now. */
  private build(title: string, height: number): uPlot {
    const { methods } = this;
    const width = Math.max(200, this.element.clientWidth || 300);
    const range: uPlot.Scale.Range = (_u, _min, max) => [0, Math.max(1, max)];
    const x: uPlot.Scale = this.logIterations ? { time: false, distr: 4, asinh: 1, range } : { time: false, range };
    const opts: uPlot.Options = {
      title,
      width,
      height,
      scales: { x, y: { distr: 3 } },
      axes: [
        {
          stroke: '#aab',
          grid: { stroke: '#ffffff14' },
          label: this.logIterations ? 'iteration (log scale)' : 'iteration',
          filter: (_u: uPlot, splits: number[]) => splits.map((v) => (v >= 0 ? v : null)), // asinh ticks reach below 0
          // On the log axis only 0 and powers of 10 are labelled (every tick keeps its grid line).
          values: (_u: uPlot, splits: number[]) =>
            splits.map((v) => (!this.logIterations || v === 0 || Number.isInteger(Math.log10(v)) ? String(v) : '')),
        },
        {
          stroke: '#aab',
          grid: { stroke: '#ffffff14' },
          label: 'E',
          size: 60,
          values: (_u: uPlot, splits: (number | null)[]) =>
            splits.map((v) => (v === null || v === undefined ? '' : v === 0 ? '0' : v.toExponential(0))),
        },
      ],
      legend: { show: true, live: false },
      cursor: { show: false },
      series: [
        { label: 'iteration' },
        ...methods.names.map((m) => ({
          label: m,
          stroke: methodColor(methods, m),
          width: 1.5,
          points: { show: true, size: 4 },
          spanGaps: false,
          value: (_u: uPlot, v: number | null) => (v === null ? '–' : v.toExponential(2)),
        })),
      ],
    };
    const plot = new uPlot(opts, this.data(), this.chart);
    plot.root.title = methods.names.map((m) => `${m}: ${methods.label(m)}`).join('\n');
    return plot;
  }

  /**
   * Shows `history` (E before iteration 1, then after each; its first `length` numbers) as
   * `method`'s last solve. The plot reads it when it draws: a caller that reuses the array (the
   * per-frame solve's report) records it again after rewriting it.
   */
  record(method: string, history: Float64Array, length = history.length): void {
    const shown = this.histories.get(method);
    if (shown) {
      shown.values = history;
      shown.length = length;
    } else this.histories.set(method, { values: history, length });
    this.changed();
  }

  clear(): void {
    this.histories.clear();
    this.changed();
  }

  /** Histories shown now (for the compare table and tests). */
  history(method: string): Float64Array | undefined {
    const h = this.histories.get(method);
    return h?.values.slice(0, h.length);
  }

  dispose(): void {
    cancelAnimationFrame(this.frame);
    this.resizeObserver.disconnect();
    this.visibility.disconnect();
    this.plot.destroy();
    this.element.remove();
  }

  private changed(): void {
    if (!this.dirty) this.element.dataset.state = 'waiting';
    this.dirty = true;
    this.schedule();
  }

  /** Draws on a coming animation frame, at most every 250 ms, while the plot is on screen. */
  private schedule(): void {
    if (this.frame || !this.visible || !this.dirty) return;
    const draw = (): void => {
      this.frame = 0;
      if (!this.dirty || !this.visible) return;
      const now = performance.now();
      if (now - this.lastDraw < 250) {
        this.frame = requestAnimationFrame(draw);
        return;
      }
      this.lastDraw = now;
      this.dirty = false;
      const data = this.data();
      this.plot.setData(data);
      this.showNote(data.slice(1));
      this.element.dataset.state = 'drawn';
    };
    this.frame = requestAnimationFrame(draw);
  }

  /**
   * Before any solve the chart (an empty frame) gives way to a line saying what will show there;
   * when every history is E = 0 throughout, a line says why nothing is drawn. `ys`: the data's series.
   */
  private showNote(ys: ReadonlyArray<ArrayLike<number | null | undefined>>): void {
    const empty = this.histories.size === 0;
    this.chart.hidden = empty;
    this.note.textContent = empty ? this.nothingYet : NOTHING_TO_PLOT;
    this.note.hidden = !empty && ys.some((y) => Array.from(y).some((v) => v !== null && v !== undefined));
    this.element.dataset.empty = String(empty);
  }

  private data(): uPlot.AlignedData {
    let n = 1;
    for (const h of this.histories.values()) n = Math.max(n, h.length);
    const ends = [...this.histories.values()].map((h) => h.length - 1);
    const xs = plotIndices(n, this.logIterations, ends);
    const ys = this.methods.names.map((m) => {
      const h = this.histories.get(m);
      return xs.map((i) => (h && i < h.length && h.values[i] > 0 && Number.isFinite(h.values[i]) ? h.values[i] : null));
    });
    return [xs, ...ys];
  }
}
