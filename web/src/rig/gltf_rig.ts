// glTF 2.0 skinned character -> RigSpec (rules and schema: docs/gltf-ik-extras.md).
// Every joint of every skin becomes one bone (a joint shared by several skins is one bone). The
// rest pose is the nodes' own transforms (the pose three.js shows the file in), so the model does
// not move at zero angles. Bones are ordered depth-first through the node tree (parents first).
import type { RigSpec } from '../ik/rig_spec.js';
import { boneRestFrame } from './bone_frame.js';
import { chooseChainChild } from './chain_child.js';
import { DEFAULT_LIMIT_DEG, effectorsByName, leafBones } from './effector_defaults.js';
import { BufferCache, readMat4Accessor } from './gltf_accessor.js';
import { failIn, parseGltfContainer, type SiblingReader } from './gltf_file.js';
import { nodeLabel, readNodes, readSkins, worldMatrices, type GltfNode } from './gltf_nodes.js';
import { readIkExtras, type IkExtras } from './ik_extras.js';
import { allFinite, invertAffine, multiply, transformDirection, transformPoint } from './mat4.js';

/** What the write-back and the page need to map rig bones onto the glTF (and three.js) nodes. */
export interface GltfRigInfo {
  /** glTF node index of each bone. */
  boneNodes: Int32Array;
  /** glTF node name of each bone ('' when the node has none). */
  nodeNames: string[];
  /** Each joint's rest world matrix in glTF scene space, 16 per bone, row-major, with its scale. */
  restWorld: Float64Array;
  /** Each joint's rest local matrix (relative to its glTF parent node), 16 per bone, row-major. */
  restLocal: Float64Array;
  /** Each bone's tip in its joint node's local coordinates, 3 per bone. */
  tailLocal: Float64Array;
  /** Per glTF skin, the bone index of each of its joints (skin order). */
  skinBones: Int32Array[];
  /** True when at least one joint carries `extras.ik`. */
  hasIkExtras: boolean;
  /** Things the user may want to know (defaults used, pose differs from bind pose...). */
  warnings: string[];
}

export interface GltfRig {
  spec: RigSpec;
  gltf: GltfRigInfo;
}

type Vec3 = [number, number, number];

const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const norm = (a: Vec3): number => Math.hypot(a[0], a[1], a[2]);

/**
 * Imports the skeleton of a .glb or .gltf. `file` names the source in errors; `readSibling`
 * reads side buffers of a .gltf (URI-decoded relative path). Throws RigFormatError for a malformed
 * file (truncated GLB, bad JSON, no skin, node cycle, missing buffer, non-finite matrix...).
 * Lengths and positions are in glTF scene units; limits in degrees.
 */
