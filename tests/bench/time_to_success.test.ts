// Time to success counts only the solves that reached their targets, and its shares are of every
// reachable sample: a method that fails fast cannot look faster than one that succeeds.
import { describe, expect, it } from 'vitest';

import { summarize, type SolveResult } from '../../bench-node/metrics.js';
import { timeToSuccessTable } from '../../bench-node/table.js';
import { timeToSuccess } from '../../bench-node/time_to_success.js';

const solve = (seconds: number, E: number): SolveResult => ({
  E,
  tipDistance: Math.sqrt(2 * E),
  iterations: 1,
  seconds,
  stopReason: E < 1e-4 ? 'converged_E' : 'zero_step',
  wobbleDuring: NaN,
  wobbleAfter: NaN,
  jumpDeg: NaN,
});

describe('time to success', () => {
  it('takes the median and p95 of the successful solves only, and shares within 1, 10, 100 ms of all', () => {
    const t = timeToSuccess([0.0005, 0.002, 0.05, 0.2, 0.0001], [true, true, true, true, false]);
    expect(t.t_success_median_s).toBeCloseTo((0.002 + 0.05) / 2, 12);
    expect(t.success_within_1ms).toBeCloseTo(1 / 5, 12); // the fast failure does not count
    expect(t.success_within_10ms).toBeCloseTo(2 / 5, 12);
    expect(t.success_within_100ms).toBeCloseTo(3 / 5, 12);
  });

  it('has no times when nothing succeeded, and no shares when nothing was judged', () => {
    expect(timeToSuccess([0.001], [false])).toMatchObject({
      t_success_median_s: null,
      t_success_p95_s: null,
      success_within_100ms: 0,
    });
    expect(timeToSuccess([], []).success_within_1ms).toBeNaN();
  });

  it('a method that gives up at once has the shorter mean time but the later success', () => {
    const key = { rig: 'r', experiment: 'random' as const, engine: 'wasm' };
    const test = { errorTolerance: 1e-4, tipTolerance: 0 };
    const quitter = summarize(
      { ...key, method: 'quitter' },
      [solve(1e-5, 1), solve(1e-5, 1), solve(5e-4, 1e-5)],
      test,
      [1, 1, 1],
    );
    const worker = summarize(
      { ...key, method: 'worker' },
      [solve(2e-3, 1e-5), solve(2e-3, 1e-5), solve(2e-3, 1e-5)],
      test,
      [1, 1, 1],
    );
    expect(quitter.t_avg_s).toBeLessThan(worker.t_avg_s);
    expect(quitter.success_within_10ms).toBeCloseTo(1 / 3, 12);
    expect(worker.success_within_10ms).toBe(1);
    const table = timeToSuccessTable([quitter, worker])!;
    expect(table.rows.map((r) => r[2])).toEqual(['quitter', 'worker']);
    expect(table.rows[1].slice(7)).toEqual(['0.0%', '100.0%', '100.0%']);
  });
});
