// The node hierarchy and skins of a glTF JSON document, checked in linear time and walked without
// recursion: every index in range, every node with at most one parent, no cycle, every transform
// finite. World matrices are the nodes' own (default, as-loaded) transforms composed from the root
// down, as three.js computes them.
import { failIn } from '../rig_format_error.js';
import { asIndex, clip, type JsonObject } from './gltf_json.js';
import { fromColumnMajor, fromTRS, identity, multiply, type Mat4 } from '../mat4.js';
import { cycleText, findCycle, preorder } from '../tree.js';

export interface GltfNode {
  /** Index in the glTF `nodes` array. */
  index: number;
  /** The node's name, '' when it has none. */
  name: string;
  /** Parent node index, -1 for a scene root (or a node in no scene). */
  parent: number;
  children: number[];
  /** Local transform, row-major (from `matrix` or from translation/rotation/scale). */
  local: Mat4;
  /** The node's `extras` (any JSON value), undefined when absent. */
  extras: unknown;
}

export interface GltfSkin {
  index: number;
  name: string;
  /** Joint node indices, in the skin's order. */
  joints: number[];
  /** Accessor index of the inverse bind matrices, if any. */
  inverseBindMatrices: number | undefined;
}

/** "node 4 "hand.L"": how errors and messages name a node (a long name cut short). */
export function nodeLabel(node: { index: number; name: string }): string {
  return node.name ? `node ${node.index} "${clip(node.name)}"` : `node ${node.index}`;
}

function numbers(v: unknown, length: number, where: string, file: string): number[] {
  if (!Array.isArray(v) || v.length !== length) failIn(file, `${where} must be ${length} numbers`);
  return v.map((x, k) => {
    if (typeof x !== 'number' || !Number.isFinite(x))
      failIn(file, `${where}[${k}] is not a finite number (NaN or infinite)`);
    return x;
  });
}

function readLocal(def: JsonObject, where: string, file: string): Mat4 {
  if (def.matrix !== undefined) {
    const m = fromColumnMajor(numbers(def.matrix, 16, `${where}.matrix`, file));
    if (Math.abs(m[12]) + Math.abs(m[13]) + Math.abs(m[14]) + Math.abs(m[15] - 1) > 1e-9)
      failIn(file, `${where}.matrix is not affine (its last row is not 0 0 0 1)`);
    return m;
  }
  const t = def.translation === undefined ? [0, 0, 0] : numbers(def.translation, 3, `${where}.translation`, file);
  const q = def.rotation === undefined ? [0, 0, 0, 1] : numbers(def.rotation, 4, `${where}.rotation`, file);
  const s = def.scale === undefined ? [1, 1, 1] : numbers(def.scale, 3, `${where}.scale`, file);
  return fromTRS(t, q, s);
}

/** The checked node tree: the nodes, and every node index once with parents first (depth-first). */
export interface GltfTree {
  nodes: GltfNode[];
  order: number[];
}

/**
 * Reads and checks the glTF `nodes` list (`defs`, see readLists), in time linear in its size.
 * Throws RigFormatError on a cycle, a node with two parents, a child listed twice or bad data.
 */
export function readNodes(defs: JsonObject[], file: string): GltfTree {
  const nodes: GltfNode[] = defs.map((def, index) => {
    const where = `nodes[${index}]`;
    const children = def.children === undefined ? [] : def.children;
    if (!Array.isArray(children)) failIn(file, `${where}.children is not an array`);
    return {
      index,
      name: typeof def.name === 'string' ? def.name : '',
      parent: -1,
      children: children.map((c, k) => asIndex(c, defs.length, `${where}.children[${k}]`, file)),
      local: identity(),
      extras: def.extras,
    };
  });
  for (const node of nodes)
    for (const c of node.children) {
      const child = nodes[c];
      if (c === node.index) failIn(file, `node hierarchy has a cycle: ${nodeLabel(node)} is its own child`);
      if (child.parent === node.index) failIn(file, `nodes[${node.index}].children lists ${nodeLabel(child)} twice`);
      if (child.parent !== -1)
        failIn(file, `${nodeLabel(child)} is a child of both ${nodeLabel(nodes[child.parent])} and ${nodeLabel(node)}`);
      child.parent = node.index;
    }
  const parents = nodes.map((n) => n.parent);
  const cycle = findCycle(parents);
  if (cycle) failIn(file, `node hierarchy has a cycle: ${cycleText(cycle, (i) => nodeLabel(nodes[i]))}`);
  nodes.forEach((node, i) => (node.local = readLocal(defs[i], `nodes[${i}]`, file)));
  return {
    nodes,
    order: preorder(
      parents,
      nodes.map((n) => n.children),
    ),
  };
}

/** World matrices of all nodes (row-major), composing local transforms from the roots down. */
export function worldMatrices({ nodes, order }: GltfTree): Mat4[] {
  const world = new Array<Mat4>(nodes.length);
  for (const i of order) {
    const p = nodes[i].parent;
    world[i] = p === -1 ? nodes[i].local : multiply(world[p], nodes[i].local);
  }
  return world;
}

/**
 * Reads the glTF `skins` list (`defs`, see readLists; run after checkReferences, which checked
 * inverseBindMatrices): joints in range and not repeated within a skin. Throws RigFormatError.
 */
export function readSkins(defs: JsonObject[], nodeCount: number, file: string): GltfSkin[] {
  return defs.map((def, index) => {
    const where = `skins[${index}]`;
    if (!Array.isArray(def.joints) || def.joints.length === 0) failIn(file, `${where}.joints is missing or empty`);
    const joints = def.joints.map((j, k) => asIndex(j, nodeCount, `${where}.joints[${k}]`, file));
    const seen = new Set<number>();
    joints.forEach((j, k) => {
      if (seen.has(j)) failIn(file, `${where}.joints[${k}] repeats node ${j}`);
      seen.add(j);
    });
    return {
      index,
      name: typeof def.name === 'string' ? def.name : '',
      joints,
      inverseBindMatrices: def.inverseBindMatrices as number | undefined,
    };
  });
}
