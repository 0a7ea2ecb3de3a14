// Summary statistics of a list of numbers: mean, largest, quantiles and the interquartile mean.
//
// Definitions (n values, x_(0) <= ... <= x_(n-1) sorted):
//   mean            sum / n
//   quantile(p)     linear interpolation between closest ranks: at position h = p (n - 1),
//                   x_(floor h) + (h - floor h) (x_(floor h + 1) - x_(floor h)) (numpy's default);
//                   median = quantile(0.5), p95 = quantile(0.95)
//   IQM             the mean of the middle half. In rank space value x_(i) covers [i, i + 1); the
//                   middle half is [n/4, 3n/4]; each value is weighted by its overlap with that
//                   interval and the weighted sum is divided by n/2. For n divisible by 4 this is
//                   the plain mean of x_(n/4) .. x_(3n/4 - 1); otherwise the two boundary values
//                   enter with a fractional weight (n = 5: 0.75 x_(1) + x_(2) + 0.75 x_(3), over 2.5).

/** The mean; NaN for no values. */
export function mean(values: ArrayLike<number>): number {
  if (values.length === 0) return NaN;
  let s = 0;
  for (let i = 0; i < values.length; i++) s += values[i];
  return s / values.length;
}

/** The largest value; NaN for no values. */
export function maxOf(values: ArrayLike<number>): number {
  if (values.length === 0) return NaN;
  let m = -Infinity;
  for (let i = 0; i < values.length; i++) m = Math.max(m, values[i]);
  return m;
}

function sorted(values: ArrayLike<number>): Float64Array {
  return Float64Array.from(values).sort();
}

/** Quantile p in [0, 1] by linear interpolation between closest ranks. NaN for no values. */
export function quantile(values: ArrayLike<number>, p: number): number {
  const s = sorted(values);
  return quantileSorted(s, p);
}

function quantileSorted(s: Float64Array, p: number): number {
  const n = s.length;
  if (n === 0) return NaN;
  const h = p * (n - 1);
  const lo = Math.floor(h);
  const hi = Math.min(lo + 1, n - 1);
  return s[lo] + (h - lo) * (s[hi] - s[lo]);
}

/** quantile(values, 0.5). */
export function median(values: ArrayLike<number>): number {
  return quantile(values, 0.5);
}

/** Interquartile mean: the mean of the middle half, fractional weights at the edges (see above). */
export function interquartileMean(values: ArrayLike<number>): number {
  const s = sorted(values);
  const n = s.length;
  if (n === 0) return NaN;
  const lo = n / 4,
    hi = (3 * n) / 4;
  let sum = 0;
  for (let i = Math.floor(lo); i < Math.ceil(hi); i++) {
    const w = Math.min(i + 1, hi) - Math.max(i, lo);
    if (w > 0) sum += w * s[i];
  }
  return sum / (n / 2);
}
