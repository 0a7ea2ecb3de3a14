// Which iterations a convergence plot draws: all of them up to `max`, else about `max` of them,
// spaced evenly on the axis in use (logarithmically for a log axis, so the first iterations keep
// their detail), always with 0, the last one, and each history's own last iteration (where a
// method stopped). A compare in paper mode can bring 10^5 iterations per method; drawing them all
// would stall the page for a large part of a second.

/** Points drawn per series at most (about). */
export const MAX_PLOT_POINTS = 1500;

/**
 * Sorted iteration indices to draw out of 0..n-1. `log`: spaced evenly in log(1 + i); `ends`:
 * indices that must be drawn (each history's last); `max`: about how many.
 */
export function plotIndices(n: number, log: boolean, ends: readonly number[] = [], max = MAX_PLOT_POINTS): number[] {
  if (n <= max) return Array.from({ length: n }, (_, i) => i);
  const picked = new Set<number>([0, n - 1]);
  for (const e of ends) if (e >= 0 && e < n) picked.add(e);
  const top = log ? Math.log1p(n - 1) : n - 1;
  for (let k = 1; k < max; k++) {
    const at = (k / max) * top;
    picked.add(Math.min(n - 1, Math.round(log ? Math.expm1(at) : at)));
  }
  return [...picked].sort((a, b) => a - b);
}
