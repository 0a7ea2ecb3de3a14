// A running median (and quantiles, max) over the last N samples, for the page's solve times.
// Fixed buffers: push() and the quantiles allocate nothing.
/** Running median over the last `capacity` samples. */
export class RunningMedian {
  private readonly ring: Float64Array;
  private readonly sorted: Float64Array;
  private count = 0;
  private next = 0;

  constructor(readonly capacity = 121) {
    this.ring = new Float64Array(capacity);
    this.sorted = new Float64Array(capacity);
  }

  /** Samples pushed since the last clear (also those that left the window). */
  total = 0;

  push(x: number): void {
    this.total++;
    this.ring[this.next] = x;
    this.next = (this.next + 1) % this.capacity;
    this.count = Math.min(this.count + 1, this.capacity);
  }

  get size(): number {
    return this.count;
  }

  median(): number {
    return this.quantile(0.5);
  }

  /** Quantile q in [0, 1] of the window, interpolating between closest ranks. */
  quantile(q: number): number {
    if (this.count === 0) return NaN;
    // The whole buffer sorted, its unused end past every sample: no view is made (the stats run in the frame loop).
    const s = this.sorted;
    for (let i = 0; i < this.capacity; i++) s[i] = i < this.count ? this.ring[i] : Infinity;
    s.sort();
    const at = q * (this.count - 1);
    const lo = Math.floor(at);
    return lo + 1 < this.count ? s[lo] + (s[lo + 1] - s[lo]) * (at - lo) : s[lo];
  }

  /** Largest sample in the window. */
  max(): number {
    let m = -Infinity;
    for (let i = 0; i < this.count; i++) m = Math.max(m, this.ring[i]);
    return this.count ? m : NaN;
  }

  clear(): void {
    this.total = 0;
    this.count = 0;
    this.next = 0;
  }
}
