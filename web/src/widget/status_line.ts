// The widget's status line: what the last per-frame solve did (method, iterations, time) and, in
// words, what it reached (status_words.ts). The words' sentence is the line's tooltip; their kind
// and whether every effector is on target are data attributes, for styling and tests.
import type { Method, SolveOutcome } from '../page/solver_port.js';
import { statusWords, type StatusWords } from '../page/status_words.js';

/** A distance (rig units) to 2 significant digits: "0.0012", "0.25", "3.4e-7". */
function twoDigits(d: number): string {
  return Number.isFinite(d) ? String(Number(d.toPrecision(2))) : String(d);
}

/**
 * Shows one solve in `el`: "lm · 4 it · tip error 0.0012 · 0.15 ms · on target". `outcome.tipDistance`
 * is the largest distance of an end effector from its target (rig units); `ms` the main-thread
 * time of the solve. Sets title (what the words mean), data-status (their kind) and data-reached.
 */
export function showSolve(el: HTMLElement, method: Method, outcome: SolveOutcome, ms: number): void {
  const words = statusWords(outcome.reached, outcome.stopReason);
  el.textContent = `${method} · ${outcome.iterations} it · tip error ${twoDigits(outcome.tipDistance)} · ${ms.toFixed(2)} ms · ${words.text}`;
  el.title = `${words.title}. Tip error: the largest distance of an end effector from its target, rig units.`;
  el.dataset.status = words.kind;
  el.dataset.reached = String(outcome.reached);
}

/** Shows `text` instead of a solve ('' empties the line); `kind`, when given, becomes data-status. */
export function showNote(el: HTMLElement, text: string, kind?: StatusWords['kind']): void {
  el.textContent = text;
  el.removeAttribute('title');
  delete el.dataset.reached;
  if (kind) el.dataset.status = kind;
  else delete el.dataset.status;
}
