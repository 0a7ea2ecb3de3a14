// The text of one command-line option turned into a checked value (options.ts). Every problem is
// a usage error: a BenchError with one line naming the flag, exit code 2.
import { BenchError, quote } from './errors.js';

/** A usage error: `message` as the one line printed, exit code 2. */
export const usage = (message: string): BenchError => new BenchError(message, 2);

/** `value` itself; a usage error naming `flag` when it is empty or blank. */
export function present(flag: string, value: string): string {
  if (value.trim() === '') throw usage(`${flag}: empty value`);
  return value;
}

/** The comma-separated items of `value`, trimmed; a usage error when there are none. */
export function list(flag: string, value: string): string[] {
  const items = present(flag, value)
    .split(',')
    .map((s) => s.trim())
    .filter((s) => s.length > 0);
  if (items.length === 0) throw usage(`${flag}: empty list ${quote(value)}`);
  return items;
}

/** The items of every value a list option was given (it may be repeated: --rig a --rig b is --rig a,b). */
export function lists(flag: string, values: string | string[]): string[] {
  return (Array.isArray(values) ? values : [values]).flatMap((v) => list(flag, v));
}

/** A finite number above 0 and at most `max`. */
export function positiveNumber(flag: string, value: string, max = Infinity): number {
  const x = Number(present(flag, value));
  if (!Number.isFinite(x) || x <= 0 || x > max)
    throw usage(`${flag}: ${quote(value)} is not a positive number${Number.isFinite(max) ? ` of at most ${max}` : ''}`);
  return x;
}

/**
 * An integer in min..max written in plain decimal digits (no 0x10, 1e3, 1.0 or blanks, which
 * Number() would take); `why` follows the range in the message.
 */
export function integerIn(flag: string, value: string, min: number, max: number, why = ''): number {
  const x = /^-?\d+$/.test(present(flag, value)) ? Number(value) : NaN;
  if (!Number.isSafeInteger(x) || x < min || x > max)
    throw usage(`${flag}: ${quote(value)} is not an integer in ${min}..${max}${why}`);
  return x;
}

/** The items of `value`, each one of `known`, without repeats. */
export function pick<T extends string>(flag: string, value: string | string[], known: readonly T[], what: string): T[] {
  const values = lists(flag, value);
  for (const v of values)
    if (!(known as readonly string[]).includes(v))
      throw usage(`${flag}: unknown ${what} ${quote(v)} (known: ${known.join(', ')})`);
  return [...new Set(values)] as T[];
}

/** One of `known`. */
export function pickOne<T extends string>(flag: string, value: string, known: readonly T[], what: string): T {
  const v = present(flag, value).trim();
  if (!(known as readonly string[]).includes(v))
    throw usage(`${flag}: unknown ${what} ${quote(v)} (known: ${known.join(', ')})`);
  return v as T;
}

/** An output or --compare file name; undefined when the option is absent. */
export function fileName(flag: string, value: string | undefined): string | undefined {
  return value === undefined ? undefined : present(flag, value);
}
