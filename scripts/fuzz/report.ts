// The run's report: outcome counts per kind, the time budget against its promise, and every
// failing case with what it did and how to replay it.
import { FUZZ_KINDS, replayCommand, type BudgetSample, type CaseId, type CaseReport } from './case_id.js';
import { OUTCOME_LABELS, SEVERE, type OutcomeKind } from './outcome.js';

const KINDS = Object.keys(OUTCOME_LABELS) as OutcomeKind[];

/** Budgets below this are too short for a ratio to mean much: only their overrun is reported. */
const RATIO_MIN_BUDGET_SECONDS = 0.01;

/** The project's promise: a solve stays within this many times its time budget. */
const BUDGET_PROMISE = 2;

/** Cases per outcome kind. */
export function countOutcomes(reports: readonly CaseReport[]): Record<OutcomeKind, number> {
  const counts = Object.fromEntries(KINDS.map((k) => [k, 0])) as Record<OutcomeKind, number>;
  for (const r of reports) counts[r.outcome.kind]++;
  return counts;
}

/** The word a promise line (the time budget, the deep chain) ends with when the run broke the promise. */
export const BROKEN = 'BROKEN';

/** The lines of `summaries` that report a broken promise. */
export function brokenPromises(...summaries: string[]): string[] {
  return summaries.flatMap((s) => s.split('\n')).filter((line) => line.endsWith(`: ${BROKEN}`));
}

/** The run's exit code: 1 on any severe outcome, unclear error, stack leak or broken promise line, else 0. */
export function exitCode(reports: readonly CaseReport[], leak: boolean, summaries: readonly string[]): number {
  const unclear = reports.some((r) => r.outcome.kind === 'unclear');
  return severeCount(reports) > 0 || unclear || leak || brokenPromises(...summaries).length > 0 ? 1 : 0;
}

/** Cases with a severe outcome (crash, hang, silent wrong, read outside). */
export function severeCount(reports: readonly CaseReport[]): number {
  return reports.filter((r) => SEVERE.includes(r.outcome.kind)).length;
}

/** A text table: one row per case kind and a total, one column per outcome. */
export function countTable(reports: readonly CaseReport[]): string {
  const kinds = FUZZ_KINDS.filter((k) => reports.some((r) => r.id.kind === k));
  const rows = [
    ['kind', ...KINDS.map((k) => OUTCOME_LABELS[k]), 'cases'],
    ...[...kinds, 'all'].map((kind) => {
      const mine = reports.filter((r) => kind === 'all' || r.id.kind === kind);
      const counts = countOutcomes(mine);
      return [kind, ...KINDS.map((k) => String(counts[k])), String(mine.length)];
    }),
  ];
  const widths = rows[0].map((_, c) => Math.max(...rows.map((row) => row[c].length)));
  return rows
    .map((row) => row.map((cell, c) => (c === 0 ? cell.padEnd(widths[c]) : cell.padStart(widths[c]))).join('  '))
    .join('\n');
}

const caseName = (id: CaseId): string => `${id.kind} case ${id.index}`;

interface Sample extends BudgetSample {
  id: CaseId;
}

function worst(samples: readonly Sample[], value: (s: Sample) => number): { value: number; id: CaseId } | undefined {
  let best: { value: number; id: CaseId } | undefined;
  for (const s of samples) if (!best || value(s) > best.value) best = { value: value(s), id: s.id };
  return best;
}

/** Seconds as signed milliseconds ("+1.25 ms", "-0.40 ms"). */
function milliseconds(seconds: number): string {
  return `${seconds >= 0 ? '+' : ''}${(seconds * 1000).toFixed(2)} ms`;
}

/** Lines on the time budget: worst ratios (budgets >= 10 ms) against the promise, worst overrun of shorter budgets. */
export function budgetSummary(reports: readonly CaseReport[]): string {
  const samples: Sample[] = reports.flatMap((r) => r.budgets.map((b) => ({ ...b, id: r.id })));
  const long = samples.filter((s) => s.budgetSeconds >= RATIO_MIN_BUDGET_SECONDS);
  const short = samples.filter((s) => s.budgetSeconds < RATIO_MIN_BUDGET_SECONDS);
  const lines: string[] = [];
  const e = worst(long, (s) => s.elapsedSeconds / s.budgetSeconds),
    w = worst(long, (s) => s.wallSeconds / s.budgetSeconds);
  if (e && w) {
    const holds = e.value <= BUDGET_PROMISE && w.value <= BUDGET_PROMISE;
    lines.push(
      `time budget, ${long.length} solves with a budget >= ${RATIO_MIN_BUDGET_SECONDS * 1000} ms: worst elapsedSeconds/budget ${e.value.toFixed(2)}x (${caseName(e.id)}), ` +
        `worst wall time/budget ${w.value.toFixed(2)}x (${caseName(w.id)}); promised within ${BUDGET_PROMISE}x: ${holds ? 'holds' : BROKEN}`,
    );
  }
  const eo = worst(short, (s) => s.elapsedSeconds - s.budgetSeconds),
    wo = worst(short, (s) => s.wallSeconds - s.budgetSeconds);
  if (eo && wo)
    lines.push(
      `time budget, ${short.length} solves with a budget < ${RATIO_MIN_BUDGET_SECONDS * 1000} ms: worst overrun elapsedSeconds ${milliseconds(eo.value)} (${caseName(eo.id)}), ` +
        `wall time ${milliseconds(wo.value)} (${caseName(wo.id)})`,
    );
  return lines.join('\n') || 'time budget: no solve with a finite budget';
}

function oneLine(text: string, max: number): string {
  const line = text.replace(/\s+/g, ' ').trim();
  return line.length > max ? `${line.slice(0, max - 3)}...` : line;
}

function entry(r: CaseReport): string {
  return [
    `[${OUTCOME_LABELS[r.outcome.kind]}] ${caseName(r.id)} (seed ${r.id.seed}): ${oneLine(r.outcome.message, 400)}`,
    `    input: ${oneLine(r.description, 1500)}`,
    `    replay: ${replayCommand(r.id)}`,
  ].join('\n');
}

/** Whether a solve of `r` with a budget >= 10 ms took more than the promise (elapsedSeconds or wall time). */
function overBudget(r: CaseReport): boolean {
  return r.budgets.some(
    (b) =>
      b.budgetSeconds >= RATIO_MIN_BUDGET_SECONDS &&
      Math.max(b.elapsedSeconds, b.wallSeconds) > BUDGET_PROMISE * b.budgetSeconds,
  );
}

/** Every failing case: the severe ones, those that broke the time budget's promise, then the unclear errors. */
export function failureList(reports: readonly CaseReport[]): string {
  const severe = reports.filter((r) => SEVERE.includes(r.outcome.kind));
  const slow = reports.filter(overBudget);
  const unclear = reports.filter((r) => r.outcome.kind === 'unclear');
  const parts: string[] = [];
  if (severe.length)
    parts.push(`${severe.length} failing cases (crash, hang, silent wrong, read outside):`, ...severe.map(entry));
  if (slow.length)
    parts.push(`${slow.length} cases with a solve over ${BUDGET_PROMISE}x its time budget:`, ...slow.map(entry));
  if (unclear.length) parts.push(`${unclear.length} unclear errors:`, ...unclear.map(entry));
  return parts.join('\n');
}
