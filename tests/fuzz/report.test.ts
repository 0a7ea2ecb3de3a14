// The fuzz run's verdict (scripts/fuzz.ts exits with exitCode()): a broken promise line fails the
// run as a severe outcome does, not only the words on the page.
import { describe, expect, it } from 'vitest';

import type { BudgetSample, CaseReport } from '../../scripts/fuzz/case_id.js';
import { budgetSummary, exitCode, failureList } from '../../scripts/fuzz/report.js';

/** An api case that ended `kind`, with one solve of a 10 ms budget taking `ratio` times it. */
function report(kind: CaseReport['outcome']['kind'], ratio: number): CaseReport {
  const budget: BudgetSample = { budgetSeconds: 0.01, elapsedSeconds: 0.01 * ratio, wallSeconds: 0.01 * ratio };
  return {
    id: { kind: 'api', seed: 1, index: 0 },
    description: '',
    outcome: { kind, message: '' },
    budgets: [budget],
    seconds: 0,
  };
}

const deepChainHolds =
  '10000-bone chain, file bytes to a rig in WebAssembly (median of 5): .glb 80 ms, A7 .json 60 ms; promised under 1 s: holds';
const deepChainBroken = deepChainHolds.replace('holds', 'BROKEN').replace('80 ms', '1500 ms');

describe('the exit code of npm run fuzz', () => {
  it('is 0 when every case is clean and every promise holds', () => {
    const reports = [report('ok', 1.9), report('clear', 0.5)];
    expect(budgetSummary(reports)).toMatch(/promised within 2x: holds$/);
    expect(exitCode(reports, false, [budgetSummary(reports), deepChainHolds])).toBe(0);
  });

  it('is 1 when the time budget line says BROKEN, though every case is ok', () => {
    const reports = [report('ok', 1), report('ok', 2.5)];
    const budget = budgetSummary(reports);
    expect(budget).toMatch(/worst elapsedSeconds\/budget 2\.50x .*promised within 2x: BROKEN$/);
    expect(exitCode(reports, false, [budget, deepChainHolds])).toBe(1);
    expect(failureList(reports)).toMatch(
      /^1 cases with a solve over 2x its time budget:\n\[ok\] api case 0 .*\n.*\n {4}replay: npm run fuzz -- --seed 1 --kind api --case 0$/,
    );
  });

  it('is 1 when the deep-chain line says BROKEN', () => {
    const reports = [report('ok', 1)];
    expect(exitCode(reports, false, [budgetSummary(reports), deepChainBroken])).toBe(1);
  });

  it('is 1 on a severe outcome, an unclear error or a stack leak', () => {
    const summaries = [budgetSummary([report('ok', 1)]), deepChainHolds];
    expect(exitCode([report('hang', 1)], false, summaries)).toBe(1);
    expect(exitCode([report('ok', 1)], true, summaries)).toBe(1);
    expect(exitCode([report('unclear', 1)], false, summaries)).toBe(1);
    expect(exitCode([report('clear', 1)], false, summaries)).toBe(0);
  });
});
