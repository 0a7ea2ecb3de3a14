// Convergence plot: E per iteration (log scale) of the last solve of each method, overlaid.
// Redraws at most a few times a second, so live dragging does not pay for it every frame.
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';

import { METHOD_LABELS, METHODS, type Method } from './solver_port.js';

export const METHOD_COLORS: Record<Method, string> = {
  gd: '#e15759',
  bfgs: '#4e9bf5',
  gn: '#59c26b',
  newton: '#b07aa1',
  lm: '#f2b134',
};

export class ConvergencePlot {
  readonly element: HTMLElement;
  private readonly plot: uPlot;
  private readonly histories = new Map<Method, Float64Array>();
  private readonly resizeObserver: ResizeObserver;
  private dirty = false;
  private lastDraw = 0;
  private frame = 0;

  constructor(parent: HTMLElement, title = 'log E vs iteration (last solve per method)', height = 170) {
    this.element = document.createElement('div');
    this.element.className = 'plot';
    parent.append(this.element);
    const width = Math.max(200, this.element.clientWidth || 300);
    const opts: uPlot.Options = {
      title,
      width,
      height,
      scales: { x: { time: false }, y: { distr: 3 } },
      axes: [
        { stroke: '#aab', grid: { stroke: '#ffffff14' }, label: 'iteration' },
        {
          stroke: '#aab',
          grid: { stroke: '#ffffff14' },
          label: 'E',
          size: 60,
          values: (_u: uPlot, splits: (number | null)[]) => splits.map((v) => (v === null || v === undefined ? '' : v === 0 ? '0' : v.toExponential(0))),
        },
      ],
      legend: { show: true, live: false },
      cursor: { show: false },
      series: [
        { label: 'iteration' },
        ...METHODS.map((m) => ({
          label: m,
          stroke: METHOD_COLORS[m],
          width: 1.5,
          points: { show: true, size: 4 },
          spanGaps: false,
          value: (_u: uPlot, v: number | null) => (v === null ? '–' : v.toExponential(2)),
        })),
      ],
    };
    this.plot = new uPlot(opts, this.data(), this.element);
    this.plot.root.title = METHODS.map((m) => `${m}: ${METHOD_LABELS[m]}`).join('\n');
    this.resizeObserver = new ResizeObserver(() => {
      const w = this.element.clientWidth;
      if (w > 0 && Math.abs(w - this.plot.width) > 1) this.plot.setSize({ width: w, height });
    });
    this.resizeObserver.observe(this.element);
  }

  /** Records the E history of the last solve of `method` (E before iteration 1, then after each). */
  record(method: Method, history: Float64Array): void {
    this.histories.set(method, history);
    this.dirty = true;
    this.schedule();
  }

  clear(): void {
    this.histories.clear();
    this.dirty = true;
    this.schedule();
  }

  /** Histories shown now (for the compare table and tests). */
  history(method: Method): Float64Array | undefined {
    return this.histories.get(method);
  }

  dispose(): void {
    cancelAnimationFrame(this.frame);
    this.resizeObserver.disconnect();
    this.plot.destroy();
    this.element.remove();
  }

  private schedule(): void {
    if (this.frame) return;
    const draw = (): void => {
      this.frame = 0;
      if (!this.dirty) return;
      const now = performance.now();
      if (now - this.lastDraw < 250) {
        this.frame = requestAnimationFrame(draw);
        return;
      }
      this.lastDraw = now;
      this.dirty = false;
      this.plot.setData(this.data());
    };
    this.frame = requestAnimationFrame(draw);
  }

  private data(): uPlot.AlignedData {
    let n = 1;
    for (const h of this.histories.values()) n = Math.max(n, h.length);
    const xs = Array.from({ length: n }, (_, i) => i);
    const ys = METHODS.map((m) => {
      const h = this.histories.get(m);
      return xs.map((i) => (h && i < h.length && h[i] > 0 && Number.isFinite(h[i]) ? h[i] : null));
    });
    return [xs, ...ys];
  }
}
