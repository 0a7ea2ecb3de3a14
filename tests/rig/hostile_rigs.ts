// Small files that ask for a lot (the hostile-input audit's memory bombs), built in memory so no
// big file is committed: a .gltf of millions of empty nodes, and a few-KB .glb whose mesh
// attributes are accessors without a bufferView (all zeros) of 512 MiB each.
import { packGlb } from '../../scripts/rig_files/glb.js';
import { treeGltf } from '../../scripts/rig_files/tree_rigs.js';

/** .gltf text of `count` empty nodes (about 3 bytes each), with a one-joint skin so it looks like a rig. */
export function manyNodesGltf(count: number): Uint8Array {
  const head = '{"asset":{"version":"2.0"},"skins":[{"joints":[0]}],"nodes":[{}';
  const text = `${head}${',{}'.repeat(count - 1)}]}`;
  return new TextEncoder().encode(text);
}

/** Elements of a FLOAT VEC3 accessor just under 512 MiB (the old per-accessor cap). */
export const ZERO_VEC3_COUNT = Math.floor((512 * 1024 * 1024) / 12);

/**
 * A .glb of a two-joint skinned mesh whose `accessorCount` POSITION-like attributes are FLOAT VEC3
 * accessors with no bufferView and ZERO_VEC3_COUNT elements (512 MiB of zeros each, 40 of them are
 * 20 GiB); the file itself is a few KB.
 */
export function zeroAccessorGlb(accessorCount: number): Uint8Array {
  const gltf = treeGltf([-1, 0]) as Record<string, unknown> & ReturnType<typeof treeGltf>;
  const accessors = Array.from({ length: accessorCount }, () => ({
    componentType: 5126,
    type: 'VEC3',
    count: ZERO_VEC3_COUNT,
  }));
  const attributes: Record<string, number> = { POSITION: 0 };
  for (let k = 1; k < accessorCount; k++) attributes[`_EXTRA${k}`] = k;
  gltf.nodes.push({ name: 'body', mesh: 0, skin: 0 });
  (gltf.scenes[0] as { nodes: number[] }).nodes.push(2);
  return packGlb({ ...gltf, accessors, meshes: [{ primitives: [{ attributes }] }] });
}
