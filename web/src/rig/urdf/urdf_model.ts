// The kinematic tree of a URDF file: its links and joints, read with fast-xml-parser (the same
// reader in Node and the browser) under hostile-input caps, and checked as a tree. Only what the
// rig needs is read: link names, and per joint its name, type, parent and child links, and
// (parsed later, by readJointGeometry, only for the joints of the chosen chain) its origin, axis,
// limits and mimic. Meshes, inertia, transmissions and gazebo tags are skipped; mesh file names
// are collected so that the importer can say it did not read them.
//
// Caps: the text (MAX_URDF_BYTES), its tags (MAX_URDF_TAGS, counted before parsing, as
// json_budget.ts counts JSON values), the nesting (MAX_URDF_DEPTH, fast-xml-parser's
// maxNestedTags) and the links and joints (MAX_URDF_LINKS). Real robots are far inside them: the
// PR2's 133 KB file has 113 joints and nests 6 deep. Entities are not expanded (URDF has no use
// for them, and an entity bomb then costs nothing).
import { XMLParser, XMLValidator } from 'fast-xml-parser';

import { failIn } from '../rig_format_error.js';
import { cycleText, findCycle } from '../tree.js';

/** Largest URDF text read, bytes (16 MiB; the PR2's is 133 KB). */
export const MAX_URDF_BYTES = 16 * 1024 * 1024;

/** Most tags ("<" characters) in one file: each costs the parser a few hundred bytes. */
export const MAX_URDF_TAGS = 1_000_000;

/** Deepest nesting of elements accepted (a URDF nests about 6 deep). */
export const MAX_URDF_DEPTH = 64;

/** Most links, and most joints, of one robot (as many as glTF nodes: gltf_budget.ts). */
export const MAX_URDF_LINKS = 100_000;

/** A parsed XML element: attributes under '@', child elements by tag name, always lists. */
export interface XmlElement {
  '@'?: Record<string, string>;
  [tag: string]: unknown;
}

export type UrdfJointType = 'revolute' | 'continuous' | 'prismatic' | 'fixed' | 'floating' | 'planar';
const JOINT_TYPES: readonly string[] = ['revolute', 'continuous', 'prismatic', 'fixed', 'floating', 'planar'];

export interface UrdfJoint {
  name: string;
  type: UrdfJointType;
  /** Link indices. */
  parent: number;
  child: number;
  /** True when the joint has a <mimic>: it follows another joint. */
  mimic: boolean;
  /** The <joint> element, for readJointGeometry. */
  element: XmlElement;
}

export interface UrdfModel {
  robot: string;
  links: string[];
  joints: UrdfJoint[];
  /** Per link, the joint whose child it is, -1 for a root link. */
  parentJoint: Int32Array;
  /** Per link, the joints whose parent it is, in file order. */
  childJoints: number[][];
  /** Mesh file names of <visual> and <collision> geometry, as written. */
  meshes: string[];
}

/** The child elements of `e` named `tag` (an empty element without attributes parses as ''). */
export function children(e: XmlElement, tag: string): XmlElement[] {
  const list = e[tag];
  if (!Array.isArray(list)) return [];
  return list.map((c) => (typeof c === 'object' && c !== null ? (c as XmlElement) : {}));
}

/** Attribute `name` of `e`, or undefined. */
export function attribute(e: XmlElement, name: string): string | undefined {
  const attrs = e['@'];
  return attrs && Object.hasOwn(attrs, name) ? attrs[name] : undefined;
}

/** The number of "<" in `text`: at least the number of tags. */
function tagCount(text: string): number {
  let n = 0;
  for (let i = text.indexOf('<'); i !== -1; i = text.indexOf('<', i + 1)) n++;
  return n;
}

/** Parses the URDF `bytes` into its kinematic tree. Throws RigFormatError naming `file` and the element. */
export function parseUrdfModel(bytes: Uint8Array, file: string): UrdfModel {
  const robot = robotElement(parseXml(urdfText(bytes, file), file), file);
  const linkElements = children(robot, 'link');
  const jointElements = children(robot, 'joint');
  checkCounts(linkElements, jointElements, file);
  const { links, linkIndex, meshes } = readLinks(linkElements, file);
  const { joints, parentJoint, childJoints } = readJoints(jointElements, links, linkIndex, file);
  checkNoCycle(joints, parentJoint, links, file);
  return { robot: attribute(robot, 'name') ?? '', links, joints, parentJoint, childJoints, meshes };
}

