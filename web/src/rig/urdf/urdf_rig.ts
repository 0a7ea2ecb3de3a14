// A URDF robot's serial chain as a RigSpec (docs/urdf.md). The chain runs from a BASE link down
// to a TIP link (options.chain "BASE:TIP", default the longest serial chain); everything else in
// the file is ignored. The BASE link's frame is the rig's world. Along the chain:
//   - a revolute joint is one bone whose rest frame sits at the joint's origin with its x axis on
//     the joint's axis (the y and z axes complete it: any completion gives the same motion), so
//     its first XZX angle a0 is the joint angle q in degrees, within the URDF limits; a1 and a2
//     are locked (lower = upper = 0);
//   - a continuous joint is the same with a0 in -180..180: the core's angles are bounded, and one
//     full turn reaches every orientation of the joint (a solve does not wrap from +180 to -180);
//   - fixed joints fold into the rest frames of the bones after them;
//   - the TIP link is one more bone (named after it; "TIP (link)" if a joint has its name) with all three angles locked, whose rest frame is the TIP
//     link's own frame at the zero pose and whose length is 0: its tip is the TIP link's origin,
//     and its bone frame (tipRotations, orientation goals) is the TIP link's frame, x y z as in
//     the URDF (the offset from the link frame is the identity). It is the one end effector.
// So bone k < joints.length has a0 = q_k (degrees) and every other angle stays 0, and the pose of
// the rig at those angles is the URDF's forward kinematics from BASE to TIP.
// A joint bone's length is the distance from its joint to the next bone's origin (the next joint,
// or the TIP link's origin): its tip then lies on the joint's axis, which is drawn, and the
// lengths along the chain add up to the arm's reach (the core's length scale: goals.h rig_reach).
// Prismatic, planar, floating and mimic joints inside the chain are refused by name; the default
// chain avoids them.
import type { RigSpec } from '../../ik/rig_arrays.js';
import { failIn } from '../rig_format_error.js';
import { limitProblem } from '../limit_degrees.js';
import { identity, multiply, type Mat4 } from '../mat4.js';
import { MAX_BONES, MAX_COORDINATE } from '../rig_limits.js';
import { readJointGeometry, type JointGeometry, type UrdfJoint, type UrdfModel } from './urdf_model.js';

/** What the URDF importer chose, beside the spec. */
export interface UrdfRigInfo {
  robot: string;
  /** The chain's BASE and TIP link names. */
  base: string;
  tip: string;
  /** The chain's revolute and continuous joints, bone k moving joint k by its a0 (degrees). */
  joints: string[];
  /** Every joint from BASE to TIP, fixed ones included, parents first. */
  path: string[];
  /** The bone of the TIP link (the end effector): the last bone. */
  tipBone: number;
  warnings: string[];
}

const RAD_TO_DEG = 180 / Math.PI;

/** Joint types that move by one angle. */
const isRevolute = (j: UrdfJoint): boolean => j.type === 'revolute' || j.type === 'continuous';
/** Joints a chain may hold. */
const importable = (j: UrdfJoint): boolean => (isRevolute(j) || j.type === 'fixed') && !j.mimic;

/** The joints from link `base` down to link `tip` (indices, parents first), or null when `tip` is not below `base`. */
function pathDown(model: UrdfModel, base: number, tip: number): number[] | null {
  const path: number[] = [];
  for (let link = tip; link !== base; link = model.joints[model.parentJoint[link]].parent) {
    if (model.parentJoint[link] === -1) return null;
    path.push(model.parentJoint[link]);
  }
  return path.reverse();
}

/**
 * The longest serial chain made of revolute, continuous and fixed joints: the most revolute and
 * continuous joints, then the most joints, then the first in the file's link order. Its BASE is
 * as high as such joints reach (a link with no parent joint, or one whose parent joint is of
 * another type), its TIP a leaf of that subtree. Null when no such chain has a moving joint.
 */
