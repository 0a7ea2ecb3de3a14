// Parent arrays walked without recursion and in linear time, so that a chain 100,000 deep costs
// no stack and a hostile hierarchy no quadratic time. A parent array holds, per node, the index of
// its parent or -1 for a root.

/**
 * A cycle of `parents`, each node the parent of the next and the last the parent of the first,
 * starting at its lowest index; null when every parent chain ends at a root. Every entry of
 * `parents` must be -1 or an index.
 */
export function findCycle(parents: ArrayLike<number>): number[] | null {
  const UNSEEN = 0,
    ON_WALK = 1,
    ENDS_AT_ROOT = 2;
  const state = new Uint8Array(parents.length);
  const walk: number[] = [];
  for (let start = 0; start < parents.length; start++) {
    let at = start;
    walk.length = 0;
    while (at !== -1 && state[at] === UNSEEN) {
      state[at] = ON_WALK;
      walk.push(at);
      at = parents[at];
    }
    if (at !== -1 && state[at] === ON_WALK) {
      // The walk went child -> parent and came back to `at`: the cycle is its tail, reversed.
      const cycle = walk.slice(walk.indexOf(at)).reverse();
      let first = 0;
      for (let k = 1; k < cycle.length; k++) if (cycle[k] < cycle[first]) first = k;
      return cycle.slice(first).concat(cycle.slice(0, first));
    }
    for (const node of walk) state[node] = ENDS_AT_ROOT;
  }
  return null;
}

/**
 * Every node once, parents before children: depth-first from the roots in index order, children
 * in the order `children` lists them. The hierarchy must have no cycle.
 */
export function preorder(parents: ArrayLike<number>, children: readonly (readonly number[])[]): number[] {
  const order: number[] = [];
  const stack: number[] = [];
  for (let i = parents.length - 1; i >= 0; i--) if (parents[i] === -1) stack.push(i);
  while (stack.length > 0) {
    const node = stack.pop()!;
    order.push(node);
    const kids = children[node];
    for (let k = kids.length - 1; k >= 0; k--) stack.push(kids[k]);
  }
  return order;
}

/** Longest stretch of a cycle that cycleText spells out, nodes. */
const CYCLE_NODES_SHOWN = 8;

/** A cycle from findCycle for messages: "a -> b -> c -> a", long ones shortened in the middle. */
export function cycleText(cycle: readonly number[], label: (node: number) => string): string {
  const parts = cycle.slice(0, CYCLE_NODES_SHOWN).map(label);
  if (cycle.length > CYCLE_NODES_SHOWN) parts.push(`... (${cycle.length - CYCLE_NODES_SHOWN} more)`);
  return [...parts, label(cycle[0])].join(' -> ');
}
