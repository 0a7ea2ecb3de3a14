// Reading values out of a glTF JSON document, each checked, with errors that name the field
// (RigFormatError from failIn) and never print more than a short description of a bad value.
import { failIn } from '../rig_format_error.js';

export type JsonObject = Record<string, unknown>;

/** Longest text of a file (a name, a string value) quoted in a message, characters. */
const QUOTE_CHARS = 60;

/** `text` cut to QUOTE_CHARS characters (with "..." when cut), for messages. */
export function clip(text: string): string {
  return text.length > QUOTE_CHARS ? `${text.slice(0, QUOTE_CHARS)}...` : text;
}

/** Longest list of names spelled out in a message. */
const LISTED_NAMES = 12;

/** Names for messages: "a, b, c", a long list cut short ("a, b, c and 40 more"). */
export function listed(names: readonly string[]): string {
  const head = names.slice(0, LISTED_NAMES).map(clip).join(', ');
  return names.length > LISTED_NAMES ? `${head} and ${names.length - LISTED_NAMES} more` : head;
}

/** A short description of any JSON value for messages: 3.5, "abc", null, an array, an object. */
export function shown(v: unknown): string {
  if (typeof v === 'string') return JSON.stringify(clip(v));
  if (Array.isArray(v)) return 'an array';
  if (typeof v === 'object' && v !== null) return 'an object';
  return String(v);
}

/** `v` as a JSON object, or a RigFormatError naming `where`. */
export function asObject(v: unknown, where: string, file: string): JsonObject {
  if (typeof v !== 'object' || v === null || Array.isArray(v)) failIn(file, `${where} is not a JSON object`);
  return v as JsonObject;
}

/** `v` as an array of objects (missing means empty). */
export function asObjectList(v: unknown, where: string, file: string): JsonObject[] {
  if (v === undefined) return [];
  if (!Array.isArray(v)) failIn(file, `${where} is not an array`);
  return v.map((x, k) => asObject(x, `${where}[${k}]`, file));
}

/** What is wrong with the value `v` of field `where`: "where = 3.5 is not <expected>" or "where is missing (<expected>)". */
export function badValue(v: unknown, where: string, expected: string): string {
  return v === undefined ? `${where} is missing (${expected})` : `${where} = ${shown(v)} is not ${expected}`;
}

/** `v` as an integer in [0, count), or a RigFormatError naming `where`. */
export function asIndex(v: unknown, count: number, where: string, file: string): number {
  if (typeof v !== 'number' || !Number.isInteger(v) || v < 0 || v >= count)
    failIn(
      file,
      badValue(v, where, count > 0 ? `an index in 0..${count - 1}` : 'an index (the list it refers to is empty)'),
    );
  return v;
}

/**
 * `v` as an integer in [min, max] (max = Number.MAX_SAFE_INTEGER for "no upper bound"; `fallback`
 * when missing), or a RigFormatError naming `where`.
 */
export function asInteger(
  v: unknown,
  min: number,
  max: number,
  where: string,
  file: string,
  fallback?: number,
): number {
  if (v === undefined && fallback !== undefined) return fallback;
  if (typeof v !== 'number' || !Number.isInteger(v) || v < min || v > max)
    failIn(
      file,
      badValue(v, where, `a whole number ${max >= Number.MAX_SAFE_INTEGER ? `>= ${min}` : `in ${min}..${max}`}`),
    );
  return v;
}
