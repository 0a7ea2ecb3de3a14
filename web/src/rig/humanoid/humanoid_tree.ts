// The tree questions humanoid recognition asks of a rig's bones, each in constant or linear time
// so that a hostile 16,384-bone file costs no more than a real one: is one bone below another,
// how deep is a bone, which bones lie between two bones, does a subtree hold a marked bone, what
// are a bone's children.

/**
 * A rig's bone tree. `parents` must list parents first in depth-first order (as the importers
 * number bones), so that every subtree is a run of consecutive bones.
 */
export class BoneTree {
  /** Depth of each bone (0 for a root). */
  readonly depth: Int32Array;
  /** The last bone of each bone's subtree. */
  private readonly last: Int32Array;

  constructor(readonly parents: ArrayLike<number>) {
    const n = parents.length;
    this.depth = new Int32Array(n);
    for (let b = 0; b < n; b++) if (parents[b] >= 0) this.depth[b] = this.depth[parents[b]] + 1;
    this.last = Int32Array.from({ length: n }, (_, b) => b);
    for (let b = n - 1; b >= 0; b--)
      if (parents[b] >= 0) this.last[parents[b]] = Math.max(this.last[parents[b]], this.last[b]);
  }

  /** True when bone `a` lies strictly below bone `b` (a descendant of it). */
  below(a: number, b: number): boolean {
    return a > b && a <= this.last[b];
  }

  /** The number of bones strictly below bone `b`. */
  descendants(b: number): number {
    return this.last[b] - b;
  }

  /** The child bones of `b`, in order. Linear in the size of its subtree. */
  children(b: number): number[] {
    const kids: number[] = [];
    for (let c = b + 1; c <= this.last[b]; c = this.last[c] + 1) kids.push(c);
    return kids;
  }

  /**
   * The bones strictly between `a` and `b` on the tree path joining them, in order from `a`; null
   * when they lie in different trees. Linear in their depths.
   */
  between(a: number, b: number): number[] | null {
    const fromA: number[] = [];
    const onA = new Map<number, number>();
    for (let x = a; x >= 0; x = this.parents[x]) {
      onA.set(x, fromA.length);
      fromA.push(x);
    }
    const fromB: number[] = [];
    let x = b;
    while (x >= 0 && !onA.has(x)) {
      fromB.push(x);
      x = this.parents[x];
    }
    if (x < 0) return null;
    const path = [...fromA.slice(0, onA.get(x)! + 1), ...fromB.reverse()];
    return path.slice(1, -1);
  }

  /**
   * A test "does bone b have a marked bone strictly below it", answered in constant time after a
   * linear pass over `marked`.
   */
  markedBelow(marked: Iterable<number>): (b: number) => boolean {
    const count = new Int32Array(this.parents.length + 1); // count[k]: marked bones among 0..k-1
    for (const m of marked) count[m + 1] = 1;
    for (let k = 1; k < count.length; k++) count[k] += count[k - 1];
    return (b) => count[this.last[b] + 1] - count[b + 1] > 0;
  }
}
