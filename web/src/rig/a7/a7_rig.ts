// Reads the A7 course rig format (JSON, see PROTOCOL.md) into a RigSpec, checking everything the
// core would refuse (so every error names the file and the field): parents in range and without
// a cycle, rigid rest matrices, lengths and positions within MAX_COORDINATE, limits as
// limit_degrees.ts says (1e10 and the like mean unbounded and are kept as written), at most
// MAX_BONES bones and as many end effectors as the core takes, none listed twice.
// Limits missing from the file are unbounded. A rig without `ik_constraints` takes its last bone
// as the end effector, as the original program did. A bone without a name gets '' (the core and
// the page then call it "bone 3"). Mesh and weight files are not needed. The native tools read the
// format with wasm/native/a7_rig.cpp (tests/bench/protocol_agreement.test.ts reads every test rig
// both ways and compares what follows from it).
import type { RigSpec } from '../../ik/rig_arrays.js';
import { jsonBudgetProblem } from '../json_budget.js';
import { limitProblem } from '../limit_degrees.js';
import { effectorCountProblem, MAX_BONES, MAX_COORDINATE } from '../rig_limits.js';
import { failIn } from '../rig_format_error.js';
import { cycleText, findCycle } from '../tree.js';

/** Largest deviation of rest_T's rotation block from orthonormal (Frobenius norm), as the core allows. */
const RIGID_TOLERANCE = 1e-6;

/** Largest deviation of a 4x4 rest_T's bottom row from (0, 0, 0, 1), as the core allows. */
const BOTTOM_ROW_TOLERANCE = 1e-9;

/** What the A7 JSON holds at the top: the bones (unchecked) and `ik_constraints` (unchecked). */
interface A7Record {
  bones: unknown[];
  ik_constraints?: unknown;
}

/**
 * Parses A7 JSON `text`; `file` names the source in error messages. Lengths and positions are
 * in rig units, limits in degrees. Throws RigFormatError naming the file and the field.
 */
export function parseA7Rig(text: string, file: string): RigSpec {
  const record = readRecord(parseJson(text, file), file);
  const n = record.bones.length;
  const spec = emptySpec(n);
  record.bones.forEach((raw, i) => readBone(raw, i, spec, file));
  const cycle = findCycle(spec.parents);
  if (cycle) failIn(file, `the bones' parent_id form a cycle: ${cycleText(cycle, (b) => `bones[${b}]`)}`);
  spec.effectors = readEffectors(record.ik_constraints, n, file);
  return spec;
}

/** The JSON value of `text` (a leading byte order mark skipped), once it is within the JSON budget. */
function parseJson(text: string, file: string): unknown {
  const tooBig = jsonBudgetProblem(text);
  if (tooBig) failIn(file, tooBig);
  try {
    return JSON.parse(text.charCodeAt(0) === 0xfeff ? text.slice(1) : text);
  } catch (e) {
    return failIn(file, `bad JSON: ${(e as Error).message}`);
  }
}

/** `doc` as an A7 record whose "bones" array holds 1 to MAX_BONES entries. */
function readRecord(doc: unknown, file: string): A7Record {
  if (typeof doc !== 'object' || doc === null || !Array.isArray((doc as { bones?: unknown }).bones))
    failIn(file, 'no "bones" array');
  const record = doc as A7Record;
  const n = record.bones.length;
  if (n === 0) failIn(file, '"bones" is empty');
  if (n > MAX_BONES) failIn(file, `${n} bones; at most ${MAX_BONES}`);
  return record;
}

/** A RigSpec for `n` bones with every array allocated and zero, no names and no end effectors yet. */
function emptySpec(n: number): RigSpec {
  return {
    names: [],
    parents: new Int32Array(n),
    rest: new Float64Array(16 * n),
    lengths: new Float64Array(n),
    lower: new Float64Array(3 * n),
    upper: new Float64Array(3 * n),
    effectors: new Int32Array(0),
  };
}

/** `v` as a number; throws when it is not a finite number (`where` names the field). */
function finiteNumber(v: unknown, where: string, file: string): number {
  if (typeof v !== 'number' || !Number.isFinite(v)) failIn(file, `${where} is not a finite number`);
  return v as number;
}

/** `v` as a length or position in rig units; throws when it is not finite or beyond +-MAX_COORDINATE. */
function coordinate(v: unknown, where: string, file: string): number {
  const x = finiteNumber(v, where, file);
  if (Math.abs(x) > MAX_COORDINATE) failIn(file, `${where} = ${x} lies beyond +-${MAX_COORDINATE} rig units`);
  return x;
}

/**
 * Bone `i` of the file (`raw`, unchecked) into `spec`: its name, parent, length (rig units), rest
 * matrix and limits (degrees). Checks the fields in that order.
 */
function readBone(raw: unknown, i: number, spec: RigSpec, file: string): void {
  const where = `bones[${i}]`;
  if (typeof raw !== 'object' || raw === null || Array.isArray(raw)) failIn(file, `${where} is not an object`);
  const b = raw as Record<string, unknown>;
  if (b.name !== undefined && typeof b.name !== 'string') failIn(file, `${where}.name is not a string`);
  spec.names.push(typeof b.name === 'string' ? b.name : '');
  spec.parents[i] = readParent(b.parent_id, i, spec.parents.length, where, file);
  const length = b.length === undefined ? 0 : coordinate(b.length, `${where}.length`, file);
  if (length < 0) failIn(file, `${where}.length ${length} is negative`);
  spec.lengths[i] = length;
  readRest(b.rest_T, spec.rest.subarray(16 * i, 16 * i + 16), `${where}.rest_T`, file);
  readLimits(b, i, spec, where, file);
}

