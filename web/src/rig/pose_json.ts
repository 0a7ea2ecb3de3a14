// The pose file: a rig's joint angles and end-effector targets as JSON, keyed by bone name so a
// pose survives a rig whose bones come in another order.
//
//   {
//     "format": "ik-pose",
//     "version": 1,
//     "rig": "knight",
//     "bones": {
//       "thigh.L": [10, -5, 0],           <- XZX angles, degrees
//       ...
//     },
//     "effectors": [
//       { "bone": "hand.L", "target": [0.1, 1.2, 0.3], "orientation": [0, 0, 0, 1] },  <- rig units; unit quaternion (x, y, z, w), optional
//       ...
//     ]
//   }
//
// Reading checks everything and names the field of the first problem: unknown bones are an error,
// bones the file lacks stay at 0 (a warning), angles past the rig's limits are clamped (a warning
// naming the bone). Numbers are written in JavaScript's shortest round-trip form, so a pose
// written and read back gives the same angles bit for bit.
import type { RigSpec } from '../ik/rig_spec.js';
import { jsonBudgetProblem } from './json_budget.js';
import { effectorCountProblem, MAX_COORDINATE } from './rig_limits.js';

/** The "format" of a pose file. */
export const POSE_FORMAT = 'ik-pose';
/** The version this module writes and reads. */
export const POSE_VERSION = 1;
/** Largest pose file read, characters (a pose of 65,536 bones is about 3 MB). */
export const MAX_POSE_CHARS = 8 * 1024 * 1024;
/** Largest deviation of an orientation quaternion's length from 1. */
const UNIT_TOLERANCE = 1e-6;
/** Bone names listed in one message before "and N more". */
const NAMES_SHOWN = 8;

/** A pose to write. */
export interface PoseInput {
  /** The rig's name (its file's base name), for the reader's information. */
  rigName: string;
  /** Every bone's name, in the order of `angles`; names must be distinct. */
  boneNames: readonly string[];
  /** XZX joint angles, 3 per bone, degrees. */
  angles: ArrayLike<number>;
  /** Bone name of each end effector. */
  effectors: readonly string[];
  /** Each effector's target position, 3 per effector, rig units. */
  targets: ArrayLike<number>;
  /** Per effector, an orientation goal as a unit quaternion (x, y, z, w), or null for none. */
  orientations?: readonly (ArrayLike<number> | null)[];
}

/** A pose read for a given rig. */
export interface PoseRead {
  /** The rig name the file gives ('' when it gives none). */
  rigName: string;
  /** XZX angles, 3 per bone of the rig (rig order), degrees, within the limits. */
  angles: Float64Array;
  /** Bone index of each end effector. */
  effectors: number[];
  /** Target per effector, 3 each, rig units. */
  targets: Float64Array;
  /** Per effector, the orientation quaternion (x, y, z, w) or null. */
  orientations: (Float64Array | null)[];
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
  const shown = names.slice(0, NAMES_SHOWN).map((n) => JSON.stringify(n)).join(', ');
  return names.length > NAMES_SHOWN ? `${shown} and ${names.length - NAMES_SHOWN} more` : shown;
};

const shown = (v: unknown): string => {
  if (typeof v === 'number' || typeof v === 'boolean' || v === null) return String(v);
  if (typeof v === 'string') return JSON.stringify(v.length > 40 ? `${v.slice(0, 40)}...` : v);
  return Array.isArray(v) ? 'an array' : typeof v;
};

function duplicates(names: readonly string[]): string[] {
  const seen = new Set<string>(), twice = new Set<string>();
  for (const n of names) (seen.has(n) ? twice : seen).add(n);
  return [...twice];
}

/** `v` as an array of `n` finite numbers, else a PoseFormatError naming `field`. */
function finiteArray(v: unknown, n: number, field: string, what: string): number[] {
  if (!Array.isArray(v)) return fail(`${field} is ${shown(v)}, not an array of ${n} numbers (${what})`);
  if (v.length !== n) return fail(`${field} has ${v.length} values, expected ${n} (${what})`);
  v.forEach((x, k) => {
    if (typeof x !== 'number' || !Number.isFinite(x)) fail(`${field}[${k}] is ${shown(x)}, not a finite number`);
  });
  return v as number[];
}

/**
 * Writes a pose as pose-file JSON text (format above): angles in degrees keyed by bone name,
 * targets in rig units, orientations as unit quaternions (x, y, z, w). Throws an Error for
 * inconsistent input: wrong lengths, non-finite numbers, duplicate bone names, an effector that
 * names no bone.
 */
