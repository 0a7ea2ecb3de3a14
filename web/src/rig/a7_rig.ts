// Reads the A7 course rig format (JSON, see PROTOCOL.md) into a RigSpec.
// Limits missing from the file are unbounded. A rig without `ik_constraints` takes its last bone
// as the end effector, as the original program did. Mesh and weight files are not needed.
import type { RigSpec } from '../ik/rig_spec.js';

export class RigFormatError extends Error {
  override name = 'RigFormatError';
}

/** Parses A7 JSON `text`; `file` names the source in error messages. Throws RigFormatError. */
export function parseA7Rig(text: string, file: string): RigSpec {
  let doc: unknown;
  try {
    doc = JSON.parse(text);
  } catch (e) {
    throw new RigFormatError(`${file}: bad JSON: ${(e as Error).message}`);
  }
  const fail = (what: string): never => {
    throw new RigFormatError(`${file}: ${what}`);
  };
  if (typeof doc !== 'object' || doc === null || !Array.isArray((doc as { bones?: unknown }).bones))
    fail('no "bones" array');
  const record = doc as { bones: unknown[]; ik_constraints?: unknown };
  const n = record.bones.length;
  if (n === 0) fail('"bones" is empty');
  const spec: RigSpec = {
    names: [],
    parents: new Int32Array(n),
    rest: new Float64Array(16 * n),
    lengths: new Float64Array(n),
    lower: new Float64Array(3 * n),
    upper: new Float64Array(3 * n),
    effectors: new Int32Array(0),
  };
  const num = (v: unknown, where: string): number => {
    if (typeof v !== 'number' || !Number.isFinite(v)) fail(`${where} is not a finite number`);
    return v as number;
  };
  record.bones.forEach((raw, i) => {
    const where = `bones[${i}]`;
    if (typeof raw !== 'object' || raw === null) fail(`${where} is not an object`);
    const b = raw as Record<string, unknown>;
    spec.names.push(typeof b.name === 'string' ? b.name : `bone ${i}`);
    if (!('parent_id' in b)) fail(`${where}.parent_id is missing`);
    const parent = num(b.parent_id, `${where}.parent_id`);
    if (!Number.isInteger(parent) || parent < -1 || parent >= n)
      fail(`${where}.parent_id ${parent} is not -1 or a bone index (0..${n - 1})`);
    spec.parents[i] = parent;
    spec.lengths[i] = 'length' in b ? num(b.length, `${where}.length`) : 0;
    const rows = b.rest_T;
    if (!Array.isArray(rows) || (rows.length !== 3 && rows.length !== 4))
      fail(`${where}.rest_T must be a 3x4 or 4x4 row-major matrix`);
    const m = spec.rest.subarray(16 * i, 16 * i + 16);
    m.set([0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1]);
    (rows as unknown[]).forEach((row, r) => {
      if (!Array.isArray(row) || row.length !== 4) fail(`${where}.rest_T row ${r} must have 4 numbers`);
      (row as unknown[]).forEach((v, c) => (m[4 * r + c] = num(v, `${where}.rest_T[${r}][${c}]`)));
    });
    for (const [key, out, missing] of [
      ['xzx_min', spec.lower, -Infinity],
      ['xzx_max', spec.upper, Infinity],
    ] as const) {
      const v = b[key];
      if (v === undefined) {
        out.fill(missing, 3 * i, 3 * i + 3);
        continue;
      }
      if (!Array.isArray(v) || v.length !== 3) fail(`${where}.${key} must be 3 numbers (degrees)`);
      (v as unknown[]).forEach((x, k) => (out[3 * i + k] = num(x, `${where}.${key}[${k}]`)));
    }
  });
  const c = record.ik_constraints;
  let effectors: number[];
  if (c === undefined) effectors = [n - 1];
  else if (typeof c === 'number') effectors = [c];
  else if (Array.isArray(c)) effectors = c.map((v, k) => num(v, `ik_constraints[${k}]`));
  else return fail('ik_constraints must be a bone index or a list of them');
  effectors.forEach((e, k) => {
    if (!Number.isInteger(e) || e < 0 || e >= n)
      fail(`ik_constraints[${k}] = ${e} is not a bone (0..${n - 1})`);
  });
  spec.effectors = Int32Array.from(effectors);
  return spec;
}
