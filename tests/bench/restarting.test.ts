// The harness's restart policy for the peers: the same restart starts as our solvers, within one
// time budget, the best result kept, never on chained (drag, reach) solves.
import { describe, expect, it } from 'vitest';

import type { SolveResult } from '../../bench-node/metrics.js';
import { RestartingRunner } from '../../bench-node/peers/restarting.js';
import type { Runner, RunSettings, SolveInput } from '../../bench-node/runner.js';

const settings: RunSettings = {
  method: 'fake',
  gradientTolerance: 1e-4,
  errorTolerance: 1e-4,
  tipTolerance: 0,
  timeBudgetSeconds: 1,
  paper: false,
  rigSize: 1,
};

/** A peer that reaches the target only from the start whose first angle is `good`, taking 5 iterations per run. */
class FakePeer implements Runner {
  readonly seen: { start: number | null; budget: number | undefined }[] = [];
  constructor(
    private readonly good: number,
    private readonly spendMs = 0,
  ) {}
  solve(input: SolveInput): SolveResult {
    const t0 = performance.now();
    while (performance.now() - t0 < this.spendMs);
    this.seen.push({ start: input.start ? input.start[0] : null, budget: input.budgetSeconds });
    const hit = input.start !== null && input.start[0] === this.good;
    const E = hit ? 1e-6 : 1 + (input.start ? input.start[0] : 0);
    return {
      E,
      tipDistance: Math.sqrt(2 * E),
      iterations: 5,
      seconds: 0,
      stopReason: hit ? 'converged_E' : 'zero_step',
      wobbleDuring: NaN,
      wobbleAfter: NaN,
      jumpDeg: 0,
    };
  }
  dispose(): void {}
}

const startOf = (k: number): Float64Array => Float64Array.of(k);
const input: SolveInput = { start: Float64Array.of(0), target: Float64Array.of(0, 0, 0), dragged: -1 };

describe('restarts for the peers', () => {
  it('restarts from the solvers’ restart starts until on target, and keeps the best', () => {
    const peer = new FakePeer(3);
    const r = new RestartingRunner(peer, startOf, settings, 10).solve(input);
    expect(peer.seen.map((s) => s.start)).toEqual([0, 1, 2, 3]);
    expect(r.stopReason).toBe('converged_E');
    expect(r.E).toBe(1e-6);
    expect(r.iterations).toBe(20);
    // Each run gets what is left of the one budget.
    const budgets = peer.seen.map((s) => s.budget!);
    expect(budgets[0]).toBe(1);
    for (let k = 1; k < budgets.length; k++) expect(budgets[k]).toBeLessThanOrEqual(budgets[k - 1]);
  });

  it('stops at the restart count, keeping the lowest E off target', () => {
    const peer = new FakePeer(99);
    const r = new RestartingRunner(peer, startOf, settings, 2).solve(input);
    expect(peer.seen).toHaveLength(3);
    expect(r.E).toBe(1); // the first run's start (0) gave the lowest E
    expect(r.stopReason).toBe('zero_step');
  });

  it('reports timeout when the budget ran out off target', () => {
    const peer = new FakePeer(99, 30);
    const r = new RestartingRunner(peer, startOf, { ...settings, timeBudgetSeconds: 0.05 }, 1000).solve(input);
    expect(peer.seen.length).toBeLessThan(5);
    expect(r.stopReason).toBe('timeout');
  });

  it('never restarts a chained solve (drag, reach) or with restarts 0', () => {
    const chained = new FakePeer(99);
    new RestartingRunner(chained, startOf, settings, 10).solve({ ...input, start: null });
    expect(chained.seen).toHaveLength(1);
    const none = new FakePeer(99);
    new RestartingRunner(none, startOf, settings, 0).solve(input);
    expect(none.seen).toHaveLength(1);
  });
});