export function poseToJson(pose: PoseInput): string {
  const { rigName, boneNames, angles, effectors, targets, orientations } = pose;
  const problem = (what: string): never => {
    throw new Error(`poseToJson: ${what}`);
  };
  if (typeof rigName !== 'string') problem('rigName is not a string');
  if (angles.length !== 3 * boneNames.length) problem(`angles has ${angles.length} values for ${boneNames.length} bones (3 per bone)`);
  const twice = duplicates(boneNames);
  if (twice.length) problem(`bone names ${listed(twice)} are used by more than one bone; a pose file keys angles by name`);
  if (targets.length !== 3 * effectors.length) problem(`targets has ${targets.length} values for ${effectors.length} effectors (3 per effector)`);
  if (orientations !== undefined && orientations.length !== effectors.length)
    problem(`orientations has ${orientations.length} entries for ${effectors.length} effectors`);
  const known = new Set(boneNames);
  const row = (a: ArrayLike<number>, at: number, n: number, what: string): number[] => {
    const out = Array.from({ length: n }, (_, k) => a[at + k]);
    if (!out.every(Number.isFinite)) problem(`${what} has a non-finite value`);
    return out;
  };
  const bones = boneNames.map((name, i) => `    ${JSON.stringify(name)}: ${JSON.stringify(row(angles, 3 * i, 3, `angles of bone ${JSON.stringify(name)}`))}`);
  const effectorLines = effectors.map((bone, e) => {
    if (!known.has(bone)) problem(`effector ${e} names the bone ${JSON.stringify(bone)}, which is not in boneNames`);
    const q = orientations?.[e];
    const entry: Record<string, unknown> = { bone, target: row(targets, 3 * e, 3, `target of effector ${JSON.stringify(bone)}`) };
    if (q !== null && q !== undefined) {
      if (q.length !== 4) problem(`orientation of effector ${JSON.stringify(bone)} has ${q.length} values, expected 4`);
      entry.orientation = row(q, 0, 4, `orientation of effector ${JSON.stringify(bone)}`);
    }
    return `    ${JSON.stringify(entry)}`;
  });
  const block = (open: string, lines: string[], close: string): string => (lines.length ? `${open}\n${lines.join(',\n')}\n  ${close}` : `${open}${close}`);
  return [
    '{',
    `  "format": ${JSON.stringify(POSE_FORMAT)},`,
    `  "version": ${POSE_VERSION},`,
    `  "rig": ${JSON.stringify(rigName)},`,
    `  "bones": ${block('{', bones, '}')},`,
    `  "effectors": ${block('[', effectorLines, ']')}`,
    '}',
    '',
  ].join('\n');
}

/**
 * Reads pose-file JSON `text` for the rig `spec` (its `names` identify the bones). Angles outside
 * `limits` (3 per bone, degrees; default the spec's lower/upper) are clamped with a warning naming
 * the bone; bones the file lacks get 0 with a warning. Throws a PoseFormatError naming the field
 * for anything malformed: more than MAX_POSE_CHARS, not JSON, another format or version, a bone
 * the rig lacks, wrong lengths, non-finite numbers, an effector listed twice, a non-unit
 * orientation, a target beyond MAX_COORDINATE.
 */
