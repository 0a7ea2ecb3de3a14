// The pose file: a rig's joint angles and end-effector targets as JSON, keyed by bone name so a
// pose survives a rig whose bones come in another order; a bone without a name of its own (none,
// or one another bone has) is keyed by its index, "#12" (pose_keys.ts).
//
//   {
//     "format": "ik-pose",
//     "version": 1,
//     "rig": "knight",
//     "bones": {
//       "thigh.L": [10, -5, 0],           <- XZX angles, degrees
//       ...
//     },
//     "root": [0, -0.2, 0.05],            <- a floating root's move, rig units (only for a rig whose hips float)
//     "effectors": [
//       { "bone": "hand.L", "target": [0.1, 1.2, 0.3], "orientation": [0, 0, 0, 1] },  <- rig units; unit quaternion (x, y, z, w), optional
//       ...
//     ]
//   }
//
// Reading checks everything and names the field of the first problem: unknown bones are an error,
// bones the file lacks get 0 (a warning), every angle is clamped into the rig's limits (a warning
// naming the bone when one changes; pose_clamp.ts). Writing refuses what reading would refuse (the checks are
// shared: pose_checks.ts). Numbers are written in JavaScript's shortest round-trip form, so a pose
// written and read back gives the same angles bit for bit.
import type { RigSpec } from '../ik/rig_arrays.js';
import { jsonBudgetProblem } from './json_budget.js';
import { effectorsProblem, numbersProblem, orientationProblem, shown, targetProblem } from './pose_checks.js';
import { clampAngles } from './pose_clamp.js';
import { poseBoneKeys } from './pose_keys.js';

/** The "format" of a pose file. */
export const POSE_FORMAT = 'ik-pose';
/** The version this module writes and reads. */
export const POSE_VERSION = 1;
/** Largest pose file read, characters (a pose of 16,384 bones is under 1 MB). */
export const MAX_POSE_CHARS = 8 * 1024 * 1024;
/** Bone names listed in one message before "and N more". */
const NAMES_SHOWN = 8;

/** A pose to write. */
export interface PoseInput {
  /** The rig's name (its file's base name), for the reader's information. */
  rigName: string;
  /** Every bone's name, in the order of `angles` ('' or a repeated name: the bone is keyed "#index"). */
  boneNames: readonly string[];
  /** XZX joint angles, 3 per bone, degrees. */
  angles: ArrayLike<number>;
  /** Bone index of each end effector. */
  effectors: ArrayLike<number>;
  /** Each effector's target position, 3 per effector, rig units. */
  targets: ArrayLike<number>;
  /** Per effector, an orientation goal as a unit quaternion (x, y, z, w), or null for none. */
  orientations?: readonly (ArrayLike<number> | null)[];
  /** A floating root's move (x, y, z, rig units), for a rig whose hips float; omitted: none. */
  root?: ArrayLike<number>;
}

/** A pose read for a given rig. */
export interface PoseRead {
  /** The rig name the file gives ('' when it gives none). */
  rigName: string;
  /** XZX angles, 3 per bone of the rig (rig order), degrees, within the limits (also those the file lacks). */
  angles: Float64Array;
  /** Bone index of each end effector. */
  effectors: number[];
  /** Target per effector, 3 each, rig units. */
  targets: Float64Array;
  /** Per effector, the orientation quaternion (x, y, z, w) or null. */
  orientations: (Float64Array | null)[];
  /** The floating root's move (x, y, z, rig units) the file gives, or null. */
  root: Float64Array | null;
  /** Things the user may want to know: bones the file lacks, clamped angles. */
  warnings: string[];
}

/** The rig's limits to clamp against (3 per bone, degrees); the spec's own by default. */
export interface PoseLimits {
  lower: ArrayLike<number>;
  upper: ArrayLike<number>;
}

export class PoseFormatError extends Error {
  override name = 'PoseFormatError';
}

const fail = (what: string): never => {
  throw new PoseFormatError(`pose file: ${what}`);
};

/** Throws a PoseFormatError for `problem`, when there is one. */
function failOn(problem: string | undefined): void {
  if (problem) fail(problem);
}

/** True when `v` is a JSON object (not null, not an array). */
const isJsonObject = (v: unknown): v is Record<string, unknown> =>
  typeof v === 'object' && v !== null && !Array.isArray(v);

/** The value of `key` in the JSON object `o`, undefined unless `o` has that key of its own ("__proto__" is no field). */
const ownField = (o: Record<string, unknown>, key: string): unknown => (Object.hasOwn(o, key) ? o[key] : undefined);

const listed = (names: readonly string[]): string => {
  const shownNames = names
    .slice(0, NAMES_SHOWN)
    .map((n) => JSON.stringify(n))
    .join(', ');
  return names.length > NAMES_SHOWN ? `${shownNames} and ${names.length - NAMES_SHOWN} more` : shownNames;
};

