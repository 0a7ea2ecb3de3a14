// How a pose file names the bones of a rig: by name, or by index ("#12") for a bone whose name
// cannot tell it apart (no name, as in every A7 rig; a name another bone has; a name that looks
// like an index key). Writer and reader compute the same keys from the rig's names.

const INDEX_KEY = /^#\d+$/;

/** The key of bone `index` when its name cannot be used. */
export const indexKey = (index: number): string => `#${index}`;

/**
 * The pose-file key of each bone of a rig whose bones are called `names` (rig order): the name
 * when it is not '', no other bone has it and it does not look like "#12"; else "#<index>".
 * The keys are distinct.
 */
export function poseBoneKeys(names: readonly string[]): string[] {
  const count = new Map<string, number>();
  for (const n of names) count.set(n, (count.get(n) ?? 0) + 1);
  return names.map((n, i) => (n === '' || count.get(n)! > 1 || INDEX_KEY.test(n) ? indexKey(i) : n));
}
