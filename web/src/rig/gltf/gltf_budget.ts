// Caps on how much a glTF file can make the rig importer and the page's three.js GLTFLoader build,
// checked on the parsed JSON (whose size json_budget.ts bounds before parsing) by counting list
// lengths, before anything is built from the lists: 4,000,000 empty nodes (12 MB of .gltf) made
// the importer take 3 GB at about 1 KB per node, and three.js builds an object per node, mesh,
// material and animation track. The bytes of accessor data are capped in gltf_ranges.ts.
// A real character has about 100 nodes, a few meshes and skins and a few dozen animation clips;
// the project's rigs have at most 67 nodes and 21 accessors. Every cap is past the 16,384 bones
// the core takes (rig_limits.ts) where the list grows with the bones.
import { failIn } from '../rig_format_error.js';
import type { JsonObject } from './gltf_json.js';
import { MAX_BONES } from '../rig_limits.js';

/** Most entries of each top-level glTF list. */
export const MAX_GLTF_LIST_LENGTHS: Readonly<Record<string, number>> = {
  nodes: 100_000,
  accessors: 100_000,
  bufferViews: 100_000,
  meshes: 10_000,
  materials: 10_000,
  textures: 10_000,
  images: 10_000,
  samplers: 10_000,
  animations: 10_000,
  cameras: 10_000,
  skins: 10_000,
  scenes: 10_000,
  buffers: 10_000,
};

/** Most entries of nested lists, summed over their parents: [parent list, child list, at most]. */
export const MAX_GLTF_NESTED_LENGTHS: readonly (readonly [string, string, number])[] = [
  ['skins', 'joints', 2 * MAX_BONES],
  ['meshes', 'primitives', 10_000],
  ['animations', 'channels', 200_000],
  ['animations', 'samplers', 200_000],
  ['scenes', 'nodes', 100_000],
];

/** `v`'s length when it is an array, else 0 (its shape is checked later, by gltf_references.ts). */
const lengthOf = (v: unknown): number => (Array.isArray(v) ? v.length : 0);

/**
 * Checks the glTF JSON document `json` against MAX_GLTF_LIST_LENGTHS and MAX_GLTF_NESTED_LENGTHS
 * by counting only. Throws RigFormatError naming `file`, the list, its length and the limit.
 */
export function checkGltfBudget(json: JsonObject, file: string): void {
  for (const [list, most] of Object.entries(MAX_GLTF_LIST_LENGTHS)) {
    const n = lengthOf(json[list]);
    if (n > most) failIn(file, `${n} ${list}; at most ${most} (the limit on glTF ${list})`);
  }
  for (const [parent, child, most] of MAX_GLTF_NESTED_LENGTHS) {
    const entries = Array.isArray(json[parent]) ? (json[parent] as unknown[]) : [];
    let n = 0;
    for (const e of entries) n += typeof e === 'object' && e !== null ? lengthOf((e as JsonObject)[child]) : 0;
    if (n > most)
      failIn(file, `${n} ${parent}[].${child} in all; at most ${most} (the limit on glTF ${parent}' ${child})`);
  }
}
