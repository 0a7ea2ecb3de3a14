// Mutations specific to glTF skeletons: IK extras with limits of 1e9 degrees (past +-36,000, so
// unbounded in their own direction and refused in the other: web/src/rig/limit_degrees.ts) and
// other absurd limits, node cycles and second parents, very deep and very wide joint hierarchies,
// huge counts, wrong buffer offsets and strides, degenerate transforms, bad bind-matrix
// accessors, bad skins.
import type { Json } from '../rig_files/glb.js';
import { INFINITY_MARK } from './json_text.js';
import type { Rand } from './random.js';

type Obj = Record<string, unknown>;

const isObj = (v: unknown): v is Obj => typeof v === 'object' && v !== null && !Array.isArray(v);

function show(v: unknown): string {
  const text = JSON.stringify(v) ?? String(v);
  return text.length > 60 ? `${text.slice(0, 57)}...` : text;
}

/** The joints of skin 0, when it still has a list of valid node indices. */
function joints(json: Json): number[] | undefined {
  const skin = Array.isArray(json.skins) ? json.skins[0] : undefined;
  const list = isObj(skin) ? skin.joints : undefined;
  const n = Array.isArray(json.nodes) ? json.nodes.length : 0;
  return Array.isArray(list) && list.length > 0 && list.every((j) => Number.isInteger(j) && j >= 0 && j < n)
    ? (list as number[])
    : undefined;
}

function childrenOf(node: Obj): number[] {
  if (!Array.isArray(node.children)) node.children = [];
  return node.children as number[];
}

const IK_EXTRAS: unknown[] = [
  { xzx_min: [-1e9, -1e9, -1e9], xzx_max: [1e9, 1e9, 1e9] },
  { xzx_min: [1e9, 1e9, 1e9], xzx_max: [1e9, 1e9, 1e9] },
  { xzx_min: [-1e9, -1e9, -1e9], xzx_max: [-1e9, -1e9, -1e9] },
  { xzx_min: [-999999999, 0, 0], xzx_max: [999999999, 0, 0] },
  { xzx_min: [1e308, 0, 0], xzx_max: [1e308, 0, 0] },
  { xzx_min: [10, 10, 10], xzx_max: [-10, -10, -10] },
  { xzx_min: [null, null, null], xzx_max: [null, null, null] },
  { xzx_min: [0, 0, 0], xzx_max: [0, 0, 0] },
  { xzx_min: [INFINITY_MARK, 0, 0] },
  { length: 1e308 },
  { length: -1 },
  { length: 1e-320 },
  { length: 1e9 },
  { tail: [1e308, 0, 0] },
  { tail: [0, 0, 0] },
  { tail: [1e200, 1e200, 1e200] },
  { child: 'nope' },
  { child: 1e9 },
  { child: -1 },
  { child: 0.5 },
  { effector: 'yes' },
  { effector: true },
  { effector: false },
  { unknown: 1 },
  [],
  'x',
  null,
  7,
];