function longestChain(model: UrdfModel): { base: number; tip: number; moving: number } | null {
  const n = model.links.length;
  // Best (moving joints, joints, tip) below each link, children before parents.
  const moving = new Int32Array(n),
    total = new Int32Array(n),
    leaf = Int32Array.from({ length: n }, (_, k) => k);
  const order: number[] = [];
  const stack = Array.from({ length: n }, (_, k) => n - 1 - k).filter((l) => model.parentJoint[l] === -1);
  while (stack.length) {
    const l = stack.pop()!;
    order.push(l);
    for (const j of model.childJoints[l]) stack.push(model.joints[j].child);
  }
  for (let k = order.length - 1; k >= 0; k--) {
    const l = order[k];
    for (const j of model.childJoints[l]) {
      const joint = model.joints[j];
      if (!importable(joint)) continue;
      const c = joint.child,
        m = moving[c] + (isRevolute(joint) ? 1 : 0),
        t = total[c] + 1;
      if (m > moving[l] || (m === moving[l] && t > total[l])) [moving[l], total[l], leaf[l]] = [m, t, leaf[c]];
    }
  }
  let best = -1;
  for (let l = 0; l < n; l++) {
    const up = model.parentJoint[l];
    if (up !== -1 && importable(model.joints[up])) continue; // not the top of its subtree
    if (best === -1 || moving[l] > moving[best] || (moving[l] === moving[best] && total[l] > total[best])) best = l;
  }
  return best === -1 || moving[best] === 0 ? null : { base: best, tip: leaf[best], moving: moving[best] };
}

/** The chain BASE:TIP of options.chain, or the longest one (with a warning saying which). */
function chooseChain(model: UrdfModel, chain: string | undefined, file: string, warnings: string[]): number[] {
  if (chain === undefined) {
    const found = longestChain(model);
    if (!found) failIn(file, 'the robot has no chain of revolute or continuous joints');
    const [base, tip] = [model.links[found.base], model.links[found.tip]];
    warnings.push(
      `no chain given: took the longest serial chain ${base}:${tip} (${found.moving} moving joints); choose another with --chain BASE:TIP`,
    );
    return pathDown(model, found.base, found.tip)!;
  }
  const parts = chain.split(':');
  if (parts.length !== 2 || !parts[0] || !parts[1])
    failIn(file, `the chain "${chain}" is not BASE:TIP (two link names)`);
  const index = (name: string, role: string): number => {
    const at = model.links.indexOf(name);
    if (at === -1) failIn(file, `the chain's ${role} link "${name}" is no <link> of the robot`);
    return at;
  };
  const base = index(parts[0], 'BASE'),
    tip = index(parts[1], 'TIP');
  if (base === tip) failIn(file, `the chain "${chain}" starts and ends at the same link`);
  const path = pathDown(model, base, tip);
  if (!path)
    failIn(file, `the chain "${chain}" is not serial: the link "${parts[1]}" does not hang below "${parts[0]}"`);
  return path;
}

/** The rotation of a URDF origin: Rz(yaw) Ry(pitch) Rx(roll), and its translation. */
function originMatrix(xyz: readonly number[], rpy: readonly number[]): Mat4 {
  const [cr, sr, cp, sp, cy, sy] = [
    Math.cos(rpy[0]),
    Math.sin(rpy[0]),
    Math.cos(rpy[1]),
    Math.sin(rpy[1]),
    Math.cos(rpy[2]),
    Math.sin(rpy[2]),
  ];
  return Float64Array.of(
    cy * cp,
    cy * sp * sr - sy * cr,
    cy * sp * cr + sy * sr,
    xyz[0],
    sy * cp,
    sy * sp * sr + cy * cr,
    sy * sp * cr - cy * sr,
    xyz[1],
    -sp,
    cp * sr,
    cp * cr,
    xyz[2],
    0,
    0,
    0,
    1,
  );
}