/** parent_id `v` of bone `i` of `n`: -1 or the index of another bone. */
function readParent(v: unknown, i: number, n: number, where: string, file: string): number {
  if (v === undefined) failIn(file, `${where}.parent_id is missing`);
  const parent = finiteNumber(v, `${where}.parent_id`, file);
  if (!Number.isInteger(parent) || parent < -1 || parent >= n)
    failIn(file, `${where}.parent_id ${parent} is not -1 or a bone index (0..${n - 1})`);
  if (parent === i) failIn(file, `${where}.parent_id is the bone itself`);
  return parent;
}

/** rest_T (3x4 or 4x4, row-major, rigid; translation in rig units) into `m` (16 numbers). */
function readRest(rows: unknown, m: Float64Array, where: string, file: string): void {
  if (!Array.isArray(rows) || (rows.length !== 3 && rows.length !== 4))
    failIn(file, `${where} must be a 3x4 or 4x4 row-major matrix`);
  m.set([0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1]);
  (rows as unknown[]).forEach((row, r) => {
    if (!Array.isArray(row) || row.length !== 4) failIn(file, `${where} row ${r} must have 4 numbers`);
    (row as unknown[]).forEach((v, c) => {
      const at = `${where}[${r}][${c}]`;
      m[4 * r + c] = c === 3 && r < 3 ? coordinate(v, at, file) : finiteNumber(v, at, file);
    });
  });
  if (Math.hypot(m[12], m[13], m[14], m[15] - 1) > BOTTOM_ROW_TOLERANCE)
    failIn(file, `${where} bottom row is not (0, 0, 0, 1)`);
  let off = 0;
  for (let r = 0; r < 3; r++)
    for (let c = 0; c < 3; c++) {
      const dot = m[r] * m[c] + m[4 + r] * m[4 + c] + m[8 + r] * m[8 + c]; // (R^T R)[r][c]
      off += (dot - (r === c ? 1 : 0)) ** 2;
    }
  if (Math.sqrt(off) > RIGID_TOLERANCE) failIn(file, `${where} is not rigid (its rotation part is not orthonormal)`);
  const det =
    m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8]) + m[2] * (m[4] * m[9] - m[5] * m[8]);
  if (det < 0) failIn(file, `${where} is not rigid (it mirrors: determinant < 0)`);
}

/** xzx_min and xzx_max of bone `i` (`b`) into `spec` (degrees; missing means unbounded). */
function readLimits(b: Record<string, unknown>, i: number, spec: RigSpec, where: string, file: string): void {
  for (const [side, out, missing] of [
    ['min', spec.lower, -Infinity],
    ['max', spec.upper, Infinity],
  ] as const) {
    const key = `xzx_${side}`;
    const v = b[key];
    if (v === undefined) {
      out.fill(missing, 3 * i, 3 * i + 3);
      continue;
    }
    if (!Array.isArray(v) || v.length !== 3) failIn(file, `${where}.${key} must be 3 numbers (degrees)`);
    (v as unknown[]).forEach((x, k) => {
      if (typeof x !== 'number') failIn(file, `${where}.${key}[${k}] is not a number (degrees)`);
      const problem = limitProblem(x as number, side);
      if (problem) failIn(file, `${where}.${key}[${k}] ${problem}`);
      out[3 * i + k] = x as number;
    });
  }
  for (let k = 0; k < 3; k++)
    if (spec.lower[3 * i + k] > spec.upper[3 * i + k])
      failIn(
        file,
        `${where}.xzx_min[${k}] = ${spec.lower[3 * i + k]} is above xzx_max[${k}] = ${spec.upper[3 * i + k]}`,
      );
}

/** The end-effector bones (of `n`) of `ik_constraints` `c` (a bone index or a list), the last bone when missing. */
function readEffectors(c: unknown, n: number, file: string): Int32Array {
  if (c === undefined) return Int32Array.of(n - 1);
  const list =
    typeof c === 'number'
      ? [c]
      : Array.isArray(c)
        ? c
        : failIn(file, 'ik_constraints must be a bone index or a list of them');
  if (list.length === 0) failIn(file, 'ik_constraints is empty: a rig needs an end effector');
  const tooMany = effectorCountProblem(list.length, n);
  if (tooMany) failIn(file, `ik_constraints lists ${tooMany}`);
  const seen = new Set<number>();
  return Int32Array.from(list, (v: unknown, k) => {
    const where = typeof c === 'number' ? 'ik_constraints' : `ik_constraints[${k}]`;
    const e = finiteNumber(v, where, file);
    if (!Number.isInteger(e) || e < 0 || e >= n) failIn(file, `${where} = ${e} is not a bone (0..${n - 1})`);
    if (seen.has(e)) failIn(file, `${where} lists bone ${e} a second time`);
    seen.add(e);
    return e;
  });
}