/** The text of the URDF `bytes` (a byte-order mark dropped), once within MAX_URDF_BYTES and MAX_URDF_TAGS. */
function urdfText(bytes: Uint8Array, file: string): string {
  if (bytes.byteLength > MAX_URDF_BYTES)
    failIn(file, `${bytes.byteLength} bytes; a URDF file may have at most ${MAX_URDF_BYTES}`);
  const text = new TextDecoder().decode(bytes).replace(/^\ufeff/, '');
  const tags = tagCount(text);
  if (tags > MAX_URDF_TAGS)
    failIn(file, `more than ${MAX_URDF_TAGS} XML tags (${tags}); a URDF file may have at most ${MAX_URDF_TAGS}`);
  return text;
}

/** The XML document of `text`, checked to be well formed and to nest at most MAX_URDF_DEPTH deep. */
function parseXml(text: string, file: string): XmlElement {
  const valid = XMLValidator.validate(text);
  if (valid !== true) failIn(file, `bad XML at line ${valid.err.line}, column ${valid.err.col}: ${valid.err.msg}`);
  try {
    return new XMLParser({
      ignoreAttributes: false,
      attributeNamePrefix: '',
      attributesGroupName: '@',
      parseAttributeValue: false,
      parseTagValue: false,
      processEntities: false,
      isArray: (_tag, _path, _leaf, isAttribute) => !isAttribute,
      maxNestedTags: MAX_URDF_DEPTH,
    }).parse(text) as XmlElement;
  } catch (e) {
    const message = (e as Error).message;
    return failIn(
      file,
      /nested/i.test(message) ? `the XML nests deeper than ${MAX_URDF_DEPTH} elements` : `bad XML: ${message}`,
    );
  }
}

/** The one <robot> element of `doc`, its root. */
function robotElement(doc: XmlElement, file: string): XmlElement {
  const robots = children(doc, 'robot');
  if (robots.length !== 1) failIn(file, 'not a URDF file: its root element is not <robot>');
  return robots[0];
}

/** Checks that there are at most MAX_URDF_LINKS links and as many joints, and at least one link. */
function checkCounts(linkElements: XmlElement[], jointElements: XmlElement[], file: string): void {
  for (const [what, list] of [
    ['links', linkElements],
    ['joints', jointElements],
  ] as const)
    if (list.length > MAX_URDF_LINKS)
      failIn(file, `${list.length} ${what}; a URDF robot may have at most ${MAX_URDF_LINKS}`);
  if (linkElements.length === 0) failIn(file, 'the robot has no <link>');
}

/**
 * The name of element `e`, the `k`th <`tag`> (from 0): it must have one, and one that `earlier`
 * (the names of the <`tag`> elements before it) does not have.
 */
function uniqueName(
  e: XmlElement,
  tag: 'link' | 'joint',
  k: number,
  earlier: { has(name: string): boolean },
  file: string,
): string {
  const name = attribute(e, 'name');
  if (!name) failIn(file, `<${tag}> number ${k + 1} has no name`);
  if (earlier.has(name)) failIn(file, `two ${tag}s are named "${name}"`);
  return name;
}

/** The links' names (file order), the index of each name, and the mesh file names of their geometry. */
function readLinks(
  linkElements: XmlElement[],
  file: string,
): { links: string[]; linkIndex: Map<string, number>; meshes: string[] } {
  const links: string[] = [];
  const linkIndex = new Map<string, number>();
  const meshes: string[] = [];
  linkElements.forEach((e, k) => {
    const name = uniqueName(e, 'link', k, linkIndex, file);
    linkIndex.set(name, links.length);
    links.push(name);
    addMeshFiles(e, meshes);
  });
  return { links, linkIndex, meshes };
}

/** Adds to `meshes` the file name of every mesh of link `e`'s <visual> and <collision> geometry ('' when it has none). */
function addMeshFiles(e: XmlElement, meshes: string[]): void {
  for (const tag of ['visual', 'collision'])
    for (const shape of children(e, tag))
      for (const geometry of children(shape, 'geometry'))
        for (const mesh of children(geometry, 'mesh')) meshes.push(attribute(mesh, 'filename') ?? '');
}