/** A rotation whose x axis is the unit vector `a`: y across it from the world axis least along it, z = x cross y. */
function axisFrame(a: readonly number[]): Mat4 {
  const k = [0, 1, 2].reduce((m, i) => (Math.abs(a[i]) < Math.abs(a[m]) ? i : m), 0);
  const e = [0, 0, 0];
  e[k] = 1;
  const y = [e[1] * a[2] - e[2] * a[1], e[2] * a[0] - e[0] * a[2], e[0] * a[1] - e[1] * a[0]]; // e x a
  const ny = Math.hypot(y[0], y[1], y[2]);
  const [y0, y1, y2] = [y[0] / ny, y[1] / ny, y[2] / ny];
  const z = [a[1] * y2 - a[2] * y1, a[2] * y0 - a[0] * y2, a[0] * y1 - a[1] * y0];
  return Float64Array.of(a[0], y0, z[0], 0, a[1], y1, z[1], 0, a[2], y2, z[2], 0, 0, 0, 0, 1);
}

const distance = (a: Mat4, b: Mat4): number => Math.hypot(a[3] - b[3], a[7] - b[7], a[11] - b[11]);

/**
 * The RigSpec of `model`'s chain (options.chain "BASE:TIP", else the longest serial one).
 * Throws RigFormatError naming `file` and the joint or link.
 */
export function urdfRigSpec(model: UrdfModel, file: string, chain?: string): { spec: RigSpec; urdf: UrdfRigInfo } {
  const warnings: string[] = [];
  const path = chooseChain(model, chain, file, warnings);
  const tip = model.links[model.joints[path[path.length - 1]].child];
  const base = model.links[model.joints[path[0]].parent];
  checkChainJoints(model, path, `${base}:${tip}`, file);
  const moving = movingJoints(model, path, `${base}:${tip}`, file);
  const spec = emptyChainSpec(moving.length + 1);
  const tipFrame = placeJointBones(model, path, spec, file);
  placeTipBone(spec, tip, tipFrame);
  setBoneLengths(spec);
  packageMeshWarning(model.meshes, warnings);
  return {
    spec,
    urdf: {
      robot: model.robot,
      base,
      tip,
      joints: moving.map((j) => model.joints[j].name),
      path: path.map((j) => model.joints[j].name),
      tipBone: spec.names.length - 1,
      warnings,
    },
  };
}

/** Checks that the joints of `path` (the chain `chainName`, "BASE:TIP") are importable: no mimic joint, no other type. */
function checkChainJoints(model: UrdfModel, path: number[], chainName: string, file: string): void {
  for (const j of path) {
    const joint = model.joints[j];
    if (joint.mimic)
      failIn(
        file,
        `joint "${joint.name}" (${joint.type}) mimics another joint and lies in the chain ${chainName}; mimic joints cannot be imported`,
      );
    if (!importable(joint))
      failIn(
        file,
        `joint "${joint.name}" is ${joint.type} and lies in the chain ${chainName}; only revolute, continuous and fixed joints can be imported`,
      );
  }
}

/** The revolute and continuous joints of `path` (the chain `chainName`): at least one, and fewer than MAX_BONES. */
function movingJoints(model: UrdfModel, path: number[], chainName: string, file: string): number[] {
  const moving = path.filter((j) => isRevolute(model.joints[j]));
  if (moving.length === 0) failIn(file, `the chain ${chainName} has no revolute or continuous joint`);
  if (moving.length + 1 > MAX_BONES)
    failIn(file, `the chain ${chainName} has ${moving.length} moving joints; the core takes at most ${MAX_BONES - 1}`);
  return moving;
}

