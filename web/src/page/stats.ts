// Live solver statistics: what the last solve reached in words (statusWords), the largest tip
// error as a distance and in screen pixels, iterations, E, ||grad||, and the main-thread time of
// one solve with its running median. Values are written as text; each field also carries its raw
// number in data-value so tests and tools can read it without parsing the display (the status
// carries the solver's stop reason code in data-reason and its tooltip). While dragging, the
// numbers are written a few times a second (Throttle), the status as soon as it changes.
import { statusWords, type StatusWords } from '../live/status_words.js';
import { Throttle } from '../live/throttle.js';
import { RunningMedian } from './running_median.js';

export interface StatsValues {
  method: string;
  iterations: number;
  E: number;
  gradNorm: number;
  /** Every end effector within the tip tolerance of its target. */
  reached: boolean;
  /** Largest distance of an end effector from its target, rig units. */
  tipDistance: number;
  /** Largest angle between an effector's bone frame and its orientation goal, DEGREES; NaN: no orientation goal. */
  orientationErrorDeg: number;
  /** Screen pixels per rig unit near the targets (for the tip error in pixels); NaN: unknown. */
  pixelsPerUnit: number;
  stopReason: string;
  /** A position goal could not be met (the core's outOfReach): the words say out of reach. */
  outOfReach: boolean;
  /** Only an orientation goal could not be met (the core's orientationOutOfReach). */
  orientationOutOfReach: boolean;
  /** The report's algorithms (no escape from stationary points): changes the words of converged_grad. */
  paperMode: boolean;
  ms: number;
  /** Largest distance from its target of an effector other than the selected one (pinned): the report's "wobble". */
  pinnedDrift: number;
}

/** A stats record before any solve (each holder rewrites its own in place). */
export function emptyStatsValues(): StatsValues {
  return {
    method: '',
    iterations: 0,
    E: 0,
    gradNorm: 0,
    reached: false,
    tipDistance: 0,
    orientationErrorDeg: NaN,
    pixelsPerUnit: NaN,
    stopReason: '',
    outOfReach: false,
    orientationOutOfReach: false,
    paperMode: false,
    ms: 0,
    pinnedDrift: 0,
  };
}

/** Fields shown only while their value is a number (not NaN). */
const OPTIONAL = new Set<string>(['orientationErrorDeg']);

const FIELDS: { key: keyof StatsValues | 'median' | 'status'; label: string; title: string }[] = [
  { key: 'method', label: 'method', title: 'the method solving every frame' },
  { key: 'status', label: 'status', title: 'what the last solve reached' },
  {
    key: 'tipDistance',
    label: 'tip error',
    title: 'largest distance of an end effector from its target (rig units, and screen pixels)',
  },
  {
    key: 'orientationErrorDeg',
    label: 'orientation error',
    title:
      'largest angle between an effector’s bone frame and its orientation goal, degrees (shown while a target has an orientation goal)',
  },
  { key: 'iterations', label: 'iterations', title: 'iterations of the last solve' },
  { key: 'E', label: 'E', title: 'E = ½ Σ |tip − target|² after the last solve' },
  { key: 'gradNorm', label: '‖∇E‖', title: 'gradient norm after the last solve' },
  { key: 'ms', label: 'ms / solve', title: 'main-thread milliseconds of the last solve (JS + WebAssembly)' },
  { key: 'median', label: 'median ms', title: 'running median of ms / solve over the last solves' },
  {
    key: 'pinnedDrift',
    label: 'pinned drift',
    title:
      'largest distance from its target of an end effector other than the selected one (the one you drag): the report’s “wobble”',
  },
];

/** What the method cell says: the method, and that it runs as the report's algorithm in paper mode. */
const methodText = (v: Pick<StatsValues, 'method' | 'paperMode'>): string =>
  v.paperMode && v.method ? `${v.method} (paper mode)` : v.method;

/** A number to 3 significant digits: plain in [1e-3, 1e4) (trailing zeros dropped), exponential outside. */
export function formatNumber(x: number): string {
  if (!Number.isFinite(x)) return String(x);
  if (x === 0) return '0';
  const a = Math.abs(x);
  return a >= 1e-3 && a < 1e4 ? String(Number(x.toPrecision(3))) : x.toExponential(2);
}

/**
 * Why the page's times are coarse, or null when they are fine: without cross-origin isolation
 * browsers round performance.now() to 0.1 ms, so a solve of 20 µs reads 0 or 0.1 ms.
 */
export function coarseTimerNote(isolated = globalThis.crossOriginIsolated === true): string | null {
  return isolated
    ? null
    : 'times are rounded to 0.1 ms: this server does not make the page cross-origin isolated (the Cross-Origin-Opener-Policy: same-origin and Cross-Origin-Embedder-Policy: require-corp headers; see the README, Deploying), so browsers coarsen performance.now(). Medians over many solves are still meaningful.';
}