/**
 * The joints (file order) between the `links` (`linkIndex` gives each name's index), and per link
 * the joint whose child it is (-1: none) and the joints whose parent it is. A link may be the
 * child of one joint only.
 */
function readJoints(
  jointElements: XmlElement[],
  links: string[],
  linkIndex: Map<string, number>,
  file: string,
): Pick<UrdfModel, 'joints' | 'parentJoint' | 'childJoints'> {
  const joints: UrdfJoint[] = [];
  const jointNames = new Set<string>();
  const parentJoint = new Int32Array(links.length).fill(-1);
  const childJoints: number[][] = links.map(() => []);
  jointElements.forEach((e, k) => {
    const name = uniqueName(e, 'joint', k, jointNames, file);
    jointNames.add(name);
    const joint = readJoint(e, name, links, linkIndex, file);
    const { parent, child } = joint;
    if (parentJoint[child] !== -1)
      failIn(
        file,
        `the link "${links[child]}" is the child of two joints, "${joints[parentJoint[child]].name}" and "${name}"`,
      );
    parentJoint[child] = joints.length;
    childJoints[parent].push(joints.length);
    joints.push(joint);
  });
  return { joints, parentJoint, childJoints };
}

/** The joint `e` called `name`: its type, and its parent and child links (indices into `links`, two different ones). */
function readJoint(
  e: XmlElement,
  name: string,
  links: string[],
  linkIndex: Map<string, number>,
  file: string,
): UrdfJoint {
  const where = `joint "${name}"`;
  const type = attribute(e, 'type');
  if (type === undefined) failIn(file, `${where} has no type`);
  if (!JOINT_TYPES.includes(type))
    failIn(file, `${where} has the unknown type "${type}" (URDF has ${JOINT_TYPES.join(', ')})`);
  const parent = jointEnd(e, 'parent', where, linkIndex, file),
    child = jointEnd(e, 'child', where, linkIndex, file);
  if (parent === child) failIn(file, `${where} joins the link "${links[child]}" to itself`);
  return {
    name,
    type: type as UrdfJointType,
    parent,
    child,
    mimic: children(e, 'mimic').length > 0,
    element: e,
  };
}

/** The link index (in `linkIndex`) of joint `e`'s one <parent> or <child> (`tag`). `where` names the joint. */
function jointEnd(
  e: XmlElement,
  tag: 'parent' | 'child',
  where: string,
  linkIndex: Map<string, number>,
  file: string,
): number {
  const list = children(e, tag);
  if (list.length !== 1)
    failIn(
      file,
      `${where} has ${list.length === 0 ? 'no' : list.length} <${tag}> link${list.length > 1 ? 's' : ''}; it needs one`,
    );
  const link = attribute(list[0], 'link');
  if (!link) failIn(file, `${where}: its <${tag}> has no link attribute`);
  const at = linkIndex.get(link);
  if (at === undefined) failIn(file, `${where}: its ${tag} link "${link}" is no <link> of the robot`);
  return at;
}

/** Checks that the `joints` (`parentJoint`: per link, the joint whose child it is) join the `links` in no cycle. */
function checkNoCycle(joints: UrdfJoint[], parentJoint: Int32Array, links: string[], file: string): void {
  const parentLink = Int32Array.from(parentJoint, (j) => (j === -1 ? -1 : joints[j].parent));
  const cycle = findCycle(parentLink);
  if (cycle) failIn(file, `the joints form a cycle of links: ${cycleText(cycle, (l) => `"${links[l]}"`)}`);
}

/** The mesh formats the page draws (web/src/view/urdf_mesh.ts: urdf-loader's STL and Collada loaders). */
export const URDF_MESH_FORMATS = /\.(stl|dae)$/i;

/** What the rig needs of one joint, in URDF units (metres, radians). */
export interface JointGeometry {
  /** <origin xyz> and <origin rpy> (fixed-axis roll about x, pitch about y, yaw about z). */
  xyz: [number, number, number];
  rpy: [number, number, number];
  /** <axis xyz> as a unit vector (URDF's default is 1 0 0); read for revolute and continuous joints only (a fixed joint's may be 0 0 0). */
  axis: [number, number, number];
  /**
   * <limit lower upper>, radians, narrowed to <safety_controller soft_lower_limit soft_upper_limit>
   * where those are given (the range a controller keeps the joint in, as MoveIt and TRAC-IK read
   * it); undefined without a <limit>.
   */
  limit?: { lower: number; upper: number };
}

