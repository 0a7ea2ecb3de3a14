// Statistics on hand-made result lists.
import { describe, expect, it } from 'vitest';

import { paperIterations, summarize, type SolveResult } from '../../bench-node/metrics.js';
import { interquartileMean, mean, median, quantile } from '../../bench-node/statistics.js';

describe('interquartile mean', () => {
  it('n divisible by 4: the plain mean of the middle half', () => {
    expect(interquartileMean([4, 1, 3, 2])).toBe(2.5); // middle of 1 2 3 4: 2, 3
    expect(interquartileMean([100, 1, 2, 3, 4, 5, 6, -100])).toBe(3.5); // 2 3 4 5
  });

  it('n = 5: boundary values weigh 3/4 (0.75 x1 + x2 + 0.75 x3) / 2.5', () => {
    expect(interquartileMean([1, 2, 3, 4, 5])).toBeCloseTo(3, 12);
    expect(interquartileMean([0, 0, 0, 10, 1000])).toBeCloseTo((0.75 * 0 + 0 + 0.75 * 10) / 2.5, 12);
  });

  it('n = 6: [1.5, 4.5] covers half of x1, x2, x3 and half of x4', () => {
    expect(interquartileMean([0, 10, 20, 30, 40, 1000])).toBeCloseTo((0.5 * 10 + 20 + 30 + 0.5 * 40) / 3, 12);
  });

  it('n = 7: [1.75, 5.25]', () => {
    const x = [0, 1, 2, 3, 4, 5, 600];
    expect(interquartileMean(x)).toBeCloseTo((0.25 * 1 + 2 + 3 + 4 + 0.25 * 5) / 3.5, 12);
  });

  it('n = 1, 2, 3', () => {
    expect(interquartileMean([7])).toBe(7);
    expect(interquartileMean([2, 4])).toBe(3);
    expect(interquartileMean([1, 2, 100])).toBeCloseTo((0.25 * 1 + 2 + 0.25 * 100) / 1.5, 12);
    expect(interquartileMean([])).toBeNaN();
  });

  it('ignores the order of the input and outliers at both ends', () => {
    const x = [5, 3, 1e9, 4, -1e9, 6, 2, 7];
    expect(interquartileMean(x)).toBe(4.5); // 3 4 5 6
  });
});

describe('quantiles', () => {
  it('interpolate linearly between closest ranks', () => {
    expect(median([3, 1, 2])).toBe(2);
    expect(median([4, 1, 3, 2])).toBe(2.5);
    expect(quantile([0, 10], 0.95)).toBeCloseTo(9.5, 12);
    const hundred = Array.from({ length: 101 }, (_, i) => i); // 0..100
    expect(quantile(hundred, 0.95)).toBe(95);
    expect(quantile([1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20], 0.95)).toBeCloseTo(
      19.05,
      12,
    );
    expect(quantile([5], 0.95)).toBe(5);
    expect(quantile([], 0.5)).toBeNaN();
    expect(mean([1, 2, 3, 6])).toBe(3);
  });
});