export async function importGltfRig(bytes: Uint8Array, file: string, readSibling?: SiblingReader): Promise<GltfRig> {
  const container = parseGltfContainer(bytes, file);
  const json = container.json;
  const nodes = readNodes(json, file);
  const skins = readSkins(json, nodes.length, file);
  if (skins.length === 0) failIn(file, 'no skin: the file has no skinned character (glTF "skins" is empty or missing)');

  // Joints, depth-first through the node tree so that parents come before children.
  const isJoint = new Set(skins.flatMap((s) => s.joints));
  const order: GltfNode[] = [];
  const visit = (n: GltfNode): void => {
    if (isJoint.has(n.index)) order.push(n);
    n.children.forEach((c) => visit(nodes[c]));
  };
  nodes.filter((n) => n.parent === -1).forEach(visit);
  const boneOfNode = new Map(order.map((n, b) => [n.index, b]));
  const count = order.length;

  const world = worldMatrices(nodes);
  const parents = new Int32Array(count).fill(-1);
  const depth = new Int32Array(count);
  order.forEach((n, b) => {
    for (let a = n.parent; a !== -1; a = nodes[a].parent) {
      const pb = boneOfNode.get(a);
      if (pb !== undefined) {
        parents[b] = pb;
        depth[b] = depth[pb] + 1;
        break;
      }
    }
    if (!allFinite(world[n.index])) failIn(file, `${nodeLabel(n)}: world matrix has a non-finite entry`);
    if (invertAffine(world[n.index]) === null) failIn(file, `${nodeLabel(n)}: world matrix is singular (a zero scale?)`);
  });
  const extras: (IkExtras | undefined)[] = order.map((n) => readIkExtras(n.extras, nodeLabel(n), file));
  const children: number[][] = order.map(() => []);
  parents.forEach((p, b) => p >= 0 && children[p].push(b));
  const descendants = new Int32Array(count);
  for (let b = count - 1; b >= 0; b--) if (parents[b] >= 0) descendants[parents[b]] += descendants[b] + 1;

  const origin = (b: number): Vec3 => {
    const m = world[order[b].index];
    return [m[3], m[7], m[11]];
  };
  let lo: Vec3 = [Infinity, Infinity, Infinity], hi: Vec3 = [-Infinity, -Infinity, -Infinity];
  for (let b = 0; b < count; b++) {
    const p = origin(b);
    lo = lo.map((v, k) => Math.min(v, p[k])) as Vec3;
    hi = hi.map((v, k) => Math.max(v, p[k])) as Vec3;
  }
  const eps = 1e-9 * (norm(sub(hi, lo)) || 1);

  const spec: RigSpec = {
    names: order.map((n) => n.name || `node ${n.index}`),
    parents,
    rest: new Float64Array(16 * count),
    lengths: new Float64Array(count),
    lower: new Float64Array(3 * count),
    upper: new Float64Array(3 * count),
    effectors: new Int32Array(0),
  };
  const info: GltfRigInfo = {
    boneNodes: Int32Array.from(order, (n) => n.index),
    nodeNames: order.map((n) => n.name),
    restWorld: new Float64Array(16 * count),
    restLocal: new Float64Array(16 * count),
    tailLocal: new Float64Array(3 * count),
    skinBones: skins.map((s) => Int32Array.from(s.joints, (j) => boneOfNode.get(j) ?? -1)),
    hasIkExtras: extras.some((e) => e !== undefined),
    warnings: [],
  };

  order.forEach((node, b) => {
    const W = world[node.index];
    const ex = extras[b];
    const p = origin(b);
    // Scale of W along a local direction u: how long one local unit along u is in the world.
    const worldLength = (localLength: number, u: Vec3): number => localLength * norm(transformDirection(W, u)) / norm(u);
    let dir: Vec3 = transformDirection(W, [0, 1, 0]); // local +Y: the bone axis of Blender and Mixamo
    let length: number;
    if (ex?.tail) {
      const d = sub(transformPoint(W, ex.tail), p);
      length = norm(d);
      if (length > eps) dir = d;
      else length = 0;
    } else {
      const child = pickChild(b, ex);
      if (child !== undefined) {
        dir = sub(origin(child), p);
        length = norm(dir);
        if (ex?.length !== undefined) length = worldLength(ex.length, transformDirection(invertAffine(W)!, dir));
      } else if (ex?.length !== undefined) length = worldLength(ex.length, [0, 1, 0]);
      else length = parents[b] >= 0 ? 0.5 * spec.lengths[parents[b]] : 0;
    }
    const dn = norm(dir);
    const unit: Vec3 = [dir[0] / dn, dir[1] / dn, dir[2] / dn];
    spec.lengths[b] = length;
    spec.rest.set(boneRestFrame(W, unit), 16 * b);
    info.restWorld.set(W, 16 * b);
    info.restLocal.set(node.local, 16 * b);
    const tip: Vec3 = [p[0] + length * unit[0], p[1] + length * unit[1], p[2] + length * unit[2]];
    info.tailLocal.set(transformPoint(invertAffine(W)!, tip), 3 * b);
    for (let k = 0; k < 3; k++) {
      spec.lower[3 * b + k] = ex?.min?.[k] ?? -DEFAULT_LIMIT_DEG;
      spec.upper[3 * b + k] = ex?.max?.[k] ?? DEFAULT_LIMIT_DEG;
      if (spec.lower[3 * b + k] > spec.upper[3 * b + k])
        failIn(file, `${nodeLabel(node)}: extras.ik gives xzx_min[${k}] = ${spec.lower[3 * b + k]} above xzx_max[${k}] = ${spec.upper[3 * b + k]}`);
    }
  });

  function pickChild(b: number, ex: IkExtras | undefined): number | undefined {
    const kids = children[b];
    if (ex?.child !== undefined) {
      const want = ex.child;
      const found = kids.find((c) => (typeof want === 'number' ? order[c].index === want : order[c].name === want));
      if (found === undefined) failIn(file, `${nodeLabel(order[b])}: extras.ik.child ${JSON.stringify(want)} is not one of its child joints`);
      return norm(sub(origin(found), origin(b))) > eps ? found : undefined;
    }
    const candidates = kids
      .filter((c) => norm(sub(origin(c), origin(b))) > eps)
      .map((c) => ({ bone: c, name: order[c].name, descendants: descendants[c] }));
    return candidates.length ? chooseChainChild(candidates).bone : undefined;
  }

  // End effectors: flagged in extras, else hands/feet/head by name, else every leaf.
  const flagged = extras.flatMap((e, b) => (e?.effector === true ? [b] : []));
  const unflagged = new Set(extras.flatMap((e, b) => (e?.effector === false ? [b] : [])));
  let effectors = flagged;
  if (effectors.length === 0) {
    const byName = effectorsByName(order.map((n, b) => ({ name: n.name, depth: depth[b] }))).filter((b) => !unflagged.has(b));
    effectors = byName.length ? byName : leafBones(parents).filter((b) => !unflagged.has(b));
    info.warnings.push(
      `no joint is flagged extras.ik.effector: end effectors are ${byName.length ? 'the hands, feet and head found by name' : 'all leaf joints'} (${effectors.map((b) => spec.names[b]).join(', ')})`,
    );
  }
  if (effectors.length === 0) failIn(file, 'no end effector: every joint is marked extras.ik.effector = false');
  spec.effectors = Int32Array.from(effectors);
  if (!info.hasIkExtras) info.warnings.push(`no IK extras: every angle is limited to +-${DEFAULT_LIMIT_DEG} degrees`);

  // Inverse bind matrices: read (so a missing buffer or NaN is an error) and compared with the pose.
  const buffers = new BufferCache(container, file, readSibling);
  for (const skin of skins) {
    if (skin.inverseBindMatrices === undefined) continue;
    const where = `skins[${skin.index}].inverseBindMatrices`;
    const ibm = await readMat4Accessor(json, buffers, skin.inverseBindMatrices, skin.joints.length, where, file);
    // In the bind pose, world(joint) * ibm(joint) is the same matrix (the mesh's bind space) for all joints.
    const first = multiply(world[skin.joints[0]], ibm.subarray(0, 16));
    const scale = Math.max(1, ...Array.from(first, Math.abs));
    const differs = skin.joints.some((j, k) => {
      const m = multiply(world[j], ibm.subarray(16 * k, 16 * k + 16));
      return m.some((v, i) => Math.abs(v - first[i]) > 1e-4 * scale);
    });
    if (differs)
      info.warnings.push(`skin ${skin.index}: the nodes are not in the bind pose; the rig's rest pose is the nodes' pose`);
  }
  return { spec, gltf: info };
}
