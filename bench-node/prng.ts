// Seeded random numbers for the target sets. One stream per (seed, experiment), so a target set
// does not depend on which other experiments, methods, engines or worker counts a run uses.

/** mulberry32: a small, fast 32-bit generator returning numbers in [0, 1). */
export function mulberry32(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let t = s;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** FNV-1a hash of `text`, as an unsigned 32-bit integer. */
export function hash32(text: string): number {
  let h = 0x811c9dc5;
  for (let i = 0; i < text.length; i++) {
    h ^= text.charCodeAt(i);
    h = Math.imul(h, 0x01000193);
  }
  return h >>> 0;
}

/** The generator for one named stream of a run seeded with `seed`. */
export function streamFor(seed: number, name: string): () => number {
  return mulberry32(hash32(`${seed >>> 0}:${name}`));
}

/** Uniform in [-1, 1). */
export function signedUnit(rand: () => number): number {
  return 2 * rand() - 1;
}
