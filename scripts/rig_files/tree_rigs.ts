// Rig files built in memory, of any size and shape: a .glb whose nodes form the tree a parent
// list gives (every node a joint of one skin, each 1 unit along +Y from its parent), and an A7
// .json of the same tree. For the loader tests and the fuzz's deep chains.
import { packGlb } from './glb.js';

/** Parents of a chain of `n` bones: -1, 0, 1, ..., n - 2. */
export function chainParents(n: number): number[] {
  return Array.from({ length: n }, (_, i) => i - 1);
}

/** The glTF JSON of the tree `parents` (node i named "link i"), for a test to edit before packGlb. */
export function treeGltf(parents: readonly number[]): {
  asset: object;
  scenes: object[];
  nodes: Record<string, unknown>[];
  skins: Record<string, unknown>[];
} {
  const nodes: Record<string, unknown>[] = parents.map((_, i) => ({ name: `link ${i}`, translation: [0, 1, 0] }));
  parents.forEach((p, i) => {
    if (p >= 0) ((nodes[p].children ??= []) as number[]).push(i);
  });
  const roots = parents.flatMap((p, i) => (p < 0 ? [i] : []));
  return {
    asset: { version: '2.0' },
    scenes: [{ nodes: roots }],
    nodes,
    skins: [{ joints: parents.map((_, i) => i) }],
  };
}

/** The .glb of the tree `parents`. */
export function treeGlb(parents: readonly number[]): Uint8Array {
  return packGlb(treeGltf(parents));
}

/** A7 JSON text of the tree `parents`: bones of length 1 along +x, `bone` fields merged into each. */
export function treeA7(
  parents: readonly number[],
  bone: Record<string, unknown> = {},
  doc: Record<string, unknown> = {},
): string {
  const bones = parents.map((p) => ({
    parent_id: p,
    length: 1,
    rest_T: [
      [1, 0, 0, p < 0 ? 0 : 1],
      [0, 1, 0, 0],
      [0, 0, 1, 0],
    ],
    ...bone,
  }));
  return JSON.stringify({ bones, ...doc });
}
