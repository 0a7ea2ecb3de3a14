// The skins' joints as the rig's bones: their order (depth-first through the node tree, parents
// first; a bone's parent is its nearest ancestor joint), their world matrices checked, and the
// skins' bind matrices read. Steps of importGltfRig (gltf_rig.ts).
import { bindMatrices } from './bind_pose.js';
import { BufferCache, readMat4Accessor } from './gltf_accessor.js';
import type { GltfContainer, SiblingReader } from './gltf_file.js';
import { nodeLabel, type GltfNode, type GltfSkin, type GltfTree } from './gltf_nodes.js';
import type { GltfLists } from './gltf_references.js';
import { allFinite, invertAffine, type Mat4 } from '../mat4.js';
import { failIn } from '../rig_format_error.js';
import { MAX_COORDINATE } from '../rig_limits.js';

/** The joints of a node tree in bone order. */
export interface JointOrder {
  /** The joint nodes, one per bone, parents first. */
  order: GltfNode[];
  /** Each bone's parent bone, -1 for a root. */
  parents: Int32Array;
  /** Each node's bone, -1 for a node that is no joint. */
  boneOfNode: Int32Array;
  /** Each node's level in the tree, 1 for a root. */
  nodeDepth: Int32Array;
}

/** The joints (`isJoint`: node indices) of `tree` in bone order. */
export function jointsInTreeOrder(tree: GltfTree, isJoint: ReadonlySet<number>): JointOrder {
  const nodes = tree.nodes;
  const order: GltfNode[] = [];
  const boneOfNode = new Int32Array(nodes.length).fill(-1);
  const jointAbove = new Int32Array(nodes.length).fill(-1); // bone of the nearest joint at or above each node
  const nodeDepth = new Int32Array(nodes.length);
  const parents: number[] = [];
  for (const i of tree.order) {
    const p = nodes[i].parent;
    const above = p === -1 ? -1 : jointAbove[p];
    nodeDepth[i] = p === -1 ? 1 : nodeDepth[p] + 1;
    if (isJoint.has(i)) {
      boneOfNode[i] = order.length;
      order.push(nodes[i]);
      parents.push(above);
    }
    jointAbove[i] = boneOfNode[i] >= 0 ? boneOfNode[i] : above;
  }
  return { order, parents: Int32Array.from(parents), boneOfNode, nodeDepth };
}

/**
 * Throws RigFormatError naming the joint of `order` whose world matrix in `world` (by node index,
 * row-major) is not finite, is singular or lies beyond MAX_COORDINATE; `which` says which pose
 * ('' for the nodes' own, 'bind pose ').
 */
export function checkWorldMatrices(order: readonly GltfNode[], world: Mat4[], which: string, file: string): void {
  for (const n of order) {
    const W = world[n.index];
    if (!allFinite(W)) failIn(file, `${nodeLabel(n)}: ${which}world matrix has a non-finite entry`);
    if (invertAffine(W) === null) failIn(file, `${nodeLabel(n)}: ${which}world matrix is singular (a zero scale?)`);
    if (Math.max(Math.abs(W[3]), Math.abs(W[7]), Math.abs(W[11])) > MAX_COORDINATE)
      failIn(
        file,
        `${nodeLabel(n)}: ${which}world position (${W[3]}, ${W[7]}, ${W[11]}) lies beyond +-${MAX_COORDINATE} scene units`,
      );
  }
}

/**
 * Each skin's bind matrices (bind_pose.ts bindMatrices), or undefined for a skin without inverse
 * bind matrices. Reads them (from the GLB, a data URI or a side file through `readSibling`), so
 * that a missing buffer or a NaN is a RigFormatError naming the skin's accessor.
 */
export async function readBindMatrices(
  container: GltfContainer,
  lists: GltfLists,
  skins: GltfSkin[],
  tree: GltfTree,
  file: string,
  readSibling?: SiblingReader,
): Promise<(Mat4[] | undefined)[]> {
  const buffers = new BufferCache(container, lists, file, readSibling);
  const binds: (Mat4[] | undefined)[] = [];
  for (const skin of skins) {
    if (skin.inverseBindMatrices === undefined) {
      binds.push(undefined);
      continue;
    }
    const where = `skins[${skin.index}].inverseBindMatrices`;
    const ibm = await readMat4Accessor(lists, buffers, skin.inverseBindMatrices, skin.joints.length, where, file);
    binds.push(bindMatrices(ibm, skin, tree, `${where} (accessor ${skin.inverseBindMatrices})`, file));
  }
  return binds;
}
