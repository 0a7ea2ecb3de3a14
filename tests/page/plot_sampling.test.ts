// The iterations a convergence plot draws (web/src/page/plot_sampling.ts): all of a short history;
// about MAX_PLOT_POINTS of a long one, sorted and distinct, with 0, the last and each history's end;
// on a log axis most of them among the first iterations, on a linear axis evenly spread.
import { describe, expect, it } from 'vitest';

import { MAX_PLOT_POINTS, plotIndices } from '../../web/src/page/plot_sampling.js';

describe('plotIndices', () => {
  it('draws every iteration of a short history', () => {
    expect(plotIndices(5, true)).toEqual([0, 1, 2, 3, 4]);
    expect(plotIndices(MAX_PLOT_POINTS, false).length).toBe(MAX_PLOT_POINTS);
  });

  for (const log of [true, false]) {
    it(`samples a history of 10^5 iterations on a ${log ? 'log' : 'linear'} axis`, () => {
      const n = 100_000;
      const xs = plotIndices(n, log, [777, 54_321]);
      expect(xs.length).toBeGreaterThan(MAX_PLOT_POINTS / 2);
      expect(xs.length).toBeLessThanOrEqual(MAX_PLOT_POINTS + 3);
      for (let k = 1; k < xs.length; k++) expect(xs[k]).toBeGreaterThan(xs[k - 1]);
      for (const must of [0, 777, 54_321, n - 1]) expect(xs).toContain(must);
      const early = xs.filter((i) => i < 100).length;
      if (log)
        expect(early).toBeGreaterThanOrEqual(100 * 0.9); // the first 100 iterations nearly all drawn
      else expect(early).toBeLessThan(5);
    });
  }
});