describe('summarize', () => {
  const result = (E: number, seconds: number, stopReason: string, iterations = 3): SolveResult => ({
    E,
    tipDistance: Math.sqrt(2 * E),
    seconds,
    stopReason,
    iterations,
    wobbleDuring: NaN,
    wobbleAfter: NaN,
    jumpDeg: NaN,
  });
  const eTest = { errorTolerance: 2e-4, tipTolerance: 0 };
  const all = (n: number): Uint8Array => new Uint8Array(n).fill(1);

  it('success means final E < errorTolerance; stop reasons are counted; times summarised', () => {
    const rows = [
      result(1e-5, 0.001, 'converged_E'),
      result(2e-4, 0.002, 'converged_grad'), // not below errorTolerance = 2e-4
      result(0.5, 1.0, 'timeout', 900),
      result(1e-4, 0.003, 'converged_E'),
    ];
    const row = summarize({ rig: 'knight', experiment: 'random', method: 'gn', engine: 'wasm' }, rows, eTest, all(4));
    expect(row.samples).toBe(4);
    expect(row.success_rate).toBe(0.5);
    expect(row.stop_reasons).toEqual({ converged_E: 2, converged_grad: 1, timeout: 1 });
    expect(row.t_avg_s).toBeCloseTo(1.006 / 4, 12);
    expect(row.t_max_s).toBe(1);
    expect(row.t_median_s).toBeCloseTo(0.0025, 12);
    expect(row.iter_avg).toBe((3 + 3 + 900 + 3) / 4);
    expect(row.E_max).toBe(0.5);
    expect(row.E_iqm).toBeCloseTo((1e-4 + 2e-4) / 2, 15);
    expect(row.wobble_during_avg).toBeNull();
    expect(row.unreachable).toBe(0);
    expect(row.jump_max_deg).toBeNull();
  });

  it('wobble: averages and maxima over the solves that have pinned effectors', () => {
    const rows = [
      { ...result(0, 0.001, 'converged_E'), wobbleDuring: 0.2, wobbleAfter: 0.1 },
      { ...result(0, 0.001, 'converged_E'), wobbleDuring: 0.4, wobbleAfter: 0.0 },
    ];
    const row = summarize({ rig: 'knight', experiment: 'drag', method: 'bfgs', engine: 'native' }, rows, eTest, all(2));
    expect(row.wobble_during_avg).toBeCloseTo(0.3, 12);
    expect(row.wobble_during_max).toBe(0.4);
    expect(row.wobble_after_avg).toBeCloseTo(0.05, 12);
    expect(row.wobble_after_max).toBe(0.1);
  });

  it('with a tip tolerance, success is every tip within it, whatever E', () => {
    const rows = [
      { ...result(1e-8, 0.001, 'converged_E'), tipDistance: 0.0009 }, // on target
      { ...result(1e-8, 0.001, 'converged_grad'), tipDistance: 0.001 }, // E tiny, a tip not within 0.001
      { ...result(0.5, 0.001, 'converged_E'), tipDistance: 1e-4 }, // E above errorTolerance, every tip within
    ];
    const row = summarize(
      { rig: 'knight', experiment: 'reach', method: 'lm', engine: 'wasm' },
      rows,
      { errorTolerance: 2e-4, tipTolerance: 0.001 },
      all(3),
    );
    expect(row.success_rate).toBeCloseTo(2 / 3, 12);
  });

  it('unreachable samples are counted apart and left out of success', () => {
    const rows = [
      { ...result(0, 0.001, 'converged_E'), tipDistance: 0 },
      { ...result(0, 0.001, 'converged_grad'), tipDistance: 0.3 }, // unreachable, missed
      { ...result(0, 0.001, 'converged_grad'), tipDistance: 0.2 }, // reachable, missed
      { ...result(0, 0.001, 'converged_grad'), tipDistance: 0.4 }, // unreachable, missed
    ];
    const test = { errorTolerance: 2e-4, tipTolerance: 0.01 };
    const row = summarize(
      { rig: 'knight', experiment: 'reach', method: 'lm', engine: 'wasm' },
      rows,
      test,
      Uint8Array.from([1, 0, 1, 0]),
    );
    expect(row.unreachable).toBe(2);
    expect(row.success_rate).toBe(0.5);
    expect(row.samples).toBe(4);
    const none = summarize(
      { rig: 'knight', experiment: 'reach', method: 'lm', engine: 'wasm' },
      rows,
      test,
      new Uint8Array(4),
    );
    expect(none.unreachable).toBe(4);
    expect(none.success_rate).toBeNaN();
  });

  it('jump_max_deg: the largest step jump of drag and reach rows, finite values only', () => {
    const rows = [2.5, 40, NaN, 0].map((jumpDeg) => ({ ...result(0, 0.001, 'converged_E'), jumpDeg }));
    expect(
      summarize({ rig: 'knight', experiment: 'reach', method: 'lm', engine: 'wasm' }, rows, eTest, all(4)).jump_max_deg,
    ).toBe(40);
    expect(
      summarize({ rig: 'knight', experiment: 'drag', method: 'lm', engine: 'wasm' }, rows.slice(0, 1), eTest, all(1))
        .jump_max_deg,
    ).toBe(2.5);
    expect(
      summarize({ rig: 'knight', experiment: 'incremental', method: 'lm', engine: 'wasm' }, rows, eTest, all(4))
        .jump_max_deg,
    ).toBeNull();
  });
});

describe('iterations as the report counted them (--paper)', () => {
  it('a solve ended by a stop test counts the call that found it; one cut short by the budget does not', () => {
    expect(paperIterations(2, 'converged_E')).toBe(3);
    expect(paperIterations(0, 'converged_E')).toBe(1); // already on target: one call found it
    expect(paperIterations(5, 'converged_grad')).toBe(6);
    expect(paperIterations(7, 'zero_step')).toBe(8);
    expect(paperIterations(40, 'timeout')).toBe(40);
    expect(paperIterations(100, 'max_iterations')).toBe(100);
  });
});