/** One glTF-specific mutation of `json`; its description. */
export function mutateGltf(r: Rand, json: Json): string {
  const js = joints(json);
  const nodes = Array.isArray(json.nodes) ? (json.nodes as Obj[]) : undefined;
  if (!js || !nodes || !nodes.every(isObj)) return 'no glTF-specific mutation (skin 0 or the nodes are already broken)';
  const j = r.pick(js),
    node = nodes[j];
  const at = `nodes[${j}]`;
  const skin = json.skins[0];
  const accessors = Array.isArray(json.accessors) ? (json.accessors as Obj[]) : [];
  const ibm =
    typeof skin.inverseBindMatrices === 'number' && isObj(accessors[skin.inverseBindMatrices])
      ? accessors[skin.inverseBindMatrices]
      : undefined;
  const views = Array.isArray(json.bufferViews) ? (json.bufferViews as Obj[]) : [];
  const ibmView =
    ibm && typeof ibm.bufferView === 'number' && isObj(views[ibm.bufferView]) ? views[ibm.bufferView] : undefined;
  return r.weighted<() => string>([
    [
      5,
      () => {
        const ik = r.pick(IK_EXTRAS);
        if (r.chance(0.2)) {
          js.forEach((k) => (nodes[k].extras = { ik: structuredClone(ik) }));
          return `every joint's extras.ik = ${show(ik)}`;
        }
        node.extras = { ik: structuredClone(ik) };
        return `${at}.extras.ik = ${show(ik)}`;
      },
    ],
    [
      2,
      () => {
        const parent = nodes.findIndex((n) => Array.isArray(n.children) && (n.children as unknown[]).includes(j));
        if (parent >= 0 && r.chance(0.6)) {
          childrenOf(node).push(parent);
          return `${at}.children gets its parent ${parent} (a cycle)`;
        }
        if (r.chance(0.5)) {
          childrenOf(node).push(j);
          return `${at}.children gets ${j} (itself)`;
        }
        const other = r.pick(js.filter((k) => k !== parent));
        if (other === undefined) return 'no second parent (one joint)';
        childrenOf(nodes[other]).push(j);
        return `nodes[${other}].children gets ${j} (a second parent)`;
      },
    ],
    [
      2,
      () => {
        const count = r.pick([1000, 10_000, 100_000]);
        const first = nodes.length;
        for (let k = 0; k < count; k++)
          nodes.push({ name: `deep ${k}`, translation: [0, 0.01, 0], children: k + 1 < count ? [first + k + 1] : [] });
        childrenOf(node).push(first);
        skin.joints = [...js, ...Array.from({ length: count }, (_, k) => first + k)];
        delete skin.inverseBindMatrices;
        return `a chain of ${count} joints under ${at} (no bind matrices)`;
      },
    ],
    [
      1,
      () => {
        const count = r.pick([1000, 20_000]);
        const first = nodes.length;
        for (let k = 0; k < count; k++) nodes.push({ name: `wide ${k}`, translation: [Math.cos(k), 0.1, Math.sin(k)] });
        childrenOf(node).push(...Array.from({ length: count }, (_, k) => first + k));
        skin.joints = [...js, ...Array.from({ length: count }, (_, k) => first + k)];
        delete skin.inverseBindMatrices;
        return `${count} leaf joints under ${at} (no bind matrices)`;
      },
    ],
    [
      1,
      () => {
        for (let k = 0; k < 100_000; k++) nodes.push({});
        return '100000 empty nodes appended';
      },
    ],
    [
      2,
      () => {
        if (!ibm) return 'no bind-matrix accessor to change';
        const v = r.pick<unknown>([1e9, 2 ** 32 - 1, -1, 1.5, '10', 0, js.length - 1]);
        ibm.count = v;
        return `bind-matrix accessor count = ${show(v)}`;
      },
    ],
    [
      4,
      () => {
        if (!ibm || !ibmView) return 'no bind-matrix buffer view to change';
        const [target, key, values] = r.pick<[Obj, string, unknown[]]>([
          [ibmView, 'byteOffset', [-4, -64, 1e9, 2 ** 32, 0.5, 3, '8', null]],
          [ibmView, 'byteLength', [0, -1, 63, 1e9, 2 ** 53, 0.5]],
          [ibmView, 'byteStride', [0, 4, 63, 65, 1e9, -64, 0.5]],
          [ibm, 'byteOffset', [-64, -1, 3, 1e9, 0.5, -0]],
          [ibmView, 'buffer', [7, -1, 0.5, null]],
        ]);
        const v = r.pick(values);
        target[key] = v;
        return `bind-matrix ${target === ibm ? 'accessor' : 'buffer view'} ${key} = ${show(v)}`;
      },
    ],
    [
      2,
      () => {
        const buffers = Array.isArray(json.buffers) ? (json.buffers as Obj[]) : [];
        if (!isObj(buffers[0])) return 'no buffer to change';
        const v = r.pick<unknown>([0, -1, 1e9, 2 ** 53, 0.5]);
        buffers[0].byteLength = v;
        return `buffers[0].byteLength = ${show(v)}`;
      },
    ],
    [
      3,
      () => {
        const [key, v] = r.pick<[string, unknown]>([
          ['scale', [0, 0, 0]],
          ['scale', [1e-300, 1e-300, 1e-300]],
          ['scale', [1e300, 1e300, 1e300]],
          ['scale', [-1, 1, 1]],
          ['rotation', [0, 0, 0, 0]],
          ['rotation', [1e300, 0, 0, 0]],
          ['rotation', [2, 0, 0, 0]],
          ['rotation', [0, 0, 0]],
          ['translation', [1e308, 1e308, 1e308]],
          ['translation', [1e200, 0, 0]],
          ['matrix', [1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]],
          ['matrix', Array(16).fill(0)],
          ['matrix', Array(16).fill(1e300)],
        ]);
        delete node.matrix;
        node[key] = v;
        return `${at}.${key} = ${show(v)}`;
      },
    ],
    [
      2,
      () => {
        if (!ibm) return 'no bind-matrix accessor to change';
        const [key, v] = r.pick<[string, unknown]>([
          ['type', 'VEC4'],
          ['componentType', 5123],
          ['sparse', { count: 1 }],
          ['bufferView', undefined],
          ['normalized', true],
        ]);
        if (v === undefined) delete ibm[key];
        else ibm[key] = v;
        return `bind-matrix accessor ${key} = ${show(v)}`;
      },
    ],
    [
      2,
      () => {
        const v = r.pick<unknown>([[], [js[0], js[0]], [1e9], [1.5], ['0'], [...nodes.keys()], js.slice(0, 1)]);
        skin.joints = v;
        return `skins[0].joints = ${show(v)}`;
      },
    ],
    [
      1,
      () => {
        const v = r.pick<unknown>(['1.0', '3.0', 2, undefined]);
        json.asset = v === undefined ? undefined : { version: v };
        return `asset.version = ${show(v)}`;
      },
    ],
    [
      1,
      () => {
        json.extensionsRequired = ['KHR_draco_mesh_compression', 'EXT_meshopt_compression'];
        return 'extensionsRequired = [draco, meshopt]';
      },
    ],
  ])();
}
