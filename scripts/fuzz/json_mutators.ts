// Generic mutations of a JSON document: a random place in the tree gets deleted, nulled, a value
// of the wrong type, an extreme number, many copies or a deep nesting. Each returns one line
// describing what it did.
import { deepMark, INFINITY_MARK, jsonText, NEG_INFINITY_MARK } from './json_text.js';
import type { Rand } from './random.js';

export type JsonContainer = Record<string, unknown> | unknown[];

/** A place in a document: `parent[key]`, and its path for descriptions. */
interface Place {
  parent: JsonContainer;
  key: string | number;
  path: string;
}

const isContainer = (v: unknown): v is JsonContainer => typeof v === 'object' && v !== null;

/** A random place under `root` (at least one level deep), or undefined for an empty root. */
function randomPlace(r: Rand, root: JsonContainer, rootPath = ''): Place | undefined {
  let parent = root,
    path = rootPath;
  for (;;) {
    const keys: (string | number)[] = Array.isArray(parent) ? [...parent.keys()] : Object.keys(parent);
    if (keys.length === 0) return undefined;
    const key = r.pick(keys);
    const child = (parent as Record<string | number, unknown>)[key];
    const childPath = typeof key === 'number' ? `${path}[${key}]` : path ? `${path}.${key}` : key;
    if (!isContainer(child) || r.chance(0.3)) return { parent, key, path: childPath };
    parent = child;
    path = childPath;
  }
}

/** Numbers that break careless code: signs, fractions, 32- and 53-bit edges, overflow, +-Infinity. */
const EXTREME_NUMBERS: readonly unknown[] = [
  0,
  -0,
  -1,
  1,
  0.5,
  -0.5,
  1e9,
  -1e9,
  1e10,
  2 ** 31 - 1,
  2 ** 31,
  2 ** 32,
  2 ** 32 + 1,
  2 ** 53 + 2,
  -(2 ** 53),
  1e308,
  -1e308,
  5e-324,
  1e-300,
  INFINITY_MARK,
  NEG_INFINITY_MARK,
];

const WRONG_TYPES: readonly unknown[] = [
  'x',
  '',
  '1',
  '-1',
  true,
  false,
  [],
  {},
  [[]],
  { 0: 1 },
  [null],
  ['1', '2', '3'],
];

function get(p: Place): unknown {
  return (p.parent as Record<string | number, unknown>)[p.key];
}

function set(p: Place, v: unknown): void {
  (p.parent as Record<string | number, unknown>)[p.key] = v;
}

function show(v: unknown): string {
  const text = JSON.stringify(v) ?? String(v);
  return text.length > 40 ? `${text.slice(0, 37)}...` : text;
}

/** Applies one generic mutation at place `p`; returns its description. */
function mutateAt(r: Rand, p: Place): string {
  const old = get(p);
  return r.weighted<() => string>([
    [
      2,
      () => {
        if (Array.isArray(p.parent)) p.parent.splice(p.key as number, 1);
        else delete p.parent[p.key as string];
        return `delete ${p.path}`;
      },
    ],
    [2, () => (set(p, null), `${p.path} = null`)],
    [
      3,
      () => {
        const v = r.pick(WRONG_TYPES);
        set(p, structuredClone(v));
        return `${p.path} = ${show(v)}`;
      },
    ],
    [
      4,
      () => {
        const v = r.pick(EXTREME_NUMBERS);
        set(p, v);
        return `${p.path} = ${show(v)}`;
      },
    ],
    [
      2,
      () => {
        if (typeof old !== 'number') return `${p.path} = ${show((set(p, -1), -1))}`;
        const v = r.pick([old * (1 + 1e-7), old + 1, -old, old * 1e6, old + 0.5]);
        set(p, v);
        return `${p.path} = ${v} (was ${old})`;
      },
    ],
    [
      1,
      () => {
        const size = old === undefined ? 0 : jsonText(old).length; // with nesting markers written out
        const copies = size < 1000 ? r.pick([2, 100, 10_000]) : 2;
        // Past 16 MB of text, copies (copied again by the next mutation) would outgrow what a
        // JavaScript string can hold before the loader ever sees them: the copy is left out.
        if (size * copies > 16_000_000)
          return `${p.path} = ${copies} copies of it in an array (left out: ${size} characters each)`;
        set(
          p,
          Array.from({ length: copies }, () => structuredClone(old)),
        );
        return `${p.path} = ${copies} copies of it in an array`;
      },
    ],
    [
      1,
      () => {
        const depth = r.pick([100, 10_000, 200_000]);
        set(p, deepMark(depth));
        return `${p.path} = arrays nested ${depth} deep`;
      },
    ],
  ])();
}

/** `count` generic mutations at random places under `root`; their descriptions. */
export function mutateJson(r: Rand, root: JsonContainer, count: number, rootPath = ''): string[] {
  const done: string[] = [];
  for (let k = 0; k < count; k++) {
    const p = randomPlace(r, root, rootPath);
    if (p) done.push(mutateAt(r, p));
  }
  return done;
}
