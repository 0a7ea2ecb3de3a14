// The node hierarchy and skins of a glTF JSON document, checked: every index in range, every node
// with at most one parent, no cycle, every transform finite. World matrices are the nodes' own
// (default, as-loaded) transforms composed from the root down, as three.js computes them.
import { failIn } from './gltf_file.js';
import { fromColumnMajor, fromTRS, identity, multiply, type Mat4 } from './mat4.js';

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

/** "node 4 "hand.L"": how errors and messages name a node. */
export function nodeLabel(node: { index: number; name: string }): string {
  return node.name ? `node ${node.index} "${node.name}"` : `node ${node.index}`;
}

export type JsonObject = Record<string, unknown>;

/** `v` as a JSON object, or a RigFormatError naming `where`. */
export function asObject(v: unknown, where: string, file: string): JsonObject {
  if (typeof v !== 'object' || v === null || Array.isArray(v)) failIn(file, `${where} is not a JSON object`);
  return v as JsonObject;
}

/** `v` as an array of objects (missing means empty). */
export function asObjectList(v: unknown, where: string, file: string): JsonObject[] {
  if (v === undefined) return [];
  if (!Array.isArray(v)) failIn(file, `${where} is not an array`);
  return v.map((x, k) => asObject(x, `${where}[${k}]`, file));
}

/** `v` as an integer in [0, count), or a RigFormatError naming `where`. */
export function asIndex(v: unknown, count: number, where: string, file: string): number {
  if (typeof v !== 'number' || !Number.isInteger(v) || v < 0 || v >= count)
    failIn(file, `${where} = ${JSON.stringify(v)} is not an index in 0..${count - 1}`);
  return v;
}

function numbers(v: unknown, length: number, where: string, file: string): number[] {
  if (!Array.isArray(v) || v.length !== length) failIn(file, `${where} must be ${length} numbers`);
  return v.map((x, k) => {
    if (typeof x !== 'number' || !Number.isFinite(x)) failIn(file, `${where}[${k}] is not a finite number (NaN or infinite)`);
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

/** Reads and checks `nodes` of a glTF JSON document. Throws RigFormatError on a cycle or bad data. */
export function readNodes(json: JsonObject, file: string): GltfNode[] {
  const defs = asObjectList(json.nodes, 'nodes', file);
  const nodes: GltfNode[] = defs.map((def, index) => {
    const where = `nodes[${index}]`;
    const name = typeof def.name === 'string' ? def.name : '';
    const children = def.children === undefined ? [] : def.children;
    if (!Array.isArray(children)) failIn(file, `${where}.children is not an array`);
    return {
      index,
      name,
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
      if (child.parent !== -1 && child.parent !== node.index)
        failIn(file, `${nodeLabel(child)} is a child of both ${nodeLabel(nodes[child.parent])} and ${nodeLabel(node)}`);
      child.parent = node.index;
    }
  for (const node of nodes) {
    // With at most one parent each, a cycle shows as an ancestor chain longer than the node count.
    const path = [node.index];
    for (let at = node.parent; at !== -1; at = nodes[at].parent) {
      if (at === node.index) {
        const names = path.map((i) => nodeLabel(nodes[i])).concat(nodeLabel(node));
        failIn(file, `node hierarchy has a cycle: ${names.reverse().join(' -> ')}`);
      }
      path.push(at);
      if (path.length > nodes.length) break; // a cycle above this node: reported from one of its nodes
    }
  }
  nodes.forEach((node, i) => (node.local = readLocal(defs[i], `nodes[${i}]`, file)));
  return nodes;
}

/** World matrices of all nodes (row-major), composing local transforms from the roots. */
export function worldMatrices(nodes: GltfNode[]): Mat4[] {
  const world: (Mat4 | undefined)[] = new Array(nodes.length);
  const get = (i: number): Mat4 => {
    const cached = world[i];
    if (cached) return cached;
    const p = nodes[i].parent;
    return (world[i] = p === -1 ? nodes[i].local : multiply(get(p), nodes[i].local));
  };
  return nodes.map((_, i) => get(i));
}

/** Reads `skins`: joints in range and not repeated within a skin. Throws RigFormatError. */
export function readSkins(json: JsonObject, nodeCount: number, file: string): GltfSkin[] {
  return asObjectList(json.skins, 'skins', file).map((def, index) => {
    const where = `skins[${index}]`;
    if (!Array.isArray(def.joints) || def.joints.length === 0) failIn(file, `${where}.joints is missing or empty`);
    const joints = def.joints.map((j, k) => asIndex(j, nodeCount, `${where}.joints[${k}]`, file));
    const seen = new Set<number>();
    joints.forEach((j, k) => {
      if (seen.has(j)) failIn(file, `${where}.joints[${k}] repeats node ${j}`);
      seen.add(j);
    });
    const ibm = def.inverseBindMatrices;
    return {
      index,
      name: typeof def.name === 'string' ? def.name : '',
      joints,
      inverseBindMatrices: ibm === undefined ? undefined : asIndex(ibm, Number.MAX_SAFE_INTEGER, `${where}.inverseBindMatrices`, file),
    };
  });
}
