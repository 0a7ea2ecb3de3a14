// glTF 2.0 skinned character -> RigSpec (rules and schema: docs/gltf-ik-extras.md).
// Every joint of every skin becomes one bone (a joint shared by several skins is one bone). The
// rest pose is the skins' bind pose (bind_pose.ts; the nodes' own transforms where a skin has no
// inverse bind matrices), and the nodes' pose, where it differs, the start angles: the model opens
// as the file shows it. Bones are ordered depth-first through the node tree (parents first).
// A humanoid skeleton is recognised (humanoid_recognition.ts) and gives the default end effectors.
import type { RigSpec } from '../../ik/rig_arrays.js';
import { restFromBindPose, startAngles } from './bind_pose.js';
import { boneRestFrame } from '../bone_frame.js';
import { chooseChainChild } from '../chain_child.js';
import { DEFAULT_LIMIT_DEG, defaultEffectors, rootChainEffectors } from './effector_defaults.js';
import { checkGltfBudget } from './gltf_budget.js';
import { failIn } from '../rig_format_error.js';
import { parseGltfContainer, type SiblingReader } from './gltf_file.js';
import { listed, shown } from './gltf_json.js';
import { checkWorldMatrices, jointsInTreeOrder, readBindMatrices } from './gltf_joints.js';
import { nodeLabel, readNodes, readSkins, worldMatrices } from './gltf_nodes.js';
import { checkRanges } from './gltf_ranges.js';
import { checkReferences, readLists } from './gltf_references.js';
import { humanoidLimits, type RigLimits } from '../humanoid/humanoid_limits.js';
import { recognizeHumanoid } from '../humanoid/humanoid_recognition.js';
import type { HumanoidMap } from '../humanoid/humanoid_roles.js';
import { readIkExtras, type IkExtras } from './ik_extras.js';
import { invertAffine, transformDirection, transformPoint, type Mat4 } from '../mat4.js';
import { effectorCountProblem, MAX_BONES, MAX_COORDINATE } from '../rig_limits.js';

