// Checks and copies of what callers hand the API, before anything reaches WebAssembly: the
// bindings get only typed arrays of the right length and plain option objects, so no user code
// (a valueOf, a getter, a Proxy trap) runs while C++ holds pointers into a rig or while a shared
// buffer is being filled, and every problem is named.
import type { IkCoreModule } from './generated/ik_core.mjs';

/** Largest array the API copies: past WebAssembly's memory anyway (a `{length: 1e10}` fails fast). */
const MAX_LENGTH = 2 ** 28;

/** The error the core left for a call that returned its failure value, as a thrown Error. */
export function coreError(module: IkCoreModule, what: string): Error {
  const message = module.takeError();
  return new Error(message || `${what} failed in the WebAssembly core`);
}

function describe(value: unknown): string {
  if (value === null) return 'null';
  if (Array.isArray(value)) return 'an array';
  if (typeof value === 'object') return 'an object';
  return typeof value === 'string' ? `the string "${value.slice(0, 40)}"` : String(value);
}

/** `value`'s length if it is an array or a typed array; throws naming `what` otherwise. */
function arrayLength(value: unknown, what: string): number {
  if (ArrayBuffer.isView(value) && !(value instanceof DataView)) return (value as unknown as ArrayLike<number>).length;
  if (!Array.isArray(value))
    throw new Error(`${what} must be an array or a typed array of numbers, not ${describe(value)}`);
  if (value.length > MAX_LENGTH) throw new Error(`${what} has ${value.length} values, more than any rig takes`);
  return value.length;
}

/**
 * A Float64Array copy of `values` (an array or typed array of numbers). `expected`: the length it
 * must have (undefined: any). `finite`: refuse NaN and infinities. Throws an Error naming `what`
 * and the first bad entry; never calls user code (entries must be numbers, not objects).
 */
export function toFloat64(values: unknown, what: string, expected?: number, finite = true): Float64Array {
  const n = arrayLength(values, what);
  if (expected !== undefined && n !== expected) throw new Error(`${what} has ${n} values, expected ${expected}`);
  const from = values as ArrayLike<unknown>;
  const out = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    const x = from[i];
    if (typeof x !== 'number') throw new Error(`${what}[${i}] is ${describe(x)}, not a number`);
    if (finite && !Number.isFinite(x)) throw new Error(`${what}[${i}] is ${x}, not a finite number`);
    out[i] = x;
  }
  return out;
}

/**
 * `values` checked for the core: `expected` numbers, any of them (the core refuses NaN and
 * infinities itself, naming the entry, wasm/src/finite_numbers.h). A typed array is passed on
 * without a copy (reading one runs no user code; the solve's hot path), anything else as a
 * Float64Array copy: a Proxy's or getter's code then runs here, before anything is written to
 * WebAssembly memory.
 */
export function checkedNumbers(values: unknown, what: string, expected: number): ArrayLike<number> {
  if (!ArrayBuffer.isView(values) || values instanceof DataView) return toFloat64(values, what, expected, false);
  const typed = values as unknown as ArrayLike<number>;
  if (typed.length !== expected) throw new Error(`${what} has ${typed.length} values, expected ${expected}`);
  return typed;
}

/**
 * An Int32Array copy of `values` (integers, e.g. bone indices). Throws an Error naming `what` and
 * the first entry that is not an integer within 32 bits (never truncated or wrapped).
 */
export function toInt32(values: unknown, what: string, expected?: number): Int32Array {
  const n = arrayLength(values, what);
  if (expected !== undefined && n !== expected) throw new Error(`${what} has ${n} values, expected ${expected}`);
  const out = new Int32Array(n);
  const from = values as ArrayLike<unknown>;
  for (let i = 0; i < n; i++) {
    const x = from[i];
    if (typeof x !== 'number' || !Number.isInteger(x) || Math.abs(x) > 0x7fffffff)
      throw new Error(`${what}[${i}] is ${describe(x)}, not an integer index`);
    out[i] = x;
  }
  return out;
}

/**
 * `value` if it is an integer number in low..high (no string, no fraction, nothing past the range
 * to be wrapped); throws an Error naming `what` otherwise.
 */
export function checkedInteger(value: unknown, what: string, low: number, high: number): number {
  if (typeof value !== 'number' || !Number.isInteger(value) || value < low || value > high)
    throw new Error(`${what} must be an integer in ${low}..${high}, not ${describe(value)}`);
  return value;
}

/**
 * A fresh plain object with the own enumerable fields of `options` whose names are in `known`,
 * each a number or a boolean, read once. Throws an Error for a non-object (arrays and Maps
 * included), an unknown name (listing the known ones) or a value of another type.
 */
export function plainOptions(
  options: unknown,
  known: readonly string[],
  what: string,
): Record<string, number | boolean> {
  if (options === undefined || options === null) return {};
  const proto = typeof options === 'object' ? Object.getPrototypeOf(options) : undefined;
  if (typeof options !== 'object' || (proto !== Object.prototype && proto !== null))
    throw new Error(`${what} must be a plain object like { maxIterations: 100 }, not ${describe(options)}`);
  const out: Record<string, number | boolean> = {};
  for (const key of Object.keys(options)) {
    if (!known.includes(key)) throw new Error(`unknown ${what} "${key.slice(0, 60)}" (known: ${known.join(', ')})`);
    const value: unknown = (options as Record<string, unknown>)[key];
    if (value === undefined) continue;
    if (typeof value !== 'number' && typeof value !== 'boolean')
      throw new Error(`${what} ${key} must be a number or a boolean, not ${describe(value)}`);
    out[key] = value;
  }
  return out;
}
