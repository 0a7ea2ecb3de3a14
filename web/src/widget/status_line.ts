// The widget's status line: what the last per-frame solve did (method, iterations, time) and, in
// words, what it reached (status_words.ts). The words' sentence is the line's tooltip; their kind
// and whether every effector is on target are data attributes, for styling and tests. The words
// and attributes change at once; the numbers are written a few times a second (Throttle).
import type { SolveOutcome } from '../live/solver.js';
import { statusWords, type StatusWords } from '../live/status_words.js';
import { Throttle } from '../live/throttle.js';

/** A distance (rig units) to 2 significant digits: "0.0012", "0.25", "3.4e-7". */
function twoDigits(d: number): string {
  return Number.isFinite(d) ? String(Number(d.toPrecision(2))) : String(d);
}

export class StatusLine {
  /** The words shown, or null while the line shows a note. */
  private words: StatusWords | null = null;
  /** The last solve's numbers (written by show(), read when the text is written). */
  private readonly latest = { method: '', iterations: 0, tipDistance: 0, ms: 0 };
  private readonly text = new Throttle(() => this.writeText());

  constructor(readonly element: HTMLElement) {}

  /**
   * Shows one solve: "lm · 4 it · tip error 0.0012 · 0.15 ms · on target". `outcome.tipDistance`
   * is the largest distance of an end effector from its target (rig units); `ms` the main-thread
   * time of the solve. Sets title (what the words mean), data-status (their kind) and data-reached.
   */
  show(method: string, outcome: SolveOutcome, ms: number): void {
    const l = this.latest;
    l.method = method;
    l.iterations = outcome.iterations;
    l.tipDistance = outcome.tipDistance;
    l.ms = ms;
    const words = statusWords(outcome.reached, outcome.stopReason);
    if (words === this.words) {
      this.text.request();
      return;
    }
    this.words = words;
    const el = this.element;
    el.title = `${words.title}. Tip error: the largest distance of an end effector from its target, rig units.`;
    el.dataset.status = words.kind;
    el.dataset.reached = outcome.reached ? 'true' : 'false';
    this.text.now();
  }

  /** Shows `text` instead of a solve ('' empties the line); `kind`, when given, becomes data-status. */
  note(text: string, kind?: StatusWords['kind']): void {
    this.text.cancel();
    this.words = null;
    const el = this.element;
    el.textContent = text;
    el.removeAttribute('title');
    delete el.dataset.reached;
    if (kind) el.dataset.status = kind;
    else delete el.dataset.status;
  }

  private writeText(): void {
    const l = this.latest;
    if (!this.words) return;
    this.element.textContent = `${l.method} · ${l.iterations} it · tip error ${twoDigits(l.tipDistance)} · ${l.ms.toFixed(2)} ms · ${this.words.text}`;
  }
}
