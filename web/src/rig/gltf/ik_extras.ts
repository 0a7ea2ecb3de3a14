// The IK metadata a glTF joint node may carry in `extras.ik` (schema: docs/gltf-ik-extras.md):
// XZX limits in degrees (their range: limit_degrees.ts), end-effector flag, bone length or tail
// (rig units, at most MAX_COORDINATE), and which child the bone points at.
import { failIn } from '../rig_format_error.js';
import { isUnbounded, limitProblem, type LimitSide } from '../limit_degrees.js';
import { MAX_COORDINATE } from '../rig_limits.js';

export interface IkExtras {
  /** 3 XZX lower limits in degrees (-Infinity = unbounded), or undefined for the default. */
  min: [number, number, number] | undefined;
  /** 3 XZX upper limits in degrees (+Infinity = unbounded), or undefined for the default. */
  max: [number, number, number] | undefined;
  /** true / false when stated, undefined when not. */
  effector: boolean | undefined;
  /** Bone length in the joint node's own units (before its world scale), if stated. */
  length: number | undefined;
  /** Bone tip in the joint node's local coordinates, if stated (wins over child and length). */
  tail: [number, number, number] | undefined;
  /** The child the bone points at: a node name or node index, if stated. */
  child: string | number | undefined;
}

const KEYS = new Set(['xzx_min', 'xzx_max', 'effector', 'length', 'tail', 'child']);

/**
 * Reads `extras.ik` of a node (`extras` is the node's raw extras value). Returns undefined when the
 * node has no `ik` object. `where` names the node in errors (RigFormatError from `file`).
 */
export function readIkExtras(extras: unknown, where: string, file: string): IkExtras | undefined {
  if (typeof extras !== 'object' || extras === null || !('ik' in extras)) return undefined;
  const ik = (extras as { ik: unknown }).ik;
  const at = `${where}: extras.ik`;
  if (typeof ik !== 'object' || ik === null || Array.isArray(ik)) failIn(file, `${at} is not a JSON object`);
  const o = ik as Record<string, unknown>;
  for (const key of Object.keys(o))
    if (!KEYS.has(key)) failIn(file, `${at}.${key} is not a known key (${[...KEYS].join(', ')})`);
  const limits = (side: LimitSide): [number, number, number] | undefined => {
    const key = `xzx_${side}`;
    const unbounded = side === 'min' ? -Infinity : Infinity;
    const v = o[key];
    if (v === undefined) return undefined;
    if (!Array.isArray(v) || v.length !== 3) failIn(file, `${at}.${key} must be 3 numbers (degrees) or nulls`);
    return v.map((x, k) => {
      if (x === null) return unbounded;
      if (typeof x !== 'number') failIn(file, `${at}.${key}[${k}] is not a number (degrees) or null`);
      const problem = limitProblem(x, side);
      if (problem) failIn(file, `${at}.${key}[${k}] ${problem}`);
      return isUnbounded(x, side) ? unbounded : x;
    }) as [number, number, number];
  };
  const result: IkExtras = {
    min: limits('min'),
    max: limits('max'),
    effector: undefined,
    length: undefined,
    tail: undefined,
    child: undefined,
  };
  if (result.min && result.max)
    for (let k = 0; k < 3; k++)
      if (result.min[k] > result.max[k])
        failIn(file, `${at}: xzx_min[${k}] = ${result.min[k]} is above xzx_max[${k}] = ${result.max[k]}`);
  if (o.effector !== undefined) {
    if (typeof o.effector !== 'boolean') failIn(file, `${at}.effector must be true or false`);
    result.effector = o.effector;
  }
  if (o.length !== undefined) {
    if (typeof o.length !== 'number' || !(o.length >= 0 && o.length <= MAX_COORDINATE))
      failIn(file, `${at}.length must be a number in 0..${MAX_COORDINATE}`);
    result.length = o.length;
  }
  if (o.tail !== undefined) {
    const t = o.tail;
    if (!Array.isArray(t) || t.length !== 3 || !t.every((x) => typeof x === 'number' && Math.abs(x) <= MAX_COORDINATE))
      failIn(
        file,
        `${at}.tail must be 3 numbers within +-${MAX_COORDINATE} (a point in the joint's local coordinates)`,
      );
    result.tail = t as [number, number, number];
  }
  if (o.child !== undefined) {
    if (typeof o.child !== 'string' && !(typeof o.child === 'number' && Number.isInteger(o.child)))
      failIn(file, `${at}.child must be a child node's name or index (a whole number)`);
    result.child = o.child;
  }
  return result;
}
