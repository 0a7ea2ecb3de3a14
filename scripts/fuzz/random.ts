// Seeded random choices for the fuzzer. Every case draws from its own stream, a function of
// (seed, kind, case number) only, so `--seed S --kind K --case N` replays one case alone.
import { streamFor } from '../../bench-node/prng.js';

export class Rand {
  constructor(private readonly next: () => number) {}

  /** The stream of case `index` of `kind` in a run seeded with `seed`. */
  static forCase(seed: number, kind: string, index: number): Rand {
    return new Rand(streamFor(seed, `fuzz:${kind}#${index}`));
  }

  /** Uniform in [0, 1). */
  float(): number {
    return this.next();
  }

  /** Uniform in [lo, hi). */
  range(lo: number, hi: number): number {
    return lo + (hi - lo) * this.next();
  }

  /** An integer in [0, n). */
  int(n: number): number {
    return Math.floor(this.next() * n);
  }

  /** An integer in [lo, hi], both included. */
  intIn(lo: number, hi: number): number {
    return lo + this.int(hi - lo + 1);
  }

  /** True with probability p. */
  chance(p: number): boolean {
    return this.next() < p;
  }

  /** One of `items`, uniformly. */
  pick<T>(items: readonly T[]): T {
    return items[this.int(items.length)];
  }

  /** One of the values, with probability proportional to its weight. */
  weighted<T>(entries: readonly (readonly [number, T])[]): T {
    let u = this.next() * entries.reduce((s, [w]) => s + w, 0);
    for (const [w, value] of entries) if ((u -= w) < 0) return value;
    return entries[entries.length - 1][1];
  }
}