/** `v` as an array of `n` finite numbers, else a PoseFormatError naming `field`. */
function finiteArray(v: unknown, n: number, field: string, what: string): number[] {
  failOn(numbersProblem(v, n, field, what));
  return v as number[];
}

/** Finite numbers as a JSON array in their shortest round-trip form, -0 kept (JSON.stringify writes 0). */
const numberList = (a: readonly number[]): string =>
  `[${a.map((v) => (Object.is(v, -0) ? '-0' : String(v))).join(',')}]`;

/** Why a bone name the rig has is no key: the message's end. */
const KEYED_BY_INDEX =
  'which is not the key of one bone: a bone without a name of its own (none, or one another bone has) is keyed "#index"';

/**
 * Writes a pose as pose-file JSON text (format above): angles in degrees keyed by bone (pose_keys.ts),
 * targets in rig units, orientations as unit quaternions (x, y, z, w). Throws an Error naming the
 * field for input the reader would refuse: wrong lengths, non-finite numbers, an effector that is no
 * bone or is listed twice, more effectors than the core takes, a target beyond MAX_COORDINATE, a
 * non-unit orientation, more than MAX_POSE_CHARS of text.
 */
export function poseToJson(pose: PoseInput): string {
  const { rigName, boneNames, angles, effectors, targets, orientations, root } = pose;
  const check = (problem: string | undefined): void => {
    if (problem) throw new Error(`poseToJson: ${problem}`);
  };
  const n = boneNames.length;
  if (typeof rigName !== 'string') check('rigName is not a string');
  if (angles.length !== 3 * n) check(`angles has ${angles.length} values for ${n} bones (3 per bone)`);
  check(effectorsProblem(effectors.length, n));
  if (targets.length !== 3 * effectors.length)
    check(`targets has ${targets.length} values for ${effectors.length} effectors (3 per effector)`);
  if (orientations !== undefined && orientations.length !== effectors.length)
    check(`orientations has ${orientations.length} entries for ${effectors.length} effectors`);
  const keys = poseBoneKeys(boneNames);
  const row = (a: ArrayLike<number>, at: number, length: number): number[] =>
    Array.from({ length }, (_, k) => a[at + k]);
  const bones = keys.map((key, i) => {
    const a = row(angles, 3 * i, 3);
    check(numbersProblem(a, 3, `"bones"[${JSON.stringify(key)}]`, 'XZX angles in degrees'));
    return `    ${JSON.stringify(key)}: ${numberList(a)}`;
  });
  const listedBones = new Set<number>();
  const effectorLines = Array.from(effectors, (b, e) => {
    const at = `"effectors"[${e}]`;
    if (!Number.isInteger(b) || b < 0 || b >= n) check(`${at} is bone ${shown(b)}, not a bone index in 0..${n - 1}`);
    if (listedBones.has(b)) check(`${at}.bone ${JSON.stringify(keys[b])} is listed twice`);
    listedBones.add(b);
    const target = row(targets, 3 * e, 3);
    check(targetProblem(target, `${at}.target`));
    const q = orientations?.[e];
    const orientation = q === null || q === undefined ? undefined : row(q, 0, q.length);
    if (orientation) check(orientationProblem(orientation, `${at}.orientation`));
    const fields = [`"bone":${JSON.stringify(keys[b])}`, `"target":${numberList(target)}`];
    if (orientation) fields.push(`"orientation":${numberList(orientation)}`);
    return `    {${fields.join(',')}}`;
  });
  const rootLine: string[] = [];
  if (root !== undefined) {
    const r = row(root, 0, root.length);
    check(numbersProblem(r, 3, '"root"', "a floating root's move in rig units"));
    check(targetProblem(r, '"root"'));
    rootLine.push(`  "root": ${numberList(r)},`);
  }
  const block = (open: string, lines: string[], close: string): string =>
    lines.length ? `${open}\n${lines.join(',\n')}\n  ${close}` : `${open}${close}`;
  const text = [
    '{',
    `  "format": ${JSON.stringify(POSE_FORMAT)},`,
    `  "version": ${POSE_VERSION},`,
    `  "rig": ${JSON.stringify(rigName)},`,
    `  "bones": ${block('{', bones, '}')},`,
    ...rootLine,
    `  "effectors": ${block('[', effectorLines, ']')}`,
    '}',
    '',
  ].join('\n');
  if (text.length > MAX_POSE_CHARS)
    check(`${text.length} characters, more than a pose file holds (at most ${MAX_POSE_CHARS})`);
  return text;
}

