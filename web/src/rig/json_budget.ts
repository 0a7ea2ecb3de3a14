// A linear scan of a rig file's JSON text before JSON.parse builds it, so that a hostile file
// cannot make the parser allocate without bound: a 200 MB A7 file of arrays nested 10,000 deep
// made 100 million arrays and ran Node out of memory. Real rigs are far inside both budgets: an A7
// rig nests 4 levels with about 35 values per bone (570,000 at the 16,384 bones the core takes),
// a glTF's JSON holds a few values per node, accessor and mesh (its bulk data sits in binary
// buffers or in long base64 strings): the project's rigs hold at most 1,300. JSON.parse of the
// largest document accepted builds at most a few hundred MB.

/** Deepest nesting of arrays and objects accepted. */
export const MAX_JSON_DEPTH = 64;

/** Most values (numbers, strings, arrays, objects...) accepted in one document. */
export const MAX_JSON_VALUES = 4_000_000;

/**
 * Most arrays and objects accepted in one document: each costs JSON.parse some 100 bytes, ten
 * times a number (an A7 rig has about 7 per bone, a glTF about 4 per node).
 */
export const MAX_JSON_CONTAINERS = 1_000_000;

const QUOTE = 0x22,
  BACKSLASH = 0x5c,
  COMMA = 0x2c;
const OPEN_ARRAY = 0x5b,
  OPEN_OBJECT = 0x7b,
  CLOSE_ARRAY = 0x5d,
  CLOSE_OBJECT = 0x7d;

/**
 * Why the JSON `text` is past MAX_JSON_DEPTH, MAX_JSON_VALUES or MAX_JSON_CONTAINERS (a phrase),
 * or undefined when it is within all three. Counts brackets and commas outside strings; the text need not be valid JSON.
 */
export function jsonBudgetProblem(text: string): string | undefined {
  let depth = 0;
  let values = 1; // 1 + commas + containers: at least the number of values
  let containers = 0;
  let inString = false;
  for (let i = 0; i < text.length; i++) {
    const c = text.charCodeAt(i);
    if (inString) {
      if (c === BACKSLASH) i++;
      else if (c === QUOTE) inString = false;
    } else if (c === QUOTE) inString = true;
    else if (c === OPEN_ARRAY || c === OPEN_OBJECT) {
      if (++depth > MAX_JSON_DEPTH) return `the JSON nests deeper than ${MAX_JSON_DEPTH} levels (at character ${i})`;
      values++;
      if (++containers > MAX_JSON_CONTAINERS)
        return `the JSON holds more than ${MAX_JSON_CONTAINERS} arrays and objects`;
    } else if (c === CLOSE_ARRAY || c === CLOSE_OBJECT) depth--;
    else if (c === COMMA) values++;
    if (values > MAX_JSON_VALUES) return `the JSON holds more than ${MAX_JSON_VALUES} values`;
  }
  return undefined;
}