export function poseFromJson(text: string, spec: Pick<RigSpec, 'names' | 'lower' | 'upper'>, limits?: PoseLimits): PoseRead {
  if (typeof text !== 'string') fail(`expected text, got ${shown(text)}`);
  if (text.length > MAX_POSE_CHARS)
    fail(`${(text.length / 1048576).toFixed(1)} MB of text, more than a pose file holds (at most ${MAX_POSE_CHARS / 1048576} MB)`);
  const tooBig = jsonBudgetProblem(text);
  if (tooBig) fail(tooBig);
  let doc: unknown;
  try {
    doc = JSON.parse(text.charCodeAt(0) === 0xfeff ? text.slice(1) : text);
  } catch (e) {
    return fail(`not JSON: ${(e as Error).message}`);
  }
  if (typeof doc !== 'object' || doc === null || Array.isArray(doc)) return fail(`the JSON is ${shown(doc)}, not an object`);
  const root = doc as Record<string, unknown>;
  const field = (key: string): unknown => (Object.hasOwn(root, key) ? root[key] : undefined);
  if (field('format') !== POSE_FORMAT) fail(`"format" is ${shown(field('format'))}, expected "${POSE_FORMAT}"`);
  if (field('version') !== POSE_VERSION) fail(`"version" is ${shown(field('version'))}; this reader takes version ${POSE_VERSION}`);
  const rig = field('rig');
  if (rig !== undefined && typeof rig !== 'string') fail(`"rig" is ${shown(rig)}, not a string`);

  const names = spec.names;
  const n = names.length;
  const lower = limits?.lower ?? spec.lower, upper = limits?.upper ?? spec.upper;
  if (lower.length !== 3 * n || upper.length !== 3 * n) throw new Error(`poseFromJson: limits have ${lower.length} and ${upper.length} values for ${n} bones (3 per bone)`);
  const index = new Map<string, number>();
  names.forEach((name, i) => index.set(name, index.has(name) ? -1 : i)); // -1: a name two bones share
  const warnings: string[] = [];

  const bones = field('bones');
  if (typeof bones !== 'object' || bones === null || Array.isArray(bones)) return fail(`"bones" is ${shown(bones)}, not an object of bone name -> [3 angles in degrees]`);
  const entries = Object.entries(bones as Record<string, unknown>);
  const unknown = entries.filter(([name]) => !index.has(name)).map(([name]) => name);
  if (unknown.length) fail(`"bones" names ${unknown.length} bone(s) the rig lacks: ${listed(unknown)}`);
  const ambiguous = entries.filter(([name]) => index.get(name) === -1).map(([name]) => name);
  if (ambiguous.length) fail(`"bones" names ${listed(ambiguous)}, which more than one bone of the rig is called`);
  const angles = new Float64Array(3 * n);
  const given = new Uint8Array(n);
  const clamped: string[] = [];
  for (const [name, value] of entries) {
    const i = index.get(name)!;
    const a = finiteArray(value, 3, `"bones"[${JSON.stringify(name)}]`, 'XZX angles in degrees');
    given[i] = 1;
    let changed = false;
    for (let k = 0; k < 3; k++) {
      const lo = lower[3 * i + k], hi = upper[3 * i + k];
      const v = Math.min(Math.max(a[k], lo), hi);
      if (v !== a[k]) changed = true;
      angles[3 * i + k] = v;
    }
    if (changed) clamped.push(`${JSON.stringify(name)} [${a.join(', ')}] -> [${Array.from(angles.subarray(3 * i, 3 * i + 3)).join(', ')}]`);
  }
  if (clamped.length)
    warnings.push(`angles outside the rig's limits were clamped for ${clamped.length} bone(s): ${clamped.slice(0, NAMES_SHOWN).join('; ')}${clamped.length > NAMES_SHOWN ? `; and ${clamped.length - NAMES_SHOWN} more` : ''}`);
  const missing = names.filter((_, i) => !given[i]);
  if (missing.length) warnings.push(`the pose gives no angles for ${missing.length} bone(s), left at 0: ${listed(missing)}`);

  const list = field('effectors');
  if (!Array.isArray(list)) return fail(`"effectors" is ${shown(list)}, not an array of { "bone", "target", "orientation"? }`);
  const countProblem = effectorCountProblem(list.length, n);
  if (countProblem) fail(`"effectors": ${countProblem}`);
  const effectors: number[] = [];
  const targets = new Float64Array(3 * list.length);
  const orientations: (Float64Array | null)[] = [];
  list.forEach((item: unknown, e) => {
    const at = `"effectors"[${e}]`;
    if (typeof item !== 'object' || item === null || Array.isArray(item)) fail(`${at} is ${shown(item)}, not an object`);
    const entry = item as Record<string, unknown>;
    const get = (key: string): unknown => (Object.hasOwn(entry, key) ? entry[key] : undefined);
    const bone = get('bone');
    if (typeof bone !== 'string') return fail(`${at}.bone is ${shown(bone)}, not a bone name`);
    const b = index.get(bone);
    if (b === undefined) fail(`${at}.bone ${JSON.stringify(bone)} is no bone of the rig`);
    if (b === -1) fail(`${at}.bone ${JSON.stringify(bone)} names more than one bone of the rig`);
    if (effectors.includes(b!)) fail(`${at}.bone ${JSON.stringify(bone)} is listed twice`);
    const t = finiteArray(get('target'), 3, `${at}.target`, 'a position in rig units');
    t.forEach((v, k) => {
      if (Math.abs(v) > MAX_COORDINATE) fail(`${at}.target[${k}] = ${v} lies beyond +-${MAX_COORDINATE} rig units`);
    });
    const q = get('orientation');
    if (q === undefined || q === null) orientations.push(null);
    else {
      const quat = finiteArray(q, 4, `${at}.orientation`, 'a unit quaternion x, y, z, w');
      const len = Math.hypot(...quat);
      if (Math.abs(len - 1) > UNIT_TOLERANCE) fail(`${at}.orientation has length ${len}, not a unit quaternion`);
      orientations.push(Float64Array.from(quat));
    }
    effectors.push(b!);
    targets.set(t, 3 * e);
  });
  return { rigName: typeof rig === 'string' ? rig : '', angles, effectors, targets, orientations, warnings };
}
