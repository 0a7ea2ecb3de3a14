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
// naming the bone when one changes). Writing refuses what reading would refuse (the checks are
// shared: pose_checks.ts). Numbers are written in JavaScript's shortest round-trip form, so a pose
// written and read back gives the same angles bit for bit.
import type { RigSpec } from '../ik/rig_arrays.js';
import { jsonBudgetProblem } from './json_budget.js';
import { effectorsProblem, numbersProblem, orientationProblem, shown, targetProblem } from './pose_checks.js';
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

const listed = (names: readonly string[]): string => {
  const shownNames = names
    .slice(0, NAMES_SHOWN)
    .map((n) => JSON.stringify(n))
    .join(', ');
  return names.length > NAMES_SHOWN ? `${shownNames} and ${names.length - NAMES_SHOWN} more` : shownNames;
};

/** `v` as an array of `n` finite numbers, else a PoseFormatError naming `field`. */
function finiteArray(v: unknown, n: number, field: string, what: string): number[] {
  const bad = numbersProblem(v, n, field, what);
  if (bad) fail(bad);
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
  if (typeof text !== 'string') fail(`expected text, got ${shown(text)}`);
  if (text.length > MAX_POSE_CHARS)
    fail(
      `${(text.length / 1048576).toFixed(1)} MB of text, more than a pose file holds (at most ${MAX_POSE_CHARS / 1048576} MB)`,
    );
  const tooBig = jsonBudgetProblem(text);
  if (tooBig) fail(tooBig);
  let doc: unknown;
  try {
    doc = JSON.parse(text.charCodeAt(0) === 0xfeff ? text.slice(1) : text);
  } catch (e) {
    return fail(`not JSON: ${(e as Error).message}`);
  }
  if (typeof doc !== 'object' || doc === null || Array.isArray(doc))
    return fail(`the JSON is ${shown(doc)}, not an object`);
  const root = doc as Record<string, unknown>;
  const field = (key: string): unknown => (Object.hasOwn(root, key) ? root[key] : undefined);
  if (field('format') !== POSE_FORMAT) fail(`"format" is ${shown(field('format'))}, expected "${POSE_FORMAT}"`);
  if (field('version') !== POSE_VERSION)
    fail(`"version" is ${shown(field('version'))}; this reader takes version ${POSE_VERSION}`);
  const rig = field('rig');
  if (rig !== undefined && typeof rig !== 'string') fail(`"rig" is ${shown(rig)}, not a string`);

  const names = spec.names;
  const n = names.length;
  const lower = limits?.lower ?? spec.lower,
    upper = limits?.upper ?? spec.upper;
  if (lower.length !== 3 * n || upper.length !== 3 * n)
    throw new Error(`poseFromJson: limits have ${lower.length} and ${upper.length} values for ${n} bones (3 per bone)`);
  const keys = poseBoneKeys(names);
  const index = new Map(keys.map((key, i) => [key, i]));
  const unusable = new Set(names.filter((name, i) => keys[i] !== name)); // names the file cannot key by
  const warnings: string[] = [];

  const bones = field('bones');
  if (typeof bones !== 'object' || bones === null || Array.isArray(bones))
    return fail(`"bones" is ${shown(bones)}, not an object of bone name -> [3 angles in degrees]`);
  const entries = Object.entries(bones as Record<string, unknown>);
  const ambiguous = entries.filter(([key]) => !index.has(key) && unusable.has(key)).map(([key]) => key);
  if (ambiguous.length) fail(`"bones" names ${listed(ambiguous)}, ${KEYED_BY_INDEX}`);
  const unknown = entries.filter(([key]) => !index.has(key)).map(([key]) => key);
  if (unknown.length) fail(`"bones" names ${unknown.length} bone(s) the rig lacks: ${listed(unknown)}`);
  const given = new Array<number[] | undefined>(n);
  for (const [key, value] of entries)
    given[index.get(key)!] = finiteArray(value, 3, `"bones"[${JSON.stringify(key)}]`, 'XZX angles in degrees');
  // Every angle, also those of bones the file lacks (0), is clamped into the limits.
  const angles = new Float64Array(3 * n);
  const clamped: string[] = [];
  for (let i = 0; i < n; i++) {
    const a = given[i] ?? [0, 0, 0];
    for (let k = 0; k < 3; k++) angles[3 * i + k] = Math.min(Math.max(a[k], lower[3 * i + k]), upper[3 * i + k]);
    const now = Array.from(angles.subarray(3 * i, 3 * i + 3));
    if (given[i] && now.some((v, k) => v !== a[k]))
      clamped.push(`${JSON.stringify(keys[i])} [${a.join(', ')}] -> [${now.join(', ')}]`);
  }
  if (clamped.length)
    warnings.push(
      `angles outside the rig's limits were clamped for ${clamped.length} bone(s): ${clamped.slice(0, NAMES_SHOWN).join('; ')}${clamped.length > NAMES_SHOWN ? `; and ${clamped.length - NAMES_SHOWN} more` : ''}`,
    );
  const missing = keys.filter((_, i) => !given[i]);
  if (missing.length)
    warnings.push(
      `the pose gives no angles for ${missing.length} bone(s), set to 0 or the nearest limit: ${listed(missing)}`,
    );

  const rootField = field('root');
  let rootMove: Float64Array | null = null;
  if (rootField !== undefined) {
    const r = finiteArray(rootField, 3, '"root"', "a floating root's move in rig units");
    const far = targetProblem(r, '"root"');
    if (far) fail(far);
    rootMove = Float64Array.from(r);
  }

  const list = field('effectors');
  if (!Array.isArray(list))
    return fail(`"effectors" is ${shown(list)}, not an array of { "bone", "target", "orientation"? }`);
  const countProblem = effectorsProblem(list.length, n);
  if (countProblem) fail(countProblem);
  const effectors: number[] = [];
  const targets = new Float64Array(3 * list.length);
  const orientations: (Float64Array | null)[] = [];
  list.forEach((item: unknown, e) => {
    const at = `"effectors"[${e}]`;
    if (typeof item !== 'object' || item === null || Array.isArray(item))
      fail(`${at} is ${shown(item)}, not an object`);
    const entry = item as Record<string, unknown>;
    const get = (key: string): unknown => (Object.hasOwn(entry, key) ? entry[key] : undefined);
    const bone = get('bone');
    if (typeof bone !== 'string') return fail(`${at}.bone is ${shown(bone)}, not a bone name`);
    const b = index.get(bone);
    if (b === undefined && unusable.has(bone)) fail(`${at}.bone ${JSON.stringify(bone)}, ${KEYED_BY_INDEX}`);
    if (b === undefined) return fail(`${at}.bone ${JSON.stringify(bone)} is no bone of the rig`);
    if (effectors.includes(b)) fail(`${at}.bone ${JSON.stringify(bone)} is listed twice`);
    const t = get('target');
    const badTarget = targetProblem(t, `${at}.target`);
    if (badTarget) fail(badTarget);
    const q = get('orientation');
    if (q === undefined || q === null) orientations.push(null);
    else {
      const badOrientation = orientationProblem(q, `${at}.orientation`);
      if (badOrientation) fail(badOrientation);
      orientations.push(Float64Array.from(q as number[]));
    }
    effectors.push(b);
    targets.set(t as number[], 3 * e);
  });
  return {
    rigName: typeof rig === 'string' ? rig : '',
    angles,
    effectors,
    targets,
    orientations,
    root: rootMove,
    warnings,
  };
}