/**
 * Reads pose-file JSON `text` for the rig `spec` (its `names` give the bones' keys, pose_keys.ts).
 * Every angle is clamped into `limits` (3 per bone, degrees; default the spec's lower/upper), with
 * a warning naming the bones whose angles changed; bones the file lacks get 0, clamped, with a
 * warning. Throws a PoseFormatError naming the field for anything malformed: more than
 * MAX_POSE_CHARS, not JSON, another format or version, a bone the rig lacks, wrong lengths,
 * non-finite numbers, an effector listed twice, a non-unit orientation, a target beyond
 * MAX_COORDINATE.
 */
export function poseFromJson(
  text: string,
  spec: Pick<RigSpec, 'names' | 'lower' | 'upper'>,
  limits?: PoseLimits,
): PoseRead {
  const doc = parsePoseText(text);
  const rigName = checkHeader(doc);
  const clampTo = limitsFor(spec, limits);
  const keys = readingKeys(spec.names);
  const given = readBoneAngles(ownField(doc, 'bones'), keys);
  const { angles, clamped } = clampAngles(given, keys.keys, clampTo);
  const warnings = angleWarnings(clamped, given, keys.keys);
  const root = readRootMove(ownField(doc, 'root'));
  const { effectors, targets, orientations } = readEffectors(ownField(doc, 'effectors'), keys);
  return { rigName, angles, effectors, targets, orientations, root, warnings };
}

/** The pose file's top-level JSON object, from `text` (a byte-order mark skipped) within MAX_POSE_CHARS and json_budget.ts. */
function parsePoseText(text: string): Record<string, unknown> {
  if (typeof text !== 'string') fail(`expected text, got ${shown(text)}`);
  if (text.length > MAX_POSE_CHARS)
    fail(
      `${(text.length / 1048576).toFixed(1)} MB of text, more than a pose file holds (at most ${MAX_POSE_CHARS / 1048576} MB)`,
    );
  failOn(jsonBudgetProblem(text));
  let doc: unknown;
  try {
    doc = JSON.parse(text.charCodeAt(0) === 0xfeff ? text.slice(1) : text);
  } catch (e) {
    return fail(`not JSON: ${(e as Error).message}`);
  }
  if (!isJsonObject(doc)) return fail(`the JSON is ${shown(doc)}, not an object`);
  return doc;
}

/** Checks the file's "format" and "version"; returns its "rig" name ('' when it gives none). */
function checkHeader(doc: Record<string, unknown>): string {
  const format = ownField(doc, 'format');
  if (format !== POSE_FORMAT) fail(`"format" is ${shown(format)}, expected "${POSE_FORMAT}"`);
  const version = ownField(doc, 'version');
  if (version !== POSE_VERSION) fail(`"version" is ${shown(version)}; this reader takes version ${POSE_VERSION}`);
  const rig = ownField(doc, 'rig');
  if (rig !== undefined && typeof rig !== 'string') fail(`"rig" is ${shown(rig)}, not a string`);
  return typeof rig === 'string' ? rig : '';
}

/**
 * The limits to clamp against, 3 per bone in degrees: `limits`, else the spec's own. Throws an
 * Error (the caller's fault, not the file's) when their lengths do not fit the spec's bones.
 */
function limitsFor(spec: Pick<RigSpec, 'names' | 'lower' | 'upper'>, limits: PoseLimits | undefined): PoseLimits {
  const n = spec.names.length;
  const lower = limits?.lower ?? spec.lower,
    upper = limits?.upper ?? spec.upper;
  if (lower.length !== 3 * n || upper.length !== 3 * n)
    throw new Error(`poseFromJson: limits have ${lower.length} and ${upper.length} values for ${n} bones (3 per bone)`);
  return { lower, upper };
}

/** How a file may name the bones of a rig, for reading. */
interface ReadingKeys {
  /** Each bone's key, rig order (pose_keys.ts). */
  keys: string[];
  /** The bone index of each key. */
  index: Map<string, number>;
  /** The rig's names that are not their bone's key: a file naming one is told to use "#index". */
  unusable: Set<string>;
}

/** The keys of the bones called `names` (rig order), with their indices and the names no key. */
function readingKeys(names: readonly string[]): ReadingKeys {
  const keys = poseBoneKeys(names);
  return {
    keys,
    index: new Map(keys.map((key, i) => [key, i])),
    unusable: new Set(names.filter((name, i) => keys[i] !== name)),
  };
}

/**
 * The file's "bones" (`bones`): per bone of the rig (rig order), the 3 XZX angles it gives in
 * degrees, unchecked against the limits, or undefined where it gives none. Throws a
 * PoseFormatError for a key that names no bone, then for angles that are not 3 finite numbers.
 */