/** A RigSpec of `n` bones in a row (each the child of the one before), the last the one end effector; no names yet, every number 0. */
function emptyChainSpec(n: number): RigSpec {
  return {
    names: [],
    parents: Int32Array.from({ length: n }, (_, k) => k - 1),
    rest: new Float64Array(16 * n),
    lengths: new Float64Array(n),
    lower: new Float64Array(3 * n),
    upper: new Float64Array(3 * n),
    effectors: Int32Array.of(n - 1),
  };
}

/**
 * Walks the chain `path` from BASE, adding to `spec` one bone per revolute or continuous joint:
 * its name, rest frame (at the joint's origin, x on its axis) and a0 limits in degrees. Returns
 * the TIP link's frame at the zero pose, in BASE's frame (URDF units, metres).
 */
function placeJointBones(model: UrdfModel, path: number[], spec: RigSpec, file: string): Mat4 {
  let link = identity(); // the current link's frame at the zero pose, in BASE's frame
  for (const j of path) {
    const joint = model.joints[j];
    const g = readJointGeometry(joint, file);
    link = multiply(link, originMatrix(g.xyz, g.rpy));
    checkWithinReach(link, `joint "${joint.name}"`, file);
    if (!isRevolute(joint)) continue;
    const k = spec.names.length;
    spec.names.push(joint.name);
    spec.rest.set(multiply(link, axisFrame(g.axis)), 16 * k);
    const [lo, hi] = jointLimits(joint, g, file);
    spec.lower[3 * k] = lo;
    spec.upper[3 * k] = hi;
  }
  return link;
}

/** Checks that the origin of frame `m` (`where` names it) lies within MAX_COORDINATE of the chain's base. */
function checkWithinReach(m: Mat4, where: string, file: string): void {
  if (Math.max(Math.abs(m[3]), Math.abs(m[7]), Math.abs(m[11])) > MAX_COORDINATE)
    failIn(file, `${where} lies beyond +-${MAX_COORDINATE} units from the chain's base`);
}

/**
 * The range of a0 for the moving `joint` (geometry `g`), degrees: its <limit> (radians) for a
 * revolute joint, which must have one; -180..180 for a continuous joint.
 */
function jointLimits(joint: UrdfJoint, g: JointGeometry, file: string): [number, number] {
  if (joint.type !== 'revolute') return [-180, 180];
  if (!g.limit) failIn(file, `joint "${joint.name}" is revolute but has no <limit> (URDF requires one)`);
  const [lo, hi] = [g.limit.lower * RAD_TO_DEG, g.limit.upper * RAD_TO_DEG];
  const problem = limitProblem(lo, 'min') ?? limitProblem(hi, 'max');
  if (problem) failIn(file, `joint "${joint.name}": its <limit> ${lo} .. ${hi} degrees: ${problem}`);
  return [lo, hi];
}

/** Names the last bone of `spec` after the TIP link `tip` and gives it the link's frame `link` (BASE's frame) as its rest. */
function placeTipBone(spec: RigSpec, tip: string, link: Mat4): void {
  // A name of its own, so that goals naming the bone find it (URDF joints and links may share names).
  spec.names.push(spec.names.includes(tip) ? `${tip} (link)` : tip);
  spec.rest.set(link, 16 * (spec.names.length - 1));
}

/** Sets each joint bone's length (metres): the distance from its rest origin to the next bone's. */
function setBoneLengths(spec: RigSpec): void {
  const n = spec.names.length;
  for (let k = 0; k + 1 < n; k++)
    spec.lengths[k] = distance(spec.rest.subarray(16 * k, 16 * k + 16), spec.rest.subarray(16 * k + 16, 16 * k + 32));
}

/** Adds to `warnings` a note on the package:// mesh files among `meshes`, when there are any: the rig reads none. */
function packageMeshWarning(meshes: string[], warnings: string[]): void {
  const packageMeshes = meshes.filter((m) => m.startsWith('package://')).length;
  if (packageMeshes > 0)
    warnings.push(
      `${packageMeshes} package:// mesh files not read: the rig needs none (a viewer without the ROS package draws the links as bones)`,
    );
}