/** A number: optional sign, digits with an optional fraction, an optional exponent. */
const NUMBER = /^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/;

/** Reads the origin, axis and limit of `joint`. Throws RigFormatError naming `file`, the joint and the attribute. */
export function readJointGeometry(joint: UrdfJoint, file: string): JointGeometry {
  const where = `joint "${joint.name}"`;
  const origin = onlyChild(joint, 'origin', where, file);
  const axisElement = onlyChild(joint, 'axis', where, file);
  const axis =
    joint.type === 'revolute' || joint.type === 'continuous'
      ? readTriple(axisElement, 'axis', 'xyz', [1, 0, 0], where, file)
      : [1, 0, 0];
  const norm = Math.hypot(axis[0], axis[1], axis[2]);
  if (!(norm > 1e-12)) failIn(file, `${where}: its <axis xyz="${attribute(axisElement!, 'xyz')}"> has zero length`);
  const geometry: JointGeometry = {
    xyz: readTriple(origin, 'origin', 'xyz', [0, 0, 0], where, file),
    rpy: readTriple(origin, 'origin', 'rpy', [0, 0, 0], where, file),
    axis: axis.map((v) => v / norm) as [number, number, number],
  };
  const limit = onlyChild(joint, 'limit', where, file);
  if (limit) geometry.limit = readLimit(joint, limit, where, file);
  return geometry;
}

/** The number `text`, attribute `at` of the joint `where` names; it must be finite. */
function urdfNumber(text: string, at: string, where: string, file: string): number {
  const x = NUMBER.test(text) ? Number(text) : NaN;
  if (!Number.isFinite(x)) failIn(file, `${where}: ${at} = "${text}" is not a finite number`);
  return x;
}

/** The one child element `tag` of `joint` (`where` names it), or undefined when it has none. */
function onlyChild(joint: UrdfJoint, tag: string, where: string, file: string): XmlElement | undefined {
  const list = children(joint.element, tag);
  if (list.length > 1) failIn(file, `${where} has ${list.length} <${tag}> elements; at most one`);
  return list[0];
}

/** The 3 numbers of attribute `name` of element `e` (a <`tag`> of the joint `where` names), or `missing` when not given. */
function readTriple(
  e: XmlElement | undefined,
  tag: string,
  name: string,
  missing: [number, number, number],
  where: string,
  file: string,
): [number, number, number] {
  const text = e && attribute(e, name);
  if (text === undefined) return missing;
  const parts = text.trim().split(/\s+/);
  if (parts.length !== 3) failIn(file, `${where}: <${tag} ${name}="${text}"> must hold 3 numbers`);
  return parts.map((p) => urdfNumber(p, `<${tag} ${name}>`, where, file)) as [number, number, number];
}

/**
 * The range of `joint` (`where` names it), radians: its <limit> element `limit` (a missing side is
 * URDF's default 0), narrowed to its <safety_controller> soft limits where given.
 */
function readLimit(joint: UrdfJoint, limit: XmlElement, where: string, file: string): { lower: number; upper: number } {
  const side = (name: string): number => {
    const text = attribute(limit, name);
    return text === undefined ? 0 : urdfNumber(text, `<limit ${name}>`, where, file); // URDF's default is 0
  };
  let lower = side('lower'),
    upper = side('upper');
  if (lower > upper) failIn(file, `${where}: <limit lower="${lower}"> is above upper="${upper}"`);
  const safety = onlyChild(joint, 'safety_controller', where, file);
  const soft = (name: string): number | undefined => {
    const text = safety && attribute(safety, name);
    return text === undefined ? undefined : urdfNumber(text, `<safety_controller ${name}>`, where, file);
  };
  const softLower = soft('soft_lower_limit'),
    softUpper = soft('soft_upper_limit');
  if (softLower !== undefined) lower = Math.max(lower, softLower);
  if (softUpper !== undefined) upper = Math.min(upper, softUpper);
  if (lower > upper)
    failIn(
      file,
      `${where}: its <safety_controller> soft limits leave no range within <limit> (${lower} > ${upper} radians)`,
    );
  return { lower, upper };
}