function readBoneAngles(bones: unknown, keys: ReadingKeys): (number[] | undefined)[] {
  if (!isJsonObject(bones))
    return fail(`"bones" is ${shown(bones)}, not an object of bone name -> [3 angles in degrees]`);
  const entries = Object.entries(bones);
  const ambiguous = entries.filter(([key]) => !keys.index.has(key) && keys.unusable.has(key)).map(([key]) => key);
  if (ambiguous.length) fail(`"bones" names ${listed(ambiguous)}, ${KEYED_BY_INDEX}`);
  const unknown = entries.filter(([key]) => !keys.index.has(key)).map(([key]) => key);
  if (unknown.length) fail(`"bones" names ${unknown.length} bone(s) the rig lacks: ${listed(unknown)}`);
  const given = new Array<number[] | undefined>(keys.keys.length);
  for (const [key, value] of entries)
    given[keys.index.get(key)!] = finiteArray(value, 3, `"bones"[${JSON.stringify(key)}]`, 'XZX angles in degrees');
  return given;
}

/**
 * The warnings about the angles read: the bones whose angles were clamped (`clamped`, from
 * clampAngles), then the bones (`keys`, rig order) the file gives no angles for (`given` undefined).
 */
function angleWarnings(
  clamped: readonly string[],
  given: readonly (number[] | undefined)[],
  keys: readonly string[],
): string[] {
  const warnings: string[] = [];
  if (clamped.length)
    warnings.push(
      `angles outside the rig's limits were clamped for ${clamped.length} bone(s): ${clamped.slice(0, NAMES_SHOWN).join('; ')}${clamped.length > NAMES_SHOWN ? `; and ${clamped.length - NAMES_SHOWN} more` : ''}`,
    );
  const missing = keys.filter((_, i) => !given[i]);
  if (missing.length)
    warnings.push(
      `the pose gives no angles for ${missing.length} bone(s), set to 0 or the nearest limit: ${listed(missing)}`,
    );
  return warnings;
}

/** The file's "root" (`root`): a floating root's move (x, y, z, rig units), or null when it gives none. */
function readRootMove(root: unknown): Float64Array | null {
  if (root === undefined) return null;
  const r = finiteArray(root, 3, '"root"', "a floating root's move in rig units");
  failOn(targetProblem(r, '"root"'));
  return Float64Array.from(r);
}

/** The end effectors a pose file gives, in its order. */
type EffectorsRead = Pick<PoseRead, 'effectors' | 'targets' | 'orientations'>;

/** The file's "effectors" (`list`), each naming a bone by its key in `keys`. Throws a PoseFormatError naming the entry. */
function readEffectors(list: unknown, keys: ReadingKeys): EffectorsRead {
  if (!Array.isArray(list))
    return fail(`"effectors" is ${shown(list)}, not an array of { "bone", "target", "orientation"? }`);
  failOn(effectorsProblem(list.length, keys.keys.length));
  const read: EffectorsRead = { effectors: [], targets: new Float64Array(3 * list.length), orientations: [] };
  list.forEach((item: unknown, e) => {
    const { bone, target, orientation } = readEffector(item, `"effectors"[${e}]`, keys, read.effectors);
    read.orientations.push(orientation);
    read.effectors.push(bone);
    read.targets.set(target, 3 * e);
  });
  return read;
}

/**
 * One entry `item` of "effectors" (`at` names it): its bone index, not among `earlier`; its
 * target (3 numbers, rig units); its orientation quaternion (x, y, z, w) or null.
 */
function readEffector(
  item: unknown,
  at: string,
  keys: ReadingKeys,
  earlier: readonly number[],
): { bone: number; target: number[]; orientation: Float64Array | null } {
  if (!isJsonObject(item)) return fail(`${at} is ${shown(item)}, not an object`);
  const bone = effectorBone(ownField(item, 'bone'), at, keys, earlier);
  const target = ownField(item, 'target');
  failOn(targetProblem(target, `${at}.target`));
  const orientation = readOrientation(ownField(item, 'orientation'), `${at}.orientation`);
  return { bone, target: target as number[], orientation };
}

/** The bone index of an effector's "bone" `bone` (a key of `keys`), which no `earlier` effector has. */
function effectorBone(bone: unknown, at: string, keys: ReadingKeys, earlier: readonly number[]): number {
  if (typeof bone !== 'string') return fail(`${at}.bone is ${shown(bone)}, not a bone name`);
  const b = keys.index.get(bone);
  if (b === undefined && keys.unusable.has(bone)) fail(`${at}.bone ${JSON.stringify(bone)}, ${KEYED_BY_INDEX}`);
  if (b === undefined) return fail(`${at}.bone ${JSON.stringify(bone)} is no bone of the rig`);
  if (earlier.includes(b)) fail(`${at}.bone ${JSON.stringify(bone)} is listed twice`);
  return b;
}

/** An effector's "orientation" `q` (`where` names it) as a unit quaternion (x, y, z, w), or null when it gives none. */
function readOrientation(q: unknown, where: string): Float64Array | null {
  if (q === undefined || q === null) return null;
  failOn(orientationProblem(q, where));
  return Float64Array.from(q as number[]);
}
