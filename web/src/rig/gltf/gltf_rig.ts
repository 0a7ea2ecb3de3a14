// glTF 2.0 skinned character -> RigSpec (rules and schema: docs/gltf-ik-extras.md).
// Every joint of every skin becomes one bone (a joint shared by several skins is one bone). The
// rest pose is the skins' bind pose (bind_pose.ts; the nodes' own transforms where a skin has no
// inverse bind matrices), and the nodes' pose, where it differs, the start angles: the model opens
// as the file shows it. Bones are ordered depth-first through the node tree (parents first).
// A humanoid skeleton is recognised (humanoid_recognition.ts) and gives the default end effectors.
import type { RigSpec } from '../../ik/rig_arrays.js';
import { restFromBindPose, startAngles } from './bind_pose.js';
import type { Vec3 } from '../anatomy/anatomy_vec.js';
import { boneAxis, jointOrigin, restJoints, type RestJoints } from './bone_axes.js';
import { boneRestFrame } from '../bone_frame.js';
import { DEFAULT_LIMIT_DEG, defaultEffectors, rootChainEffectors } from './effector_defaults.js';
import { checkGltfBudget } from './gltf_budget.js';
import { failIn } from '../rig_format_error.js';
import { parseGltfContainer, type GltfContainer, type SiblingReader } from './gltf_file.js';
import { listed, type JsonObject } from './gltf_json.js';
import { checkWorldMatrices, jointsInTreeOrder, readBindMatrices, type JointOrder } from './gltf_joints.js';
import { nodeLabel, readNodes, readSkins, worldMatrices, type GltfNode, type GltfSkin } from './gltf_nodes.js';
import { checkRanges } from './gltf_ranges.js';
import { checkReferences, readLists, type GltfLists } from './gltf_references.js';
import { humanoidLimits, type RigLimits } from '../humanoid/humanoid_limits.js';
import { recognizeHumanoid } from '../humanoid/humanoid_recognition.js';
import type { HumanoidMap } from '../humanoid/humanoid_roles.js';
import { readIkExtras, type IkExtras } from './ik_extras.js';
import { invertAffine, transformPoint, type Mat4 } from '../mat4.js';
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
  const { container, lists } = openGltf(bytes, file);
  const skins = readSkins(lists.skins, lists.nodes.length, file);
  const isJoint = skinJoints(skins, file);
  const tree = readNodes(lists.nodes, file);
  const joints = jointsInTreeOrder(tree, isJoint);
  const posed = worldMatrices(tree); // the nodes' own pose
  checkWorldMatrices(joints.order, posed, '', file);
  // The inverse bind matrices give the rest.
  const binds = await readBindMatrices(container, lists, skins, tree, file, readSibling);
  const restPose = restFromBindPose(tree, skins, binds, posed, isJoint);
  if (restPose.rebound.length) checkWorldMatrices(joints.order, restPose.world, 'bind pose ', file);
  const extras: (IkExtras | undefined)[] = joints.order.map((n) => readIkExtras(n.extras, nodeLabel(n), file));
  const skeleton = restJoints(joints.order, joints.parents, restPose.world);
  const { spec, gltf: info } = emptyRig(container.json, joints, skins, extras);
  // Parents first: a bone with no tail, child or length of its own takes half its parent's length.
  for (let b = 0; b < skeleton.order.length; b++) placeBone(skeleton, b, extras[b], restPose.local, spec, info, file);
  spec.effectors = chooseEffectors(extras, spec, info, file);
  humanoidAnatomy(extras, spec, info);
  if (!info.hasIkExtras) info.warnings.push(noExtrasWarning(info.humanoid));
  posedFile(restPose, posed, joints.boneOfNode, spec, info);
  return { spec, gltf: info };
}

/**
 * The container of `bytes` (.glb or .gltf) and its top-level lists, once the file is within
 * gltf_budget.ts, every index in it points at something, and every accessor range fits its buffer.
 */
function openGltf(bytes: Uint8Array, file: string): { container: GltfContainer; lists: GltfLists } {
  const container = parseGltfContainer(bytes, file);
  const json = container.json;
  checkGltfBudget(json, file);
  const lists = readLists(json, file);
  checkReferences(json, lists, file);
  checkRanges(container, lists, file);
  return { container, lists };
}