/** What the write-back and the page need to map rig bones onto the glTF (and three.js) nodes. */
export interface GltfRigInfo {
  /** glTF node index of each bone. */
  boneNodes: Int32Array;
  /** glTF node name of each bone ('' when the node has none). */
  nodeNames: string[];
  /** Each joint's rest (bind pose) world matrix in glTF scene space, 16 per bone, row-major, with its scale. */
  restWorld: Float64Array;
  /** Each joint's rest (bind pose) local matrix (relative to its glTF parent node), 16 per bone, row-major. */
  restLocal: Float64Array;
  /**
   * The pose the file's nodes stand in, where it differs from the rest (the bind pose): XZX angles
   * from the rest, 3 per bone in degrees, within the spec's limits (the nearest angles within them
   * where the pose leaves them; `warnings` names those bones). Posing the rig at these angles puts
   * every joint where the file has it, so the model opens as saved, while the rest (angles 0, the
   * page's reset) is the bind pose. null when the nodes stand in the rest pose.
   */
  startAngles: Float64Array | null;
  /** Each bone's tip in its joint node's local coordinates, 3 per bone. */
  tailLocal: Float64Array;
  /** Per glTF skin, the bone index of each of its joints (skin order). */
  skinBones: Int32Array[];
  /** True when at least one joint carries `extras.ik`. */
  hasIkExtras: boolean;
  /** Levels of the glTF node tree: 1 when every node is a root. */
  treeDepth: number;
  /** Which bone plays which humanoid role (docs/gltf-ik-extras.md), or null for a rig that is no humanoid. */
  humanoid: HumanoidMap | null;
  /**
   * The file's own limits (extras.ik, else +-180), 3 per bone in degrees, when the spec carries
   * the humanoid's anatomical limits instead (humanoid_limits.ts); null otherwise.
   */
  fileLimits: RigLimits | null;
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
 * file (truncated GLB, bad JSON, no skin, node cycle, missing buffer, non-finite matrix, more
 * bones or end effectors than the core takes, more nodes, accessors or accessor bytes than
 * gltf_budget.ts and gltf_ranges.ts allow...), in time linear in the file's size; a file past
 * those caps is refused before anything is built from it. Lengths and positions are in glTF
 * scene units; limits in degrees.
 */
export async function importGltfRig(bytes: Uint8Array, file: string, readSibling?: SiblingReader): Promise<GltfRig> {
  const container = parseGltfContainer(bytes, file);
  const json = container.json;
  checkGltfBudget(json, file);
  const lists = readLists(json, file);
  checkReferences(json, lists, file);
  checkRanges(container, lists, file);
  const skins = readSkins(lists.skins, lists.nodes.length, file);
  if (skins.length === 0) failIn(file, 'no skin: the file has no skinned character (glTF "skins" is empty or missing)');
  const isJoint = new Set(skins.flatMap((s) => s.joints));
  if (isJoint.size > MAX_BONES) failIn(file, `${isJoint.size} joints; at most ${MAX_BONES} bones`);
  const tree = readNodes(lists.nodes, file);
  const { order, parents, boneOfNode, nodeDepth } = jointsInTreeOrder(tree, isJoint);
  const count = order.length;
  const posed = worldMatrices(tree); // the nodes' own pose
  checkWorldMatrices(order, posed, '', file);
  // The inverse bind matrices give the rest.
  const binds = await readBindMatrices(container, lists, skins, tree, file, readSibling);
  const restPose = restFromBindPose(tree, skins, binds, posed, isJoint);
  const world = restPose.world;
  if (restPose.rebound.length) checkWorldMatrices(order, world, 'bind pose ', file);
  const extras: (IkExtras | undefined)[] = order.map((n) => readIkExtras(n.extras, nodeLabel(n), file));
  const children: number[][] = order.map(() => []);
  parents.forEach((p, b) => p >= 0 && children[p].push(b));
  const descendants = new Int32Array(count);
  for (let b = count - 1; b >= 0; b--) if (parents[b] >= 0) descendants[parents[b]] += descendants[b] + 1;

  const origin = (b: number): Vec3 => {
    const m = world[order[b].index];
    return [m[3], m[7], m[11]];
  };
  let lo: Vec3 = [Infinity, Infinity, Infinity],
    hi: Vec3 = [-Infinity, -Infinity, -Infinity];
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
  const humanoid = recognizeHumanoid(
    json,
    order.map((n) => n.name),
    parents,
    boneOfNode,
  );
  const info: GltfRigInfo = {
    boneNodes: Int32Array.from(order, (n) => n.index),
    nodeNames: order.map((n) => n.name),
    restWorld: new Float64Array(16 * count),
    restLocal: new Float64Array(16 * count),
    tailLocal: new Float64Array(3 * count),
    skinBones: skins.map((s) => Int32Array.from(s.joints, (j) => boneOfNode[j])),
    hasIkExtras: extras.some((e) => e !== undefined),
    treeDepth: nodeDepth.reduce((a, b) => Math.max(a, b), 0),
    humanoid: humanoid.map,
    fileLimits: null,
    startAngles: null,
    warnings: [...humanoid.notes],
  };

  order.forEach((node, b) => {
    const W = world[node.index];
    const ex = extras[b];
    const p = origin(b);
    // Scale of W along a local direction u: how long one local unit along u is in the world.
    const worldLength = (localLength: number, u: Vec3): number =>
      (localLength * norm(transformDirection(W, u))) / norm(u);
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
    if (length > MAX_COORDINATE)
      failIn(file, `${nodeLabel(node)}: bone length ${length} is beyond ${MAX_COORDINATE} scene units`);
    const dn = norm(dir);
    const unit: Vec3 = [dir[0] / dn, dir[1] / dn, dir[2] / dn];
    spec.lengths[b] = length;
    spec.rest.set(boneRestFrame(W, unit), 16 * b);
    info.restWorld.set(W, 16 * b);
    info.restLocal.set(restPose.local[node.index], 16 * b);
    const tip: Vec3 = [p[0] + length * unit[0], p[1] + length * unit[1], p[2] + length * unit[2]];
    info.tailLocal.set(transformPoint(invertAffine(W)!, tip), 3 * b);
    for (let k = 0; k < 3; k++) {
      spec.lower[3 * b + k] = ex?.min?.[k] ?? -DEFAULT_LIMIT_DEG;
      spec.upper[3 * b + k] = ex?.max?.[k] ?? DEFAULT_LIMIT_DEG;
      if (spec.lower[3 * b + k] > spec.upper[3 * b + k])
        failIn(
          file,
          `${nodeLabel(node)}: extras.ik gives xzx_min[${k}] = ${spec.lower[3 * b + k]} above xzx_max[${k}] = ${spec.upper[3 * b + k]}`,
        );
    }
  });

  function pickChild(b: number, ex: IkExtras | undefined): number | undefined {
    const kids = children[b];
    if (ex?.child !== undefined) {
      const want = ex.child;
      const found = kids.find((c) => (typeof want === 'number' ? order[c].index === want : order[c].name === want));
      if (found === undefined)
        failIn(file, `${nodeLabel(order[b])}: extras.ik.child ${shown(want)} is not one of its child joints`);
      return norm(sub(origin(found), origin(b))) > eps ? found : undefined;
    }
    const candidates = kids
      .filter((c) => norm(sub(origin(c), origin(b))) > eps)
      .map((c) => ({ bone: c, name: order[c].name, descendants: descendants[c] }));
    return candidates.length ? chooseChainChild(candidates).bone : undefined;
  }

  spec.effectors = chooseEffectors(extras, spec, info, file);
  // A humanoid gets anatomical limits on its mapped bones (limits given in extras.ik win; a rig
  // that gives them for every mapped bone is left as it is).
  const explicit = extras.map((e) => e?.min !== undefined || e?.max !== undefined);
  const mapped = info.humanoid ? Object.values(info.humanoid.bones) : [];
  if (info.humanoid && mapped.some((b) => !explicit[b])) {
    const anatomy = humanoidLimits(spec, info.humanoid, explicit);
    info.fileLimits = { lower: spec.lower, upper: spec.upper };
    spec.lower = anatomy.lower;
    spec.upper = anatomy.upper;
    info.warnings.push(...anatomy.notes);
  }

  if (!info.hasIkExtras)
    info.warnings.push(
      info.humanoid
        ? `no IK extras: anatomical limits on the humanoid's bones, +-${DEFAULT_LIMIT_DEG} degrees on the others`
        : `no IK extras: every angle is limited to +-${DEFAULT_LIMIT_DEG} degrees`,
    );

  posedFile(restPose, posed, boneOfNode, spec, info);
  return { spec, gltf: info };
}

/**
 * The end effectors (bone indices): the joints flagged in extras.ik, else the humanoid's hands,
 * feet and head or those found by name, else the deepest leaf joints (effector_defaults.ts);
 * never one marked extras.ik.effector = false. Says which in `info.warnings`, and which ones the
 * root bone alone moves. Throws RigFormatError for none at all or more than the core takes.
 */
function chooseEffectors(extras: (IkExtras | undefined)[], spec: RigSpec, info: GltfRigInfo, file: string): Int32Array {
  const parents = spec.parents;
  const flagged = extras.flatMap((e, b) => (e?.effector === true ? [b] : []));
  const unflagged = new Set(extras.flatMap((e, b) => (e?.effector === false ? [b] : [])));
  let effectors = flagged;
  if (effectors.length === 0) {
    const chosen = defaultEffectors(info.nodeNames, parents, info.humanoid, unflagged);
    effectors = chosen.effectors;
    info.warnings.push(
      `no joint is flagged extras.ik.effector: end effectors are ${chosen.which} (${listed(effectors.map((b) => spec.names[b]))})`,
    );
  }
  if (effectors.length === 0) failIn(file, 'no end effector: every joint is marked extras.ik.effector = false');
  const tooMany = effectorCountProblem(effectors.length, parents.length);
  if (tooMany) failIn(file, `too many end effectors flagged in extras.ik: ${tooMany}`);
  const offRoot = rootChainEffectors(effectors, parents).map((b) => spec.names[b]);
  if (offRoot.length)
    info.warnings.push(
      grouped('end effector', offRoot, 'moved by the root bone alone, so dragging swings the whole body'),
    );
  return Int32Array.from(effectors);
}

/**
 * Which pose is the rest (`restPose`, bind_pose.ts), said in `info.warnings` where it is not the
 * bind pose, and the file's pose (`posed`: the nodes' world matrices) as `info.startAngles` where
 * it differs from the rest.
 */
function posedFile(
  restPose: ReturnType<typeof restFromBindPose>,
  posed: Mat4[],
  boneOfNode: Int32Array,
  spec: RigSpec,
  info: GltfRigInfo,
): void {
  // Which pose is the rest, and the file's pose as start angles where it differs from the rest.
  const skinList = (list: number[]): string[] => list.map(String);
  if (restPose.unbound.length)
    info.warnings.push(
      grouped('skin', skinList(restPose.unbound), "no inverse bind matrices, so the nodes' pose is the rest"),
    );
  if (restPose.unusable.length)
    info.warnings.push(
      grouped(
        'skin',
        skinList(restPose.unusable),
        "the nodes are not in the bind pose; the rig's rest pose is the nodes' pose",
      ),
    );
  if (restPose.rebound.length) {
    const start = startAngles(spec, info.boneNodes, restPose.world, posed);
    info.startAngles = start.angles;
    const moved = restPose.rebound.map((n) => spec.names[boneOfNode[n]]);
    const at = moved.length === 1 ? 'joint' : `${moved.length} joints`;
    info.warnings.push(
      `the file's pose differs from the bind pose (${at}: ${listed(moved)}): opened posed, the rest is the bind pose`,
    );
    if (start.clamped.length)
      info.warnings.push(
        grouped(
          'bone',
          start.clamped.map((b) => spec.names[b]),
          'posed past its limits in the file: opened at the nearest angles within them',
        ),
      );
  }
}

/** One warning line about one or several things: "skin 2: text", or "4 skins (0, 1, 2, 3): text". */
function grouped(noun: string, items: string[], text: string): string {
  return items.length === 1 ? `${noun} ${items[0]}: ${text}` : `${items.length} ${noun}s (${listed(items)}): ${text}`;
}