export class StatsPanel {
  readonly element: HTMLElement;
  readonly median = new RunningMedian(121);
  private readonly cells = new Map<string, HTMLElement>();
  /** The last solve's values, written out by writeNumbers(). */
  private readonly latest: StatsValues = emptyStatsValues();
  /** The words the status cell shows, or null. */
  private words: StatusWords | null = null;
  private readonly numbers = new Throttle(() => this.writeNumbers());

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
      dt.hidden = dd.hidden = OPTIONAL.has(f.key);
      this.cells.set(f.key, dd);
      this.element.append(dt, dd);
    }
    const note = coarseTimerNote();
    if (note) {
      const dt = document.createElement('dt');
      dt.textContent = 'timer';
      const dd = document.createElement('dd');
      dd.dataset.stat = 'timer';
      dd.className = 'timer-note';
      dd.textContent = 'coarse, 0.1 ms steps (page not cross-origin isolated)';
      dt.title = dd.title = note;
      this.element.append(dt, dd);
    }
    parent.append(this.element);
  }

  /**
   * Shows one per-frame solve and adds its time to the running median. The status changes at once
   * (with the numbers when it changes); the numbers alone are written a few times a second.
   */
  show(v: StatsValues): void {
    this.median.push(v.ms);
    Object.assign(this.latest, v);
    if (this.showStatus(v)) this.numbers.now();
    else this.numbers.request();
  }

  /** Shows one step of step mode at once (its time is not a per-frame solve's: not in the median). */
  showStep(v: StatsValues): void {
    Object.assign(this.latest, v);
    this.showStatus(v);
    this.numbers.now();
  }

  /** Shows a pose that no solve has reached for yet (step mode, a target moved): at once when its status changes, else a few times a second. */
  showPending(v: StatsValues): void {
    Object.assign(this.latest, v);
    if (this.showStatus(v)) this.numbers.now();
    else this.numbers.request();
  }

  /** Shows E for a pose that was not solved (after reset, load, or an effector change). */
  showIdle(method: string, E: number, paperMode = false): void {
    this.numbers.cancel();
    this.set('method', methodText({ method, paperMode }), NaN);
    this.set('E', formatNumber(E), E);
    this.setOptional('orientationErrorDeg', '', NaN);
  }

  reset(): void {
    this.numbers.cancel();
    this.median.clear();
    this.words = null;
    for (const [key, cell] of this.cells) this.set(key, '–', NaN, cell);
    for (const key of OPTIONAL) this.setOptional(key, '', NaN);
    const status = this.cells.get('status');
    if (status) {
      status.title = '';
      for (const k of ['reason', 'kind', 'reached']) delete status.dataset[k];
    }
  }

  /** Shows the status of `v` if it differs from the one shown; true if it did. */
  private showStatus(v: StatsValues): boolean {
    const words = statusWords(v, v.paperMode);
    const cell = this.cells.get('status');
    if (!cell || words === this.words) return false;
    this.words = words;
    this.set('status', words.text, NaN);
    cell.title = words.title;
    cell.dataset.reason = v.stopReason;
    cell.dataset.kind = words.kind;
    cell.dataset.reached = v.reached ? 'true' : 'false';
    return true;
  }

  private writeNumbers(): void {
    const v = this.latest;
    this.set('method', methodText(v), NaN);
    this.set('iterations', String(v.iterations), v.iterations);
    this.set('E', formatNumber(v.E), v.E);
    this.set('gradNorm', Number.isNaN(v.gradNorm) ? '–' : formatNumber(v.gradNorm), v.gradNorm); // –: not solved
    const px = v.tipDistance * v.pixelsPerUnit;
    this.set(
      'tipDistance',
      `${formatNumber(v.tipDistance)}${Number.isFinite(px) ? ` (${px.toFixed(1)} px)` : ''}`,
      v.tipDistance,
    );
    this.setOptional('orientationErrorDeg', `${v.orientationErrorDeg.toPrecision(3)}°`, v.orientationErrorDeg);
    this.set('ms', Number.isNaN(v.ms) ? '–' : formatNumber(v.ms), v.ms);
    const m = this.median.median();
    this.set('median', Number.isNaN(m) ? '–' : `${formatNumber(m)} (n=${this.median.size})`, m);
    this.set('pinnedDrift', formatNumber(v.pinnedDrift), v.pinnedDrift);
  }

  /** Sets an OPTIONAL field, shown only while `value` is not NaN. */
  private setOptional(key: string, text: string, value: number): void {
    const cell = this.cells.get(key);
    if (!cell) return;
    const hidden = Number.isNaN(value);
    if (cell.hidden !== hidden) {
      cell.hidden = hidden;
      if (cell.previousElementSibling instanceof HTMLElement) cell.previousElementSibling.hidden = hidden;
    }
    this.set(key, hidden ? '–' : text, value, cell);
  }

  private set(key: string, text: string, value: number, cell = this.cells.get(key)): void {
    if (!cell) return;
    if (cell.textContent !== text) cell.textContent = text;
    cell.dataset.value = Number.isNaN(value) ? '' : String(value);
  }
}