/** The joints (node indices) of all `skins`; throws when there is no skin or more joints than MAX_BONES. */
function skinJoints(skins: GltfSkin[], file: string): Set<number> {
  if (skins.length === 0) failIn(file, 'no skin: the file has no skinned character (glTF "skins" is empty or missing)');
  const isJoint = new Set(skins.flatMap((s) => s.joints));
  if (isJoint.size > MAX_BONES) failIn(file, `${isJoint.size} joints; at most ${MAX_BONES} bones`);
  return isJoint;
}

/**
 * A RigSpec and GltfRigInfo for the bones `joints.order`, named, with their parents, skins,
 * humanoid roles (recognised in `json`) and its notes, and whether any bone has `extras`; the
 * per-bone arrays are zero and there are no end effectors yet.
 */
function emptyRig(json: JsonObject, joints: JointOrder, skins: GltfSkin[], extras: (IkExtras | undefined)[]): GltfRig {
  const { order, parents, boneOfNode, nodeDepth } = joints;
  const count = order.length;
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
  return { spec, gltf: info };
}

/**
 * Bone `b` (extras.ik `ex`) into `spec` and `info`: its length (scene units) and rest frame, its
 * rest matrices and tip, and its limits (degrees). `restLocal` holds each node's rest local matrix
 * (by node index); the bone's parent must be placed already.
 */
function placeBone(
  joints: RestJoints,
  b: number,
  ex: IkExtras | undefined,
  restLocal: Mat4[],
  spec: RigSpec,
  info: GltfRigInfo,
  file: string,
): void {
  const node = joints.order[b];
  const W = joints.world[node.index];
  const p = jointOrigin(joints, b);
  const { unit, length } = boneAxis(joints, b, p, ex, spec.lengths, file);
  if (length > MAX_COORDINATE)
    failIn(file, `${nodeLabel(node)}: bone length ${length} is beyond ${MAX_COORDINATE} scene units`);
  spec.lengths[b] = length;
  spec.rest.set(boneRestFrame(W, unit), 16 * b);
  info.restWorld.set(W, 16 * b);
  info.restLocal.set(restLocal[node.index], 16 * b);
  const tip: Vec3 = [p[0] + length * unit[0], p[1] + length * unit[1], p[2] + length * unit[2]];
  info.tailLocal.set(transformPoint(invertAffine(W)!, tip), 3 * b);
  extrasLimits(ex, b, node, spec, file);
}

/** Bone `b`'s (joint `node`) limits from extras.ik `ex` into `spec` (degrees, +-DEFAULT_LIMIT_DEG where not given). */
function extrasLimits(ex: IkExtras | undefined, b: number, node: GltfNode, spec: RigSpec, file: string): void {
  for (let k = 0; k < 3; k++) {
    spec.lower[3 * b + k] = ex?.min?.[k] ?? -DEFAULT_LIMIT_DEG;
    spec.upper[3 * b + k] = ex?.max?.[k] ?? DEFAULT_LIMIT_DEG;
    if (spec.lower[3 * b + k] > spec.upper[3 * b + k])
      failIn(
        file,
        `${nodeLabel(node)}: extras.ik gives xzx_min[${k}] = ${spec.lower[3 * b + k]} above xzx_max[${k}] = ${spec.upper[3 * b + k]}`,
      );
  }
}

/**
 * A humanoid's anatomical limits (humanoid_limits.ts, degrees) on its mapped bones in `spec`, the
 * file's own kept as `info.fileLimits`. Limits given in extras.ik win; a rig that gives them for
 * every mapped bone, or is no humanoid, is left as it is.
 */
function humanoidAnatomy(extras: (IkExtras | undefined)[], spec: RigSpec, info: GltfRigInfo): void {
  const explicit = extras.map((e) => e?.min !== undefined || e?.max !== undefined);
  const mapped = info.humanoid ? Object.values(info.humanoid.bones) : [];
  if (info.humanoid && mapped.some((b) => !explicit[b])) {
    const anatomy = humanoidLimits(spec, info.humanoid, explicit);
    info.fileLimits = { lower: spec.lower, upper: spec.upper };
    spec.lower = anatomy.lower;
    spec.upper = anatomy.upper;
    info.warnings.push(...anatomy.notes);
  }
}

/** The warning for a file without extras.ik, which says the limits used (degrees) for a humanoid or not. */
function noExtrasWarning(humanoid: HumanoidMap | null): string {
  return humanoid
    ? `no IK extras: anatomical limits on the humanoid's bones, +-${DEFAULT_LIMIT_DEG} degrees on the others`
    : `no IK extras: every angle is limited to +-${DEFAULT_LIMIT_DEG} degrees`;
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
