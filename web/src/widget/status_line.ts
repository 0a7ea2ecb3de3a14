// The widget's status line: what the last per-frame solve did (method, iterations, time) and, in
// words, what it reached (status_words.ts). The words' sentence is the line's tooltip; their kind
// and whether every effector is on target are data attributes, for styling and tests. The words
// and attributes change at once; the numbers are written a few times a second (Throttle).
import type { SolveOutcome } from '../live/method_solver.js';
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
  private readonly latest = { method: '', iterations: 0, tipDistance: 0, orientationDeg: NaN, ms: 0 };
  private readonly text = new Throttle(() => this.writeText());
  /** A lasting problem shown before the rest of the line ('' for none). */
  private problemText = '';
  /** What note() shows ('' when the line shows a solve or nothing). */
  private noteText = '';

  constructor(readonly element: HTMLElement) {}

  /**
   * Shows one solve: "lm · 4 it · tip error 0.0012 · 0.15 ms · on target". `outcome.tipDistance`
   * is the largest distance of an end effector from its target (rig units); `ms` the main-thread
   * time of the solve; `orientationDeg` the largest orientation error in DEGREES, shown after the
   * tip error ("orientation error 0.123°", 3 significant digits) unless NaN (no orientation goal).
   * Sets title (what the words mean), data-status (their kind) and data-reached.
   */
  show(method: string, outcome: SolveOutcome, ms: number, orientationDeg = NaN): void {
    const l = this.latest;
    l.method = method;
    l.iterations = outcome.iterations;
    l.tipDistance = outcome.tipDistance;
    l.orientationDeg = orientationDeg;
    l.ms = ms;
    const words = statusWords(outcome);
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

  /**
   * A lasting problem (e.g. unknown names in the widget's attributes), shown in front of whatever
   * the line shows ("unknown goal bone "x" — lm · 4 it · ...") and as data-problem, until
   * problem('') clears it.
   */
  problem(text: string): void {
    this.problemText = text;
    if (text) this.element.dataset.problem = text;
    else delete this.element.dataset.problem;
    if (this.words) this.writeText();
    else this.element.textContent = this.withProblem(this.noteText);
  }

  /** Shows `text` instead of a solve ('' empties the line, but for a problem); `kind`, when given, becomes data-status. */
  note(text: string, kind?: StatusWords['kind']): void {
    this.text.cancel();
    this.words = null;
    this.noteText = text;
    const el = this.element;
    el.textContent = this.withProblem(text);
    el.removeAttribute('title');
    delete el.dataset.reached;
    if (kind) el.dataset.status = kind;
    else delete el.dataset.status;
  }

  private writeText(): void {
    const l = this.latest;
    if (!this.words) return;
    const turn = Number.isNaN(l.orientationDeg) ? '' : ` · orientation error ${l.orientationDeg.toPrecision(3)}°`;
    this.element.textContent = this.withProblem(
      `${l.method} · ${l.iterations} it · tip error ${twoDigits(l.tipDistance)}${turn} · ${l.ms.toFixed(2)} ms · ${this.words.text}`,
    );
  }

  private withProblem(text: string): string {
    return this.problemText && text ? `${this.problemText} — ${text}` : this.problemText || text;
  }
}
