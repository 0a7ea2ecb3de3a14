// Live solver statistics: what the last solve reached in words (statusWords), the largest tip
// error as a distance and in screen pixels, iterations, E, ||grad||, and the main-thread time of
// one solve with its running median. Values are written as text; each field also carries its raw
// number in data-value so tests and tools can read it without parsing the display (the status
// carries the solver's stop reason code in data-reason and its tooltip).
import { statusWords } from './status_words.js';

/** Running median over the last `capacity` samples. */
export class RunningMedian {
  private readonly ring: Float64Array;
  private readonly sorted: Float64Array;
  private count = 0;
  private next = 0;

  constructor(readonly capacity = 121) {
    this.ring = new Float64Array(capacity);
    this.sorted = new Float64Array(capacity);
  }

  /** Samples pushed since the last clear (also those that left the window). */
  total = 0;

  push(x: number): void {
    this.total++;
    this.ring[this.next] = x;
    this.next = (this.next + 1) % this.capacity;
    this.count = Math.min(this.count + 1, this.capacity);
  }

  get size(): number {
    return this.count;
  }

  median(): number {
    return this.quantile(0.5);
  }

  /** Quantile q in [0, 1] of the window, interpolating between closest ranks. */
  quantile(q: number): number {
    if (this.count === 0) return NaN;
    const s = this.sorted.subarray(0, this.count);
    s.set(this.ring.subarray(0, this.count));
    s.sort();
    const at = q * (this.count - 1);
    const lo = Math.floor(at);
    return lo + 1 < this.count ? s[lo] + (s[lo + 1] - s[lo]) * (at - lo) : s[lo];
  }

  /** Largest sample in the window. */
  max(): number {
    let m = -Infinity;
    for (let i = 0; i < this.count; i++) m = Math.max(m, this.ring[i]);
    return this.count ? m : NaN;
  }

  clear(): void {
    this.total = 0;
    this.count = 0;
    this.next = 0;
  }
}

export interface StatsValues {
  method: string;
  iterations: number;
  E: number;
  gradNorm: number;
  /** Every end effector within the tip tolerance of its target. */
  reached: boolean;
  /** Largest distance of an end effector from its target, rig units. */
  tipDistance: number;
  /** Screen pixels per rig unit near the targets (for the tip error in pixels); NaN: unknown. */
  pixelsPerUnit: number;
  stopReason: string;
  /** The report's algorithms (no escape from stationary points): changes the words of converged_grad. */
  paperMode: boolean;
  ms: number;
  /** Largest distance from a pinned (not dragged) effector to its target: the report's "wobble". */
  pinnedDrift: number;
}

const FIELDS: { key: keyof StatsValues | 'median' | 'status'; label: string; title: string }[] = [
  { key: 'method', label: 'method', title: 'the method solving every frame' },
  { key: 'status', label: 'status', title: 'what the last solve reached' },
  { key: 'tipDistance', label: 'tip error', title: 'largest distance of an end effector from its target (rig units, and screen pixels)' },
  { key: 'iterations', label: 'iterations', title: 'iterations of the last solve' },
  { key: 'E', label: 'E', title: 'E = ½ Σ |tip − target|² after the last solve' },
  { key: 'gradNorm', label: '‖∇E‖', title: 'gradient norm after the last solve' },
  { key: 'ms', label: 'ms / solve', title: 'main-thread milliseconds of the last solve (JS + WebAssembly)' },
  { key: 'median', label: 'median ms', title: 'running median of ms / solve over the last solves' },
  { key: 'pinnedDrift', label: 'pinned drift', title: 'largest distance of a pinned effector from its target (the report’s “wobble”)' },
];

/** A number in 4 significant digits, exponential outside [1e-3, 1e4). */
export function formatNumber(x: number): string {
  if (!Number.isFinite(x)) return String(x);
  if (x === 0) return '0';
  const a = Math.abs(x);
  return a >= 1e-3 && a < 1e4 ? x.toPrecision(4) : x.toExponential(2);
}

export class StatsPanel {
  readonly element: HTMLElement;
  readonly median = new RunningMedian(121);
  private readonly cells = new Map<string, HTMLElement>();

  constructor(parent: HTMLElement) {
    this.element = document.createElement('dl');
    this.element.className = 'stats';
    this.element.id = 'stats';
    for (const f of FIELDS) {
      const dt = document.createElement('dt');
      dt.textContent = f.label;
      dt.title = f.title;
      const dd = document.createElement('dd');
      dd.dataset.stat = f.key;
      dd.textContent = '–';
      this.cells.set(f.key, dd);
      this.element.append(dt, dd);
    }
    parent.append(this.element);
  }

  /** Shows one solve; `timed` adds its time to the running median. */
  show(v: StatsValues, timed = true): void {
    if (timed) this.median.push(v.ms);
    this.set('method', v.method, NaN);
    this.set('iterations', String(v.iterations), v.iterations);
    this.set('E', formatNumber(v.E), v.E);
    this.set('gradNorm', formatNumber(v.gradNorm), v.gradNorm);
    const px = v.tipDistance * v.pixelsPerUnit;
    this.set('tipDistance', `${formatNumber(v.tipDistance)}${Number.isFinite(px) ? ` (${px.toFixed(1)} px)` : ''}`, v.tipDistance);
    this.showStatus(v.reached, v.stopReason, v.paperMode);
    this.set('ms', v.ms.toFixed(3), v.ms);
    const m = this.median.median();
    this.set('median', Number.isNaN(m) ? '–' : `${m.toFixed(3)} (n=${this.median.size})`, m);
    this.set('pinnedDrift', formatNumber(v.pinnedDrift), v.pinnedDrift);
  }

  /** Shows E for a pose that was not solved (after reset, load, or an effector change). */
  showIdle(method: string, E: number): void {
    this.set('method', method, NaN);
    this.set('E', formatNumber(E), E);
  }

  private showStatus(reached: boolean, stopReason: string, paperMode: boolean): void {
    const cell = this.cells.get('status');
    if (!cell) return;
    const words = statusWords(reached, stopReason, paperMode);
    this.set('status', words.text, NaN);
    cell.title = words.title;
    cell.dataset.reason = stopReason;
    cell.dataset.kind = words.kind;
    cell.dataset.reached = String(reached);
  }

  reset(): void {
    this.median.clear();
    for (const [key, cell] of this.cells) this.set(key, '–', NaN, cell);
    const status = this.cells.get('status');
    if (status) {
      status.title = '';
      for (const k of ['reason', 'kind', 'reached']) delete status.dataset[k];
    }
  }

  private set(key: string, text: string, value: number, cell = this.cells.get(key)): void {
    if (!cell) return;
    if (cell.textContent !== text) cell.textContent = text;
    cell.dataset.value = Number.isNaN(value) ? '' : String(value);
  }
}
